// haros_arch stand-in: the part of SDFormat's sdf::Element that Gazebo classic plugins
// read their <plugin> element's children with (declarations only; every sdf/... header
// stands in as this one, read only when the workspace has no sdformat sources,
// headers.FALLBACK_UMBRELLAS). Element::Get and GetElement are API rows (api.SDF): the
// value a name takes from them is filled from the description (robot.attach).
#ifndef HAROS_STANDIN_SDF_H
#define HAROS_STANDIN_SDF_H
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sdf
{
class Element;
class Param;
typedef std::shared_ptr<Element> ElementPtr;
typedef std::shared_ptr<const Element> ElementConstPtr;
typedef std::shared_ptr<Param> ParamPtr;

class Param
{
public:
  std::string GetAsString() const;
  std::string GetDefaultAsString() const;
  std::string GetKey() const;
  bool GetSet() const;
  template <typename T> bool Get(T &_value) const;
  template <typename T> bool Set(const T &_value);
  bool SetFromString(const std::string &_value);
};

class Element : public std::enable_shared_from_this<Element>
{
public:
  bool HasElement(const std::string &_name) const;
  bool HasAttribute(const std::string &_key) const;
  ElementPtr GetElement(const std::string &_name);
  ElementPtr GetElement(const std::string &_name) const;
  ElementPtr FindElement(const std::string &_name);
  ElementPtr GetFirstElement() const;
  ElementPtr GetNextElement(const std::string &_name = "") const;
  ElementPtr GetParent() const;
  ElementPtr AddElement(const std::string &_name);
  ParamPtr GetValue() const;
  ParamPtr GetAttribute(const std::string &_key) const;
  std::string GetName() const;
  std::string ToString(const std::string &_prefix) const;
  template <typename T> T Get(const std::string &_key = "") const;
  template <typename T> std::pair<T, bool> Get(const std::string &_key,
                                               const T &_defaultValue) const;
  template <typename T> bool Get(const std::string &_key, T &_param,
                                 const T &_defaultValue) const;
  template <typename T> bool Set(const T &_value);
};
}  // namespace sdf
#endif
