// haros_arch stand-in: the base of ros2_control's hardware components (declarations only).
// Humble's components override on_init(const HardwareInfo &) and export_state_interfaces();
// Jazzy's may take HardwareComponentInterfaceParams and export shared pointers, and have a
// node of their own (get_node()).
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_COMPONENT_INTERFACE_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_COMPONENT_INTERFACE_HPP
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <hardware_interface/handle.hpp>
#include <hardware_interface/hardware_info.hpp>
#include <hardware_interface/types/hardware_component_interface_params.hpp>
#include <hardware_interface/types/hardware_component_params.hpp>
#include <hardware_interface/types/hardware_interface_return_values.hpp>
#include <hardware_interface/types/lifecycle_state_names.hpp>
namespace hardware_interface {
using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;
class HardwareComponentInterface : public rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface {
public:
  HardwareComponentInterface();
  virtual ~HardwareComponentInterface();
  CallbackReturn init(const HardwareInfo& hardware_info, rclcpp::Logger logger,
                      rclcpp::Clock::SharedPtr clock);
  CallbackReturn init(const HardwareComponentParams& params);
  virtual CallbackReturn on_init(const HardwareInfo& hardware_info);
  virtual CallbackReturn on_init(const HardwareComponentInterfaceParams& params);
  virtual rclcpp::NodeOptions define_custom_node_options() const;
  virtual std::vector<StateInterface> export_state_interfaces();
  virtual std::vector<InterfaceDescription> export_unlisted_state_interface_descriptions();
  virtual std::vector<StateInterface::ConstSharedPtr> on_export_state_interfaces();
  virtual std::vector<CommandInterface> export_command_interfaces();
  virtual std::vector<InterfaceDescription> export_unlisted_command_interface_descriptions();
  virtual std::vector<CommandInterface::SharedPtr> on_export_command_interfaces();
  virtual return_type prepare_command_mode_switch(const std::vector<std::string>& start_interfaces,
                                                  const std::vector<std::string>& stop_interfaces);
  virtual return_type perform_command_mode_switch(const std::vector<std::string>& start_interfaces,
                                                  const std::vector<std::string>& stop_interfaces);
  HardwareComponentCycleStatus trigger_read(const rclcpp::Time& time,
                                            const rclcpp::Duration& period);
  virtual return_type read(const rclcpp::Time& time, const rclcpp::Duration& period) = 0;
  HardwareComponentCycleStatus trigger_write(const rclcpp::Time& time,
                                             const rclcpp::Duration& period);
  virtual return_type write(const rclcpp::Time& time, const rclcpp::Duration& period);
  virtual std::string get_name() const;
  const std::string& get_group_name() const;
  const rclcpp_lifecycle::State& get_lifecycle_state() const;
  void set_lifecycle_state(const rclcpp_lifecycle::State& new_state);
  const rclcpp_lifecycle::State& get_state() const;
  void set_state(const rclcpp_lifecycle::State& new_state);
  virtual bool has_state(const std::string& interface_name) const;
  virtual const StateInterface::SharedPtr& get_state_interface_handle(
      const std::string& interface_name) const;
  template <typename T> bool set_state(const StateInterface::SharedPtr& interface_handle,
                                       const T& value, bool wait_until_set);
  template <typename T> void set_state(const std::string& interface_name, const T& value);
  template <typename T> bool get_state(const StateInterface::SharedPtr& interface_handle,
                                       T& state, bool wait_until_get) const;
  template <typename T = double> T get_state(const std::string& interface_name) const;
  virtual bool has_command(const std::string& interface_name) const;
  virtual const CommandInterface::SharedPtr& get_command_interface_handle(
      const std::string& interface_name) const;
  template <typename T> bool set_command(const CommandInterface::SharedPtr& interface_handle,
                                         const T& value, bool wait_until_set);
  template <typename T> void set_command(const std::string& interface_name, const T& value);
  template <typename T> bool get_command(const CommandInterface::SharedPtr& interface_handle,
                                         T& command, bool wait_until_get) const;
  template <typename T = double> T get_command(const std::string& interface_name) const;
  virtual rclcpp::Logger get_logger() const;
  virtual rclcpp::Clock::SharedPtr get_clock() const;
  virtual rclcpp::Node::SharedPtr get_node() const;
  const HardwareInfo& get_hardware_info() const;
  void pause_async_operations();
  void prepare_for_activation();
  void enable_introspection(bool enable);
protected:
  HardwareInfo info_;
  rclcpp_lifecycle::State lifecycle_state_;
  std::unordered_map<std::string, InterfaceDescription> joint_state_interfaces_;
  std::unordered_map<std::string, InterfaceDescription> joint_command_interfaces_;
  std::unordered_map<std::string, InterfaceDescription> sensor_state_interfaces_;
  std::unordered_map<std::string, InterfaceDescription> gpio_state_interfaces_;
  std::unordered_map<std::string, InterfaceDescription> gpio_command_interfaces_;
  std::unordered_map<std::string, InterfaceDescription> unlisted_state_interfaces_;
  std::unordered_map<std::string, InterfaceDescription> unlisted_command_interfaces_;
  std::vector<StateInterface::SharedPtr> joint_states_;
  std::vector<CommandInterface::SharedPtr> joint_commands_;
  std::vector<StateInterface::SharedPtr> sensor_states_;
  std::vector<StateInterface::SharedPtr> gpio_states_;
  std::vector<CommandInterface::SharedPtr> gpio_commands_;
  std::vector<StateInterface::SharedPtr> unlisted_states_;
  std::vector<CommandInterface::SharedPtr> unlisted_commands_;
};
}  // namespace hardware_interface
#endif
