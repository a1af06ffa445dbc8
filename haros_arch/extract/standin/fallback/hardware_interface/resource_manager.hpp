// haros_arch stand-in: ros2_control's ResourceManager, the hardware components a
// controller manager drives (declarations only; read only when the workspace has no
// hardware_interface package, headers.FALLBACK). Humble's and Jazzy's constructors side
// by side; no ROS call of its own (the manager's node makes them).
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_RESOURCE_MANAGER_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_RESOURCE_MANAGER_HPP
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <hardware_interface/actuator_interface.hpp>
#include <hardware_interface/hardware_info.hpp>
#include <hardware_interface/sensor_interface.hpp>
#include <hardware_interface/system_interface.hpp>
#include <hardware_interface/types/hardware_interface_return_values.hpp>
// ROS 1's class template of the same name (haros_ros1.h) wins in a unit that has both
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_ROS1_H
namespace hardware_interface {
struct HardwareComponentInfo {
  std::string name;
  std::string type;
  std::string plugin_name;
  rclcpp_lifecycle::State state;
  std::vector<std::string> state_interfaces;
  std::vector<std::string> command_interfaces;
};
class ResourceManager {
 public:
  ResourceManager();
  explicit ResourceManager(const std::string& urdf, bool validate_interfaces = true,
                           bool activate_all = false);
  explicit ResourceManager(
      rclcpp::node_interfaces::NodeClockInterface::SharedPtr clock_interface,
      rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr logger_interface);
  explicit ResourceManager(rclcpp::Clock::SharedPtr clock, rclcpp::Logger logger);
  explicit ResourceManager(
      const std::string& urdf,
      rclcpp::node_interfaces::NodeClockInterface::SharedPtr clock_interface,
      rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr logger_interface,
      bool activate_all = false, const unsigned int update_rate = 100);
  explicit ResourceManager(const std::string& urdf, rclcpp::Clock::SharedPtr clock,
                           rclcpp::Logger logger, bool activate_all = false,
                           const unsigned int update_rate = 100);
  ResourceManager(const ResourceManager&) = delete;
  virtual ~ResourceManager();
  bool shutdown_components();
  void load_urdf(const std::string& urdf, bool validate_interfaces = true,
                 bool load_and_initialize_components = true);
  virtual bool load_and_initialize_components(const std::string& urdf,
                                              const unsigned int update_rate = 100);
  bool is_urdf_already_loaded() const;
  // one overload per component kind (actuator, sensor, system) in ros2_control: one
  // template here, as the std stand-in's unique_ptr converts from any other, so a
  // component class derived from one kind would find the three ambiguous
  template<class Component>
  void import_component(std::unique_ptr<Component> component, const HardwareInfo& hardware_info);
  std::unordered_map<std::string, HardwareComponentInfo> get_components_status();
  return_type set_component_state(const std::string& component_name,
                                  rclcpp_lifecycle::State& target_state);
  bool state_interface_exists(const std::string& key) const;
  bool command_interface_exists(const std::string& key) const;
  std::vector<std::string> state_interface_keys() const;
  std::vector<std::string> command_interface_keys() const;
};
}  // namespace hardware_interface
#endif
#endif
