// haros_arch stand-in: the plugin export macros
#ifndef HAROS_STANDIN_PLUGINLIB_CLASS_LIST_MACROS_HPP
#define HAROS_STANDIN_PLUGINLIB_CLASS_LIST_MACROS_HPP
namespace haros_standin { template<class C, class B> struct plugin_export { typedef C type; }; }
#define PLUGINLIB_EXPORT_CLASS(class_type, base_class_type) \
  static haros_standin::plugin_export<class_type, base_class_type> haros_plugin_export_##__LINE__;
#define PLUGINLIB_DECLARE_CLASS(pkg, name, class_type, base_class_type) \
  PLUGINLIB_EXPORT_CLASS(class_type, base_class_type)
#endif
