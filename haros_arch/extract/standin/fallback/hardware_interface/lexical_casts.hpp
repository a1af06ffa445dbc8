// haros_arch stand-in: ros2_control's string conversions for hardware parameters
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_LEXICAL_CASTS_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_LEXICAL_CASTS_HPP
#include <string>
#include <vector>
namespace hardware_interface {
double stod(const std::string& s);
bool parse_bool(const std::string& bool_string);
std::vector<std::string> parse_string_array(const std::string& string_array_string);
}  // namespace hardware_interface
#endif
