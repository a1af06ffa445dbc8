// haros_arch stand-in: the plugin export macros
#ifndef HAROS_STANDIN_PLUGINLIB_CLASS_LIST_MACROS_HPP
#define HAROS_STANDIN_PLUGINLIB_CLASS_LIST_MACROS_HPP
// every other pluginlib header stands in as this one: the ClassLoader comes with it
#include <pluginlib/class_loader.hpp>
#include <haros_registration.h>
#define PLUGINLIB_EXPORT_CLASS(class_type, base_class_type) \
  HAROS_PLUGIN_EXPORT(class_type, base_class_type)
#define PLUGINLIB_DECLARE_CLASS(pkg, name, class_type, base_class_type) \
  PLUGINLIB_EXPORT_CLASS(class_type, base_class_type)
#endif
