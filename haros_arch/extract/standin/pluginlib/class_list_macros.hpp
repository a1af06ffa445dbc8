// haros_arch stand-in: the plugin export macros
#ifndef HAROS_STANDIN_PLUGINLIB_CLASS_LIST_MACROS_HPP
#define HAROS_STANDIN_PLUGINLIB_CLASS_LIST_MACROS_HPP
// every other pluginlib header stands in as this one: the ClassLoader comes with it
#include <pluginlib/class_loader.hpp>
namespace haros_standin { template<class C, class B> struct plugin_export { typedef C type; }; }
#define PLUGINLIB_EXPORT_CLASS(class_type, base_class_type) \
  static haros_standin::plugin_export<class_type, base_class_type> haros_plugin_export_##__LINE__;
#define PLUGINLIB_DECLARE_CLASS(pkg, name, class_type, base_class_type) \
  PLUGINLIB_EXPORT_CLASS(class_type, base_class_type)
#endif
