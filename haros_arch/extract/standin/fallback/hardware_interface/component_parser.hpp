// haros_arch stand-in: ros2_control's URDF parser of <ros2_control> tags (declarations
// only; read only when the workspace has no hardware_interface package, headers.FALLBACK)
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_COMPONENT_PARSER_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_COMPONENT_PARSER_HPP
#include <string>
#include <vector>
#include <hardware_interface/hardware_info.hpp>
namespace hardware_interface {
std::vector<HardwareInfo> parse_control_resources_from_urdf(const std::string& urdf);
}  // namespace hardware_interface
#endif
