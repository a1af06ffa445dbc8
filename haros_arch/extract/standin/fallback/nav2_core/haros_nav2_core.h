// haros_arch stand-in: navigation2's plugin interfaces, nav2_core (declarations only;
// every nav2_core/... header stands in as this one, read only when the workspace has no
// nav2_core package, headers.FALLBACK_UMBRELLAS). Each interface's methods of Humble,
// Jazzy and Kilted are all here: those whose signature changed between releases
// (configure with the Kilted node, createPlan, computeVelocityCommands, ...) are virtual
// but not pure, so a plugin written for any one release overrides its own and is not
// abstract; the methods every release has alike are pure. The interfaces make no ROS
// call: a plugin's calls are its own, on the node its host gives it.
#ifndef HAROS_STANDIN_NAV2_CORE_H
#define HAROS_STANDIN_NAV2_CORE_H
#include <chrono>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <tf2_ros/buffer.h>
#include <nav2_ros_common/lifecycle_node.hpp>
#include <nav2_costmap_2d/costmap_2d_ros.hpp>
#include <nav2_util/simple_action_server.hpp>
#include <behaviortree_cpp/bt_factory.h>
#include <geometry_msgs/msg/pose.hpp>
#include <geometry_msgs/msg/pose_stamped.hpp>
#include <geometry_msgs/msg/twist.hpp>
#include <geometry_msgs/msg/twist_stamped.hpp>
#include <nav_msgs/msg/path.hpp>

