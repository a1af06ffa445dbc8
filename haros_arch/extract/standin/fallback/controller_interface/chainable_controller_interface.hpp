// haros_arch stand-in: ros2_control's ChainableControllerInterface (declarations only;
// headers.FALLBACK). Humble's hooks (vectors of interfaces, update_reference_from_subscribers
// without arguments) are here beside Jazzy's.
#ifndef HAROS_STANDIN_CHAINABLE_CONTROLLER_INTERFACE_HPP
#define HAROS_STANDIN_CHAINABLE_CONTROLLER_INTERFACE_HPP
#include <controller_interface/controller_interface_base.hpp>
namespace controller_interface {
class ChainableControllerInterface : public ControllerInterfaceBase {
public:
  ChainableControllerInterface();
  virtual ~ChainableControllerInterface();
  return_type update(const rclcpp::Time& time, const rclcpp::Duration& period) final;
  bool is_chainable() const final;
  std::vector<hardware_interface::StateInterface::ConstSharedPtr>
  export_state_interfaces() final;
  std::vector<hardware_interface::CommandInterface::SharedPtr>
  export_reference_interfaces() final;
  bool set_chained_mode(bool chained_mode) final;
  bool is_in_chained_mode() const final;
protected:
  virtual std::vector<hardware_interface::StateInterface> on_export_state_interfaces();
  virtual std::vector<hardware_interface::StateInterface::SharedPtr>
  on_export_state_interfaces_list();
  virtual std::vector<hardware_interface::CommandInterface> on_export_reference_interfaces();
  virtual std::vector<hardware_interface::CommandInterface::SharedPtr>
  on_export_reference_interfaces_list();
  virtual bool on_set_chained_mode(bool chained_mode);
  virtual return_type update_reference_from_subscribers();
  virtual return_type update_reference_from_subscribers(const rclcpp::Time& time,
                                                        const rclcpp::Duration& period);
  virtual return_type update_and_write_commands(const rclcpp::Time& time,
                                                const rclcpp::Duration& period);
  std::vector<std::string> exported_state_interface_names_;
  std::vector<hardware_interface::StateInterface::SharedPtr> ordered_exported_state_interfaces_;
  std::unordered_map<std::string, hardware_interface::StateInterface::SharedPtr>
      exported_state_interfaces_;
  std::vector<double> state_interfaces_values_;
  std::vector<std::string> exported_reference_interface_names_;
  std::vector<double> reference_interfaces_;
  std::vector<hardware_interface::CommandInterface::SharedPtr>
      ordered_exported_reference_interfaces_;
  std::unordered_map<std::string, hardware_interface::CommandInterface::SharedPtr>
      exported_reference_interfaces_;
};
}  // namespace controller_interface
#endif
