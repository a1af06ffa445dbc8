// haros_arch stand-in: class_loader, plugins loaded by name (declarations only)
#ifndef HAROS_STANDIN_CLASS_LOADER_HPP
#define HAROS_STANDIN_CLASS_LOADER_HPP
#include <memory>
#include <string>
#include <vector>
#include <haros_registration.h>
namespace class_loader {
class ClassLoader {
public:
  explicit ClassLoader(const std::string& library_path, bool ondemand_load_unload = false);
  virtual ~ClassLoader();
  template<class Base> std::vector<std::string> getAvailableClasses() const;
  template<class Base> std::shared_ptr<Base> createInstance(const std::string& derived);
  template<class Base> std::unique_ptr<Base> createUniqueInstance(const std::string& derived);
  template<class Base> bool isClassAvailable(const std::string& derived) const;
  const std::string& getLibraryPath() const;
  bool isLibraryLoaded() const;
  void loadLibrary();
  int unloadLibrary();
};
class MultiLibraryClassLoader {
public:
  explicit MultiLibraryClassLoader(bool enable_ondemand_loadunload);
  template<class Base> std::vector<std::string> getAvailableClasses() const;
  template<class Base> std::shared_ptr<Base> createInstance(const std::string& derived);
  void loadLibrary(const std::string& library_path);
};
}
// the registration pluginlib's export expands to, written by some libraries themselves
// (a component's factory: rclcpp_components' macro is this one in ROS 2)
#define CLASS_LOADER_REGISTER_CLASS(Derived, Base) HAROS_PLUGIN_EXPORT(Derived, Base)
#define CLASS_LOADER_REGISTER_CLASS_WITH_MESSAGE(Derived, Base, Message) \
  HAROS_PLUGIN_EXPORT(Derived, Base)
#endif
