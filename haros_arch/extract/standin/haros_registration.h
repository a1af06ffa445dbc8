// haros_arch stand-in: what a plugin's registration macro declares, shared by the macros
// of pluginlib (PLUGINLIB_EXPORT_CLASS), class_loader (CLASS_LOADER_REGISTER_CLASS) and
// Gazebo classic (GZ_REGISTER_*_PLUGIN): a variable of namespace scope whose type names
// the class its host constructs (``owners.registered_class``), as a container's
// registration does (rclcpp_components' own, component_registration)
#ifndef HAROS_STANDIN_REGISTRATION_H
#define HAROS_STANDIN_REGISTRATION_H
namespace haros_standin { template<class C, class B> struct plugin_export { typedef C type; }; }
// a name of its own per export (pasting __LINE__ itself would give every export of a file
// one name: a redefinition, and the second class's export lost)
#define HAROS_PLUGIN_EXPORT_NAME2(counter) haros_plugin_export_##counter
#define HAROS_PLUGIN_EXPORT_NAME(counter) HAROS_PLUGIN_EXPORT_NAME2(counter)
#define HAROS_PLUGIN_EXPORT(class_type, base_class_type) \
  static haros_standin::plugin_export<class_type, base_class_type> \
      HAROS_PLUGIN_EXPORT_NAME(__COUNTER__);
#endif
