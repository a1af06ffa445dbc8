// haros_arch stand-in: ros2_control's controller_manager::ControllerManager (declarations
// only; read only when the workspace has no controller_manager package, headers.FALLBACK).
// The manager is an rclcpp::Node named by its constructor's manager_node_name
// ("controller_manager" unless given) in node_namespace; a node of the workspace that
// makes one (KUKA's control_node, as ros2_control_node does) makes its calls on it.
// Its constructor serves the manager's services (api.LIBRARIES, the ROS 2 form of ROS 1's
// row); the rest of what it makes (the robot_description subscription, its parameters,
// Jazzy's activity and statistics topics) is not described: HAROS_UNREAD, the node is
// partial. Its three constructors (Humble has the first two, Jazzy all): one given the
// resource manager (a simulator plugin's: gazebo_ros2_control, gz_ros2_control), the one
// ros2_control_node calls, and Jazzy's given the URDF; each names the node by its
// parameter manager_node_name (api.STANDIN_NODE_NAME reads the parameters' names).
#ifndef HAROS_STANDIN_CONTROLLER_MANAGER_HPP
#define HAROS_STANDIN_CONTROLLER_MANAGER_HPP
// ROS 1's class of the same name (controller_manager.h) wins in a unit that has both
#ifndef HAROS_STANDIN_CONTROLLER_MANAGER_H
#include <chrono>
#include <memory>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <hardware_interface/resource_manager.hpp>

#ifndef HAROS_UNREAD
#define HAROS_UNREAD __attribute__((annotate("haros_unread")))
#endif
namespace controller_manager {
class HAROS_UNREAD ControllerManager : public rclcpp::Node {
 public:
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_ROS1_H  // (ROS 1's ResourceManager: a template)
  ControllerManager(std::unique_ptr<hardware_interface::ResourceManager> resource_manager,
                    std::shared_ptr<rclcpp::Executor> executor,
                    const std::string& manager_node_name = "controller_manager",
                    const std::string& node_namespace = "",
                    const rclcpp::NodeOptions& options = rclcpp::NodeOptions())
      : rclcpp::Node(manager_node_name, node_namespace, options) {}
#endif
  ControllerManager(std::shared_ptr<rclcpp::Executor> executor,
                    const std::string& manager_node_name = "controller_manager",
                    const std::string& node_namespace = "",
                    const rclcpp::NodeOptions& options = rclcpp::NodeOptions())
      : rclcpp::Node(manager_node_name, node_namespace, options) {}
  ControllerManager(std::shared_ptr<rclcpp::Executor> executor, const std::string& urdf,
                    bool activate_all_hw_components,
                    const std::string& manager_node_name = "controller_manager",
                    const std::string& node_namespace = "",
                    const rclcpp::NodeOptions& options = rclcpp::NodeOptions())
      : rclcpp::Node(manager_node_name, node_namespace, options) {}
  virtual ~ControllerManager();
  void init_resource_manager(const std::string& robot_description);
  int get_update_rate() const;
  rclcpp::Time now() const;
  void read(const rclcpp::Time& time, const rclcpp::Duration& period);
  void update(const rclcpp::Time& time, const rclcpp::Duration& period);
  void write(const rclcpp::Time& time, const rclcpp::Duration& period);
  bool is_resource_manager_initialized() const;
  bool use_multiple_callback_groups();
  rclcpp::Clock::SharedPtr get_trigger_clock() const;
  void shutdown_async_controllers_and_components();
};
}  // namespace controller_manager
#endif
#endif