namespace nav2_core {

using LegacyNode = rclcpp_lifecycle::LifecycleNode::WeakPtr;  // Humble, Jazzy
using KiltedNode = nav2::LifecycleNode::WeakPtr;

class GoalChecker {
public:
  typedef std::shared_ptr<nav2_core::GoalChecker> Ptr;
  virtual ~GoalChecker() {}
  virtual void initialize(const LegacyNode& parent, const std::string& plugin_name,
                          const std::shared_ptr<nav2_costmap_2d::Costmap2DROS> costmap_ros);
  virtual void initialize(const KiltedNode& parent, const std::string& plugin_name,
                          const std::shared_ptr<nav2_costmap_2d::Costmap2DROS> costmap_ros);
  virtual void reset() = 0;
  virtual bool isGoalReached(const geometry_msgs::msg::Pose& query_pose,
                             const geometry_msgs::msg::Pose& goal_pose,
                             const geometry_msgs::msg::Twist& velocity);
  virtual bool isGoalReached(const geometry_msgs::msg::Pose& query_pose,
                             const geometry_msgs::msg::Pose& goal_pose,
                             const geometry_msgs::msg::Twist& velocity,
                             const nav_msgs::msg::Path& transformed_global_plan);
  virtual bool isGoalXYReached(const geometry_msgs::msg::Pose& query_pose,
                               const geometry_msgs::msg::Pose& goal_pose,
                               const geometry_msgs::msg::Twist& velocity,
                               const nav_msgs::msg::Path& transformed_global_plan);
  virtual bool getTolerances(geometry_msgs::msg::Pose& pose_tolerance,
                             geometry_msgs::msg::Twist& vel_tolerance);
  virtual bool getTolerances(geometry_msgs::msg::Pose& pose_tolerance,
                             geometry_msgs::msg::Twist& vel_tolerance,
                             double& path_length_tolerance);
};

class ProgressChecker {
public:
  typedef std::shared_ptr<nav2_core::ProgressChecker> Ptr;
  virtual ~ProgressChecker() {}
  virtual void initialize(const LegacyNode& parent, const std::string& plugin_name);
  virtual void initialize(const KiltedNode& parent, const std::string& plugin_name);
  virtual bool check(geometry_msgs::msg::PoseStamped& current_pose) = 0;
  virtual void reset() = 0;
};

class Controller {
public:
  using Ptr = std::shared_ptr<nav2_core::Controller>;
  virtual ~Controller() {}
  virtual void configure(const LegacyNode& parent, std::string name,
                         std::shared_ptr<tf2_ros::Buffer> tf,
                         std::shared_ptr<nav2_costmap_2d::Costmap2DROS> costmap_ros);
  virtual void configure(const KiltedNode& parent, std::string name,
                         nav2::TransformBuffer::SharedPtr tf,
                         std::shared_ptr<nav2_costmap_2d::Costmap2DROS> costmap_ros);
  virtual void cleanup() = 0;
  virtual void activate() = 0;
  virtual void deactivate() = 0;
  virtual void setPlan(const nav_msgs::msg::Path& path);
  virtual void newPathReceived(const nav_msgs::msg::Path& raw_global_path);
  virtual geometry_msgs::msg::TwistStamped computeVelocityCommands(
    const geometry_msgs::msg::PoseStamped& pose, const geometry_msgs::msg::Twist& velocity,
    nav2_core::GoalChecker* goal_checker);
  virtual geometry_msgs::msg::TwistStamped computeVelocityCommands(
    const geometry_msgs::msg::PoseStamped& pose, const geometry_msgs::msg::Twist& velocity,
    nav2_core::GoalChecker* goal_checker, const nav_msgs::msg::Path& transformed_global_plan,
    const geometry_msgs::msg::PoseStamped& global_goal);
  virtual bool cancel();
  virtual void setSpeedLimit(const double& speed_limit, const bool& percentage) = 0;
  virtual void reset();
};

class GlobalPlanner {
public:
  using Ptr = std::shared_ptr<GlobalPlanner>;
  virtual ~GlobalPlanner() {}
  virtual void configure(const LegacyNode& parent, std::string name,
                         std::shared_ptr<tf2_ros::Buffer> tf,
                         std::shared_ptr<nav2_costmap_2d::Costmap2DROS> costmap_ros);
  virtual void configure(const KiltedNode& parent, std::string name,
                         nav2::TransformBuffer::SharedPtr tf,
                         std::shared_ptr<nav2_costmap_2d::Costmap2DROS> costmap_ros);
  virtual void cleanup() = 0;
  virtual void activate() = 0;
  virtual void deactivate() = 0;
  virtual nav_msgs::msg::Path createPlan(const geometry_msgs::msg::PoseStamped& start,
                                         const geometry_msgs::msg::PoseStamped& goal);
  virtual nav_msgs::msg::Path createPlan(const geometry_msgs::msg::PoseStamped& start,
                                         const geometry_msgs::msg::PoseStamped& goal,
                                         std::function<bool()> cancel_checker);
  virtual nav_msgs::msg::Path createPlan(
    const geometry_msgs::msg::PoseStamped& start, const geometry_msgs::msg::PoseStamped& goal,
    const std::vector<geometry_msgs::msg::PoseStamped>& viapoints,
    std::function<bool()> cancel_checker);
};

enum class CostmapInfoType { NONE = 0, LOCAL = 1, GLOBAL = 2, BOTH = 3 };

class Behavior {
public:
  using Ptr = std::shared_ptr<Behavior>;
  virtual ~Behavior() {}
  virtual void configure(
    const LegacyNode& parent, const std::string& name, std::shared_ptr<tf2_ros::Buffer> tf,
    std::shared_ptr<nav2_costmap_2d::CostmapTopicCollisionChecker> collision_checker);
  virtual void configure(
    const LegacyNode& parent, const std::string& name, std::shared_ptr<tf2_ros::Buffer> tf,
    std::shared_ptr<nav2_costmap_2d::CostmapTopicCollisionChecker> local_collision_checker,
    std::shared_ptr<nav2_costmap_2d::CostmapTopicCollisionChecker> global_collision_checker);
  virtual void configure(
    const KiltedNode& parent, const std::string& name, nav2::TransformBuffer::SharedPtr tf,
    std::shared_ptr<nav2_costmap_2d::CostmapTopicCollisionChecker> local_collision_checker,
    std::shared_ptr<nav2_costmap_2d::CostmapTopicCollisionChecker> global_collision_checker);
  virtual void cleanup() = 0;
  virtual void activate() = 0;
  virtual void deactivate() = 0;
  virtual CostmapInfoType getResourceInfo();
};

class Smoother {
public:
  using Ptr = std::shared_ptr<nav2_core::Smoother>;
  virtual ~Smoother() {}
  virtual void configure(const LegacyNode& parent, std::string name,
                         std::shared_ptr<tf2_ros::Buffer> tf,
                         std::shared_ptr<nav2_costmap_2d::CostmapSubscriber> costmap_sub,
                         std::shared_ptr<nav2_costmap_2d::FootprintSubscriber> footprint_sub);
  virtual void configure(const KiltedNode& parent, std::string name,
                         nav2::TransformBuffer::SharedPtr tf,
                         std::shared_ptr<nav2_costmap_2d::CostmapSubscriber> costmap_sub,
                         std::shared_ptr<nav2_costmap_2d::FootprintSubscriber> footprint_sub);
  virtual void cleanup() = 0;
  virtual void activate() = 0;
  virtual void deactivate() = 0;
  virtual bool smooth(nav_msgs::msg::Path& path, const rclcpp::Duration& max_time) = 0;
};

class WaypointTaskExecutor {
public:
  WaypointTaskExecutor() {}
  virtual ~WaypointTaskExecutor() {}
  virtual void initialize(const LegacyNode& parent, const std::string& plugin_name);
  virtual void initialize(const KiltedNode& parent, const std::string& plugin_name);
  virtual bool processAtWaypoint(const geometry_msgs::msg::PoseStamped& curr_pose,
                                 const int& curr_waypoint_index) = 0;
};

// bt_navigator's navigators (behavior_tree_navigator.hpp, Jazzy and Kilted): the base of a
// custom navigator, with the members and hooks a derived class uses. What its
// on_configure does on the node (the action server named by getName(), the behaviour
// tree server's parameters) is not read from here: a derived plugin class runs it as the
// interface model of nav2's NavigateToPoseNavigator shows it (plugins.hosts.RUNS_AS).
class NavigatorMuxer;
struct FeedbackUtils {
  std::string robot_frame;
  std::string global_frame;
  double transform_tolerance;
  std::shared_ptr<tf2_ros::Buffer> tf;
};
class NavigatorBase {
public:
  NavigatorBase();
  virtual ~NavigatorBase();
  virtual bool on_activate() = 0;
  virtual bool on_deactivate() = 0;
  virtual bool on_cleanup() = 0;
  virtual void preempt() = 0;
};
class NavigatorMuxer {
public:
  NavigatorMuxer();
  bool isNavigating();
  void startNavigating(NavigatorBase* navigator);
  void stopNavigating(NavigatorBase* navigator);
  void preemptCurrentNavigator();
  bool isCurrentNavigator(NavigatorBase* navigator);
};

}  // namespace nav2_core

