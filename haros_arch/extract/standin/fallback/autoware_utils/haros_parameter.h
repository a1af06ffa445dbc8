// haros_arch stand-in: Autoware's parameter helpers (autoware_utils and
// autoware_utils_rclcpp spell the same functions), for workspaces that have the library
// installed, not as sources: declarations only. get_or_declare_parameter<T>(node, name)
// returns the parameter, declaring it (typed T, with no default) unless it is declared
// already: an API row of the extractor. update_param reads a list of parameters given to
// a callback, not the node.
#ifndef HAROS_STANDIN_AUTOWARE_PARAMETER_H
#define HAROS_STANDIN_AUTOWARE_PARAMETER_H
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#define HAROS_AUTOWARE_PARAMETER                                                            \
  template<class T, class NodeT> T get_or_declare_parameter(NodeT& node,                  \
                                                            const std::string& name);     \
  template<class T> bool update_param(const std::vector<rclcpp::Parameter>& params,        \
                                      const std::string& name, T& value);
namespace autoware_utils { HAROS_AUTOWARE_PARAMETER }
namespace autoware_utils_rclcpp { HAROS_AUTOWARE_PARAMETER }
#undef HAROS_AUTOWARE_PARAMETER
#endif
