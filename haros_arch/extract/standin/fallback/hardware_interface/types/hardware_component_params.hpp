// haros_arch stand-in: what the resource manager initialises a hardware component with
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_COMPONENT_PARAMS_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_COMPONENT_PARAMS_HPP
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <hardware_interface/hardware_info.hpp>
namespace hardware_interface {
struct HardwareComponentParams {
  HardwareInfo hardware_info;
  rclcpp::Logger logger;
  rclcpp::Clock::SharedPtr clock;
  std::string node_namespace;
  rclcpp::Executor::WeakPtr executor;
};
}  // namespace hardware_interface
#endif