namespace nav2_behavior_tree {
enum class BtStatus { SUCCEEDED, FAILED, CANCELED };
// the action server a navigator runs its tree with (bt_action_server.hpp): its methods
// make no ROS call of their own here (the server is the base's, RUNS_AS)
template<class ActionT, class NodeT = nav2::LifecycleNode>
class BtActionServer {
public:
  using ActionServer = nav2_util::SimpleActionServer<ActionT>;
  bool on_configure();
  bool on_activate();
  bool on_deactivate();
  bool on_cleanup();
  void setGrootMonitoring(const bool enable, const unsigned server_port);
  bool loadBehaviorTree(const std::string& bt_xml_filename = "");
  BT::Blackboard::Ptr getBlackboard() const;
  std::string getCurrentBTFilename() const;
  std::string getDefaultBTFilename() const;
  std::string getDefaultBTFilenameOrID() const;
  const std::shared_ptr<const typename ActionT::Goal> acceptPendingGoal();
  void terminatePendingGoal();
  const std::shared_ptr<const typename ActionT::Goal> getCurrentGoal() const;
  const std::shared_ptr<const typename ActionT::Goal> getPendingGoal() const;
  void publishFeedback(typename std::shared_ptr<typename ActionT::Feedback> feedback);
  const BT::Tree& getTree() const;
  void haltTree();
  bool isPreemptRequested() const;
  void preemptCurrentNavigator();
  void setInternalError(uint16_t error_code, const std::string& error_msg);
};
}  // namespace nav2_behavior_tree

// nav2_util's odometry smoother (odometry_utils.hpp) subscribes to the odometry topic it
// is given: a class that makes calls the API rows do not describe, declared so that code
// passing it parses; a node that builds one is partial (HAROS_UNREAD)
#ifndef HAROS_UNREAD
#define HAROS_UNREAD __attribute__((annotate("haros_unread")))
#endif
namespace nav2_util {
class HAROS_UNREAD OdomSmoother {
public:
  template<typename... Args> explicit OdomSmoother(Args&&... args);
  geometry_msgs::msg::Twist getTwist();
  geometry_msgs::msg::TwistStamped getTwistStamped();
  geometry_msgs::msg::Twist getRawTwist();
  geometry_msgs::msg::TwistStamped getRawTwistStamped();
};
}  // namespace nav2_util

