// haros_arch stand-in: actionlib servers and clients (declarations only)
#ifndef HAROS_STANDIN_ACTIONLIB_H
#define HAROS_STANDIN_ACTIONLIB_H
#include <ros/ros.h>
#include <boost/shared_ptr.hpp>
#include <boost/function.hpp>
// the goal handle's messages, declared: this header is precompiled with the stand-ins,
// where no message header is; action_server.h includes them, as actionlib's does
namespace actionlib_msgs { struct GoalID; struct GoalStatus; }
namespace actionlib {
class SimpleClientGoalState {
public:
  enum StateEnum { PENDING, ACTIVE, RECALLED, REJECTED, PREEMPTED, ABORTED, SUCCEEDED, LOST };
  SimpleClientGoalState(StateEnum state, const std::string& text = std::string(""));
  StateEnum state_;
  std::string toString() const;
  std::string getText() const;
  bool isDone() const;
  bool operator==(const StateEnum& other) const;
  bool operator!=(const StateEnum& other) const;
};
namespace terminal_state { enum StateEnum { RECALLED, REJECTED, PREEMPTED, ABORTED, SUCCEEDED, LOST }; }
// the types actionlib's ACTION_DEFINITION names for an action A (as the generated
// NameAction declares its parts: Goal, Result, Feedback, _action_*_type)
#define HAROS_ACTIONLIB_TYPES(A) \
  typedef typename A::_action_goal_type ActionGoal; \
  typedef typename A::_action_result_type ActionResult; \
  typedef typename A::_action_feedback_type ActionFeedback; \
  typedef typename A::Goal Goal; \
  typedef typename A::Result Result; \
  typedef typename A::Feedback Feedback; \
  typedef boost::shared_ptr<const ActionGoal> ActionGoalConstPtr; \
  typedef boost::shared_ptr<ActionGoal> ActionGoalPtr; \
  typedef boost::shared_ptr<const ActionResult> ActionResultConstPtr; \
  typedef boost::shared_ptr<const ActionFeedback> ActionFeedbackConstPtr; \
  typedef boost::shared_ptr<const Goal> GoalConstPtr; \
  typedef boost::shared_ptr<Goal> GoalPtr; \
  typedef boost::shared_ptr<const Result> ResultConstPtr; \
  typedef boost::shared_ptr<Result> ResultPtr; \
  typedef boost::shared_ptr<const Feedback> FeedbackConstPtr; \
  typedef boost::shared_ptr<Feedback> FeedbackPtr;
// actionlib/action_definition.h (which the servers' headers include): the same types in a
// class templated on its action (bwi_common's InterruptableActionServer<ActionSpec>)
#define ACTION_DEFINITION(A) HAROS_ACTIONLIB_TYPES(A)
// the goal handle an ActionServer gives its callbacks (no ROS call of its own: what it
// sends goes out on the server's topics)
template<class A> class ServerGoalHandle {
public:
  HAROS_ACTIONLIB_TYPES(A)
  ServerGoalHandle();
  void setAccepted(const std::string& text = std::string(""));
  void setCanceled(const Result& result = Result(), const std::string& text = std::string(""));
  void setRejected(const Result& result = Result(), const std::string& text = std::string(""));
  void setAborted(const Result& result = Result(), const std::string& text = std::string(""));
  void setSucceeded(const Result& result = Result(), const std::string& text = std::string(""));
  bool setCancelRequested();
  void publishFeedback(const Feedback& feedback);
  GoalConstPtr getGoal() const;
  actionlib_msgs::GoalID getGoalID() const;
  actionlib_msgs::GoalStatus getGoalStatus() const;
  bool operator==(const ServerGoalHandle& other) const;
  bool operator!=(const ServerGoalHandle& other) const;
};
// the goal handle an ActionClient's sendGoal returns
class CommState {
public:
  enum StateEnum { WAITING_FOR_GOAL_ACK, PENDING, ACTIVE, WAITING_FOR_RESULT,
                   WAITING_FOR_CANCEL_ACK, RECALLING, PREEMPTING, DONE };
  CommState(const StateEnum& state);
  StateEnum state_;
  std::string toString() const;
  bool operator==(const StateEnum& other) const;
  bool operator!=(const StateEnum& other) const;
};
class TerminalState {
public:
  enum StateEnum { RECALLED, REJECTED, PREEMPTED, ABORTED, SUCCEEDED, LOST };
  TerminalState(const StateEnum& state, const std::string& text = std::string(""));
  StateEnum state_;
  std::string getText() const;
  std::string toString() const;
  bool operator==(const StateEnum& other) const;
  bool operator!=(const StateEnum& other) const;
};
template<class A> class ClientGoalHandle {
public:
  HAROS_ACTIONLIB_TYPES(A)
  ClientGoalHandle();
  void reset();
  bool isExpired() const;
  CommState getCommState() const;
  TerminalState getTerminalState() const;
  ResultConstPtr getResult() const;
  void resend();
  void cancel();
  bool operator==(const ClientGoalHandle& other) const;
  bool operator!=(const ClientGoalHandle& other) const;
};
template<class A> class SimpleActionServer {
public:
  typedef ServerGoalHandle<A> GoalHandle;
  typedef typename A::Goal Goal;
  typedef typename A::Result Result;
  typedef typename A::Feedback Feedback;
  typedef boost::shared_ptr<const Goal> GoalConstPtr;
  typedef boost::function<void(const GoalConstPtr&)> ExecuteCallback;
  SimpleActionServer(std::string name, bool auto_start);
  SimpleActionServer(std::string name, ExecuteCallback execute_callback, bool auto_start);
  SimpleActionServer(ros::NodeHandle n, std::string name, bool auto_start);
  SimpleActionServer(ros::NodeHandle n, std::string name, ExecuteCallback execute_callback,
                     bool auto_start);
  GoalConstPtr acceptNewGoal();
  bool isNewGoalAvailable();
  bool isPreemptRequested();
  bool isActive();
  void setSucceeded(const Result& result = Result(), const std::string& text = std::string(""));
  void setAborted(const Result& result = Result(), const std::string& text = std::string(""));
  void setPreempted(const Result& result = Result(), const std::string& text = std::string(""));
  void publishFeedback(const Feedback& feedback);
  template<class C> void registerGoalCallback(C callback);
  template<class C> void registerPreemptCallback(C callback);
  void start();
  void shutdown();
};
template<class A> class ActionServer {
public:
  HAROS_ACTIONLIB_TYPES(A)
  typedef ServerGoalHandle<A> GoalHandle;
  template<class... X> ActionServer(ros::NodeHandle n, std::string name, X&&... more);
  void registerGoalCallback(boost::function<void(GoalHandle)> cb);
  void registerCancelCallback(boost::function<void(GoalHandle)> cb);
  void start();
};
template<class A> class SimpleActionClient {
public:
  typedef typename A::Goal Goal;
  typedef typename A::Result Result;
  typedef typename A::Feedback Feedback;
  typedef boost::shared_ptr<const Result> ResultConstPtr;
  typedef boost::shared_ptr<const Feedback> FeedbackConstPtr;
  typedef boost::function<void(const SimpleClientGoalState&, const ResultConstPtr&)>
      SimpleDoneCallback;
  typedef boost::function<void()> SimpleActiveCallback;
  typedef boost::function<void(const FeedbackConstPtr&)> SimpleFeedbackCallback;
  SimpleActionClient(const std::string& name, bool spin_thread = true);
  SimpleActionClient(ros::NodeHandle& n, const std::string& name, bool spin_thread = true);
  bool waitForServer(const ros::Duration& timeout = ros::Duration(0, 0)) const;
  bool isServerConnected() const;
  template<class... C> void sendGoal(const Goal& goal, C... callbacks);
  SimpleClientGoalState sendGoalAndWait(const Goal& goal,
      const ros::Duration& execute_timeout = ros::Duration(0, 0),
      const ros::Duration& preempt_timeout = ros::Duration(0, 0));
  bool waitForResult(const ros::Duration& timeout = ros::Duration(0, 0));
  ResultConstPtr getResult() const;
  SimpleClientGoalState getState() const;
  void cancelGoal();
  void cancelAllGoals();
  void cancelGoalsAtAndBeforeTime(const ros::Time& time);
  void stopTrackingGoal();
};
template<class A> class ActionClient {
public:
  HAROS_ACTIONLIB_TYPES(A)
  typedef ClientGoalHandle<A> GoalHandle;
  GoalHandle sendGoal(const Goal& goal,
                      boost::function<void(GoalHandle)> transition_cb = nullptr,
                      boost::function<void(GoalHandle, const FeedbackConstPtr&)> feedback_cb =
                          nullptr);
  void cancelAllGoals();
  void cancelGoalsAtAndBeforeTime(const ros::Time& time);
  bool isServerConnected() const;
  ActionClient(const std::string& name, void* queue = nullptr);
  ActionClient(const ros::NodeHandle& n, const std::string& name, void* queue = nullptr);
  bool waitForActionServerToStart(const ros::Duration& timeout = ros::Duration(0, 0));
};
}
#endif
