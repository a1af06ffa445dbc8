// haros_arch stand-in: actionlib servers and clients (declarations only)
#ifndef HAROS_STANDIN_ACTIONLIB_H
#define HAROS_STANDIN_ACTIONLIB_H
#include <ros/ros.h>
#include <boost/shared_ptr.hpp>
#include <boost/function.hpp>
namespace actionlib {
class SimpleClientGoalState {
public:
  enum StateEnum { PENDING, ACTIVE, RECALLED, REJECTED, PREEMPTED, ABORTED, SUCCEEDED, LOST };
  SimpleClientGoalState(StateEnum state);
  StateEnum state_;
  std::string toString() const;
  std::string getText() const;
  bool isDone() const;
  bool operator==(const StateEnum& other) const;
  bool operator!=(const StateEnum& other) const;
};
namespace terminal_state { enum StateEnum { RECALLED, REJECTED, PREEMPTED, ABORTED, SUCCEEDED, LOST }; }
template<class A> class SimpleActionServer {
public:
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
  template<class... X> ActionServer(ros::NodeHandle n, std::string name, X&&... more);
  void start();
};
template<class A> class SimpleActionClient {
public:
  typedef typename A::Goal Goal;
  typedef typename A::Result Result;
  typedef typename A::Feedback Feedback;
  typedef boost::shared_ptr<const Result> ResultConstPtr;
  typedef boost::shared_ptr<const Feedback> FeedbackConstPtr;
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
  void stopTrackingGoal();
};
template<class A> class ActionClient {
public:
  ActionClient(const std::string& name, void* queue = nullptr);
  ActionClient(const ros::NodeHandle& n, const std::string& name, void* queue = nullptr);
  bool waitForActionServerToStart(const ros::Duration& timeout = ros::Duration(0, 0));
};
}
#endif