namespace nav2_core {

template<class ActionT>
class BehaviorTreeNavigator : public NavigatorBase {
public:
  using Ptr = std::shared_ptr<nav2_core::BehaviorTreeNavigator<ActionT>>;
  BehaviorTreeNavigator();
  virtual ~BehaviorTreeNavigator();
  bool on_activate() final;
  bool on_deactivate() final;
  bool on_cleanup() final;
  void preempt() final;
  virtual std::string getDefaultBTFilepath(LegacyNode node);  // Jazzy
  virtual std::string getDefaultBTFilepath(KiltedNode node);
  virtual std::string getName() = 0;

protected:
  bool onGoalReceived(typename ActionT::Goal::ConstSharedPtr goal);
  void onCompletion(typename ActionT::Result::SharedPtr result,
                    nav2_behavior_tree::BtStatus& final_bt_status);
  virtual bool goalReceived(typename ActionT::Goal::ConstSharedPtr goal) = 0;
  virtual void onLoop() = 0;
  virtual void onPreempt(typename ActionT::Goal::ConstSharedPtr goal) = 0;
  virtual void goalCompleted(typename ActionT::Result::SharedPtr result,
                             nav2_behavior_tree::BtStatus& final_bt_status) = 0;
  virtual bool configure(LegacyNode node, std::shared_ptr<nav2_util::OdomSmoother> odom);
  virtual bool configure(KiltedNode node, std::shared_ptr<nav2_util::OdomSmoother> odom);
  virtual bool cleanup();
  virtual bool activate();
  virtual bool deactivate();
  std::unique_ptr<nav2_behavior_tree::BtActionServer<ActionT, nav2::LifecycleNode>>
      bt_action_server_;
  rclcpp::Logger logger_{rclcpp::get_logger("Navigator")};
  rclcpp::Clock::SharedPtr clock_;
  FeedbackUtils feedback_utils_;
  NavigatorMuxer* plugin_muxer_;
  bool allow_navigator_preemption_;
  std::chrono::milliseconds navigator_preemption_timeout_;
};

// the exceptions plugins throw (exceptions.hpp of Humble, *_exceptions.hpp since Jazzy)
#define HAROS_NAV2_EXCEPTION(Name, Base)                                                \
  class Name : public Base {                                                            \
  public:                                                                               \
    explicit Name(const std::string& description);                                      \
  };
HAROS_NAV2_EXCEPTION(PlannerException, std::runtime_error)
HAROS_NAV2_EXCEPTION(InvalidPlanner, PlannerException)
HAROS_NAV2_EXCEPTION(StartOccupied, PlannerException)
HAROS_NAV2_EXCEPTION(GoalOccupied, PlannerException)
HAROS_NAV2_EXCEPTION(StartOutsideMapBounds, PlannerException)
HAROS_NAV2_EXCEPTION(GoalOutsideMapBounds, PlannerException)
HAROS_NAV2_EXCEPTION(NoValidPathCouldBeFound, PlannerException)
HAROS_NAV2_EXCEPTION(PlannerTimedOut, PlannerException)
HAROS_NAV2_EXCEPTION(PlannerTFError, PlannerException)
HAROS_NAV2_EXCEPTION(NoViapointsGiven, PlannerException)
HAROS_NAV2_EXCEPTION(PlannerCancelled, PlannerException)
HAROS_NAV2_EXCEPTION(ControllerException, std::runtime_error)
HAROS_NAV2_EXCEPTION(InvalidController, ControllerException)
HAROS_NAV2_EXCEPTION(ControllerTFError, ControllerException)
HAROS_NAV2_EXCEPTION(FailedToMakeProgress, ControllerException)
HAROS_NAV2_EXCEPTION(PatienceExceeded, ControllerException)
HAROS_NAV2_EXCEPTION(InvalidPath, ControllerException)
HAROS_NAV2_EXCEPTION(NoValidControl, ControllerException)
HAROS_NAV2_EXCEPTION(ControllerTimedOut, ControllerException)
HAROS_NAV2_EXCEPTION(SmootherException, std::runtime_error)
HAROS_NAV2_EXCEPTION(InvalidSmoother, SmootherException)
HAROS_NAV2_EXCEPTION(SmootherTimedOut, SmootherException)
HAROS_NAV2_EXCEPTION(SmoothedPathInCollision, SmootherException)
HAROS_NAV2_EXCEPTION(FailedToSmoothPath, SmootherException)
#undef HAROS_NAV2_EXCEPTION

}  // namespace nav2_core
#endif
