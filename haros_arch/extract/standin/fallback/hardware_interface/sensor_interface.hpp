// haros_arch stand-in: ros2_control's SensorInterface, a hardware component (declarations
// only; read only when the workspace has no hardware_interface package, headers.FALLBACK)
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_SENSOR_INTERFACE_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_SENSOR_INTERFACE_HPP
#include <hardware_interface/hardware_component_interface.hpp>
namespace hardware_interface {
class SensorInterface : public HardwareComponentInterface {
public:
  SensorInterface();
  virtual ~SensorInterface();
};
}  // namespace hardware_interface
#endif
