// haros_arch stand-in: what a hardware component's on_init is given (Jazzy and later)
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_COMPONENT_INTERFACE_PARAMS_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_COMPONENT_INTERFACE_PARAMS_HPP
#include <rclcpp/rclcpp.hpp>
#include <hardware_interface/hardware_info.hpp>
namespace hardware_interface {
struct HardwareComponentInterfaceParams {
  HardwareInfo hardware_info;
  rclcpp::Executor::WeakPtr executor;
};
}  // namespace hardware_interface
#endif
