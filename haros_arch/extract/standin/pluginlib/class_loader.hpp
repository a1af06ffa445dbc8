// haros_arch stand-in: pluginlib's ClassLoader and its exceptions (ROS 1 and ROS 2 API;
// declarations only). A class made by name is only known at run time: the extractor
// reports the sites (CPP_PLUGINS_LOADED) and the plugin models give their interfaces.
#ifndef HAROS_STANDIN_PLUGINLIB_CLASS_LOADER_HPP
#define HAROS_STANDIN_PLUGINLIB_CLASS_LOADER_HPP
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>
#include <boost/shared_ptr.hpp>
namespace pluginlib {
class PluginlibException : public std::runtime_error {
public:
  explicit PluginlibException(const std::string& error_desc);
};
class LibraryLoadException : public PluginlibException { public: using PluginlibException::PluginlibException; };
class ClassLoaderException : public PluginlibException { public: using PluginlibException::PluginlibException; };
class LibraryUnloadException : public PluginlibException { public: using PluginlibException::PluginlibException; };
class CreateClassException : public PluginlibException { public: using PluginlibException::PluginlibException; };
template<class T> using UniquePtr = std::unique_ptr<T>;
class ClassLoaderBase {
public:
  virtual ~ClassLoaderBase();
  virtual std::vector<std::string> getDeclaredClasses() = 0;
};
template<class T> class ClassLoader : public ClassLoaderBase {
public:
  ClassLoader(std::string package, std::string base_class,
              std::string attrib_name = std::string("plugin"),
              std::vector<std::string> plugin_xml_paths = std::vector<std::string>());
  ~ClassLoader();
  std::shared_ptr<T> createSharedInstance(const std::string& lookup_name);
  UniquePtr<T> createUniqueInstance(const std::string& lookup_name);
  T* createUnmanagedInstance(const std::string& lookup_name);
  boost::shared_ptr<T> createInstance(const std::string& lookup_name);  // ROS 1
  T* createClassInstance(const std::string& lookup_name, bool auto_load = true);
  std::vector<std::string> getDeclaredClasses();
  std::string getName(const std::string& lookup_name);
  std::string getBaseClassType() const;
  std::string getClassDescription(const std::string& lookup_name);
  std::string getClassType(const std::string& lookup_name);
  std::string getClassPackage(const std::string& lookup_name);
  std::string getClassLibraryPath(const std::string& lookup_name);
  std::string getPluginManifestPath(const std::string& lookup_name);
  std::vector<std::string> getPluginXmlPaths();
  std::vector<std::string> getRegisteredLibraries();
  bool isClassAvailable(const std::string& lookup_name);
  bool isClassLoaded(const std::string& lookup_name);
  void loadLibraryForClass(const std::string& lookup_name);
  int unloadLibraryForClass(const std::string& lookup_name);
  void refreshDeclaredClasses();
};
}  // namespace pluginlib
#endif
