// haros_arch stand-in: class_loader, plugins loaded by name (declarations only)
#ifndef HAROS_STANDIN_CLASS_LOADER_HPP
#define HAROS_STANDIN_CLASS_LOADER_HPP
#include <memory>
#include <string>
#include <vector>
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
#define CLASS_LOADER_REGISTER_CLASS(Derived, Base)
#endif
