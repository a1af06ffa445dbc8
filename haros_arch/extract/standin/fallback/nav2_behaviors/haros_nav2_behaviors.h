// haros_arch stand-in: navigation2's nav2_behaviors as behaviours outside navigation2 use
// it (declarations only; every nav2_behaviors/... header stands in as this one, read only
// when the workspace has no nav2_behaviors package, headers.FALLBACK_UMBRELLAS): the
// TimedBehavior<ActionT> base of a custom behaviour, with the members and hooks a derived
// class uses, for Humble, Jazzy and Kilted side by side where their spellings differ.
// What the base's own configure() does on the node (the action server named after the
// plugin, the velocity publisher, the behavior server's parameters it reads) is not read
// from here: a derived plugin class runs it as the interface model of nav2_behaviors'
// Wait shows it (plugins.hosts.RUNS_AS).
#ifndef HAROS_STANDIN_NAV2_BEHAVIORS_H
#define HAROS_STANDIN_NAV2_BEHAVIORS_H
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <tf2_ros/buffer.h>
#include <geometry_msgs/msg/twist.hpp>
#include <geometry_msgs/msg/twist_stamped.hpp>
#include <nav2_core/behavior.hpp>
#include <nav2_util/simple_action_server.hpp>
#include <nav2_ros_common/lifecycle_node.hpp>
#include <nav2_costmap_2d/costmap_topic_collision_checker.hpp>

namespace nav2_behaviors {

enum class Status : int8_t { SUCCEEDED = 1, FAILED = 2, RUNNING = 3 };

// Jazzy's (status, error_code) and Kilted's error_msg
struct ResultStatus {
  Status status;
  uint16_t error_code{0};
  std::string error_msg{};
};

// the velocity publisher the base makes (nav2_util::TwistPublisher): what a derived class
// does with it publishes on the base's cmd_vel publisher
class haros_twist_publisher {
public:
  void publish(std::unique_ptr<geometry_msgs::msg::TwistStamped> velocity);
  void publish(std::unique_ptr<geometry_msgs::msg::Twist> velocity);
  void publish(const geometry_msgs::msg::TwistStamped& velocity);
  void publish(const geometry_msgs::msg::Twist& velocity);
  void on_activate();
  void on_deactivate();
  bool is_activated() const;
  uint32_t get_subscription_count() const;
};

template<typename ActionT>
class TimedBehavior : public nav2_core::Behavior {
public:
  using ActionServer = nav2_util::SimpleActionServer<ActionT>;
  TimedBehavior();
  virtual ~TimedBehavior();
  virtual ResultStatus onRun(const std::shared_ptr<const typename ActionT::Goal> command) = 0;
  virtual ResultStatus onCycleUpdate() = 0;
  virtual void onConfigure();
  virtual void onCleanup();
  virtual void onActionCompletion();  // Humble
  virtual void onActionCompletion(std::shared_ptr<typename ActionT::Result> result);
  void cleanup() override;
  void activate() override;
  void deactivate() override;

protected:
  nav2::LifecycleNode::WeakPtr node_;
  std::string behavior_name_;
  std::unique_ptr<haros_twist_publisher> vel_pub_;
  std::shared_ptr<ActionServer> action_server_;
  std::shared_ptr<nav2_costmap_2d::CostmapTopicCollisionChecker> collision_checker_;  // Humble
  std::shared_ptr<nav2_costmap_2d::CostmapTopicCollisionChecker> local_collision_checker_;
  std::shared_ptr<nav2_costmap_2d::CostmapTopicCollisionChecker> global_collision_checker_;
  std::shared_ptr<tf2_ros::Buffer> tf_;
  double cycle_frequency_;
  double enabled_;
  std::string local_frame_;
  std::string global_frame_;
  std::string robot_base_frame_;
  double transform_tolerance_;
  rclcpp::Duration elapsed_time_{0, 0};
  rclcpp::Duration action_server_result_timeout_{0, 0};
  rclcpp::Clock::SharedPtr clock_;
  rclcpp::Logger logger_{rclcpp::get_logger("nav2_behaviors")};
  void execute();
  void stopRobot();
};

}  // namespace nav2_behaviors
#endif
