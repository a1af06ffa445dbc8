// haros_arch stand-in: ros2_control's ControllerInterface, a controller that is not
// chainable (declarations only; headers.FALLBACK)
#ifndef HAROS_STANDIN_CONTROLLER_INTERFACE_HPP
#define HAROS_STANDIN_CONTROLLER_INTERFACE_HPP
#include <controller_interface/controller_interface_base.hpp>
namespace controller_interface {
class ControllerInterface : public ControllerInterfaceBase {
public:
  ControllerInterface();
  virtual ~ControllerInterface();
  bool is_chainable() const final;
  std::vector<hardware_interface::StateInterface::ConstSharedPtr>
  export_state_interfaces() final;
  std::vector<hardware_interface::CommandInterface::SharedPtr>
  export_reference_interfaces() final;
  bool set_chained_mode(bool chained_mode) final;
  bool is_in_chained_mode() const final;
};
using ControllerInterfaceSharedPtr = std::shared_ptr<ControllerInterface>;
}  // namespace controller_interface
#endif
