// haros_arch stand-in: the component registration macro
#ifndef HAROS_STANDIN_RCLCPP_COMPONENTS_REGISTER_NODE_MACRO_HPP
#define HAROS_STANDIN_RCLCPP_COMPONENTS_REGISTER_NODE_MACRO_HPP
#include <rclcpp/rclcpp.hpp>
namespace haros_standin { template<class T> struct component_registration { typedef T type; }; }
#define RCLCPP_COMPONENTS_REGISTER_NODE(NodeClass) \
  static haros_standin::component_registration<NodeClass> haros_component_registration;
#endif
