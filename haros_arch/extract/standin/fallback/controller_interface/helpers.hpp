// haros_arch stand-in: ros2_control's controller helpers (declarations only)
#ifndef HAROS_STANDIN_CONTROLLER_INTERFACE_HELPERS_HPP
#define HAROS_STANDIN_CONTROLLER_INTERFACE_HELPERS_HPP
#include <functional>
#include <string>
#include <vector>
namespace controller_interface {
template <typename T>
bool get_ordered_interfaces(std::vector<T>& unordered_interfaces,
                            const std::vector<std::string>& ordered_names,
                            const std::string& interface_type,
                            std::vector<std::reference_wrapper<T>>& ordered_interfaces);
bool interface_list_contains_interface_type(const std::vector<std::string>& interface_type_list,
                                            const std::string& interface_type);
template <typename T> void add_element_to_list(std::vector<T>& list, const T& element);
}  // namespace controller_interface
#endif
