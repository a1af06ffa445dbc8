// haros_arch stand-in: the plugin export macros
#ifndef HAROS_STANDIN_PLUGINLIB_CLASS_LIST_MACROS_HPP
#define HAROS_STANDIN_PLUGINLIB_CLASS_LIST_MACROS_HPP
// every other pluginlib header stands in as this one: the ClassLoader comes with it
#include <pluginlib/class_loader.hpp>
namespace haros_standin { template<class C, class B> struct plugin_export { typedef C type; }; }
// a name of its own per export (pasting __LINE__ itself would give every export of a file
// one name: a redefinition, and the second class's export lost)
#define HAROS_PLUGIN_EXPORT_NAME2(counter) haros_plugin_export_##counter
#define HAROS_PLUGIN_EXPORT_NAME(counter) HAROS_PLUGIN_EXPORT_NAME2(counter)
#define PLUGINLIB_EXPORT_CLASS(class_type, base_class_type) \
  static haros_standin::plugin_export<class_type, base_class_type> \
      HAROS_PLUGIN_EXPORT_NAME(__COUNTER__);
#define PLUGINLIB_DECLARE_CLASS(pkg, name, class_type, base_class_type) \
  PLUGINLIB_EXPORT_CLASS(class_type, base_class_type)
#endif
