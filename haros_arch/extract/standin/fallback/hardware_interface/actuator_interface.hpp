// haros_arch stand-in: ros2_control's ActuatorInterface, a hardware component (declarations
// only; read only when the workspace has no hardware_interface package, headers.FALLBACK)
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_ACTUATOR_INTERFACE_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_ACTUATOR_INTERFACE_HPP
#include <hardware_interface/hardware_component_interface.hpp>
namespace hardware_interface {
class ActuatorInterface : public HardwareComponentInterface {
public:
  ActuatorInterface();
  virtual ~ActuatorInterface();
};
}  // namespace hardware_interface
#endif
