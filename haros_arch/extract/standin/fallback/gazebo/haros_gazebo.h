// haros_arch stand-in: the plugin base classes of Gazebo classic (gazebo 7 to 11) and
// their registration macros (declarations only; every gazebo/... header stands in as
// this one, read only when the workspace has no such header, headers.FALLBACK_UMBRELLAS).
// A library whose source registers a class with GZ_REGISTER_*_PLUGIN is a plugin node
// (cmake.nodes.gazebo_plugins). Gazebo's own classes (physics::Model, sensors::Sensor,
// math, common, event, ...) are not declared here: the parse declares what a plugin uses
// of them as unknown names, which have every member asked for. So the bases cannot
// declare Load with those types, and ``override`` is defined empty where Gazebo is
// included: a plugin's ``Load(...) override`` overrides nothing here.
#ifndef HAROS_STANDIN_GAZEBO_H
#define HAROS_STANDIN_GAZEBO_H
#include <functional>
#include <iostream>
#include <stdexcept>
#include <memory>
#include <string>
#include <vector>
#include <boost/shared_ptr.hpp>
// boost::bind and its placeholders in the global namespace, which Gazebo's headers bring
// (gazebo/transport/Node.hh writes ``boost::bind(_fp, _obj, _1)``): a plugin binds its
// update callback with a bare ``_1``
#include <boost/bind.hpp>
#include <sdf/sdf.hh>
#include <haros_registration.h>

#define override

// gazebo/util/system.hh: the symbol visibility of Gazebo's libraries and of plugins,
// written between ``class`` and the name (``class GZ_PLUGIN_VISIBLE MyPlugin :
// public ModelPlugin``); attributes only, empty here as in a static build
#define GAZEBO_VISIBLE
#define GAZEBO_HIDDEN
#define GZ_COMMON_VISIBLE
#define GZ_MATH_VISIBLE
#define GZ_TRANSPORT_VISIBLE
#define GZ_MSGS_VISIBLE
#define GZ_RENDERING_VISIBLE
#define GZ_UTIL_VISIBLE
#define GZ_PLUGIN_VISIBLE
#define GZ_PLUGIN_HIDDEN
#define GZ_PHYSICS_VISIBLE
#define GZ_SENSORS_VISIBLE
#define GZ_GUI_VISIBLE

// gazebo/gazebo_config.h: Gazebo 11 (the version of ROS Noetic, Foxy and Humble)
#define GAZEBO_MAJOR_VERSION 11
#define GAZEBO_MINOR_VERSION 0
#define GAZEBO_PATCH_VERSION 0

// a plugin casts what Gazebo gives it (``dynamic_pointer_cast<sensors::RaySensor>(
// _sensor)``, boost's in Gazebo 7 and older code), whose class the parse declares
// permissively: not a shared_ptr here
namespace std
{
template <class T, class U> shared_ptr<T> dynamic_pointer_cast(const U &_value);
}  // namespace std
namespace boost
{
template <class T, class U> shared_ptr<T> dynamic_pointer_cast(const U &_value);
}  // namespace boost

// gazebo/common/Console.hh and Exception.hh: the log streams and the throwing macro
#define gzerr std::cerr
#define gzwarn std::cerr
#define gzmsg std::cout
#define gzdbg std::cout
#define gzlog std::cout
#define gzthrow(msg) throw std::runtime_error("gazebo")

namespace gazebo
{
// Gazebo's libraries, by namespace: what a plugin uses of them (``common::Time``,
// ``physics::ModelPtr``) is declared permissively there, Gazebo's, not a ROS
// package's of that name (a workspace package ``common``)
namespace common {}
namespace physics {}
namespace sensors {}
namespace rendering {}
namespace event {}
namespace msgs {}
namespace util {}
namespace gui {}
// gazebo/transport: Gazebo's own topics (not ROS): a plugin advertises and subscribes
// gz messages there, which makes no ROS call; declared so that its code parses. Its
// pointers are boost's (gazebo/transport/TransportTypes.hh), as plugins build them:
// ``boost::make_shared<transport::Node>()``, ``transport::NodePtr(new transport::Node())``
namespace transport
{
class Publisher
{
public:
  template <class M> void Publish(const M &_message, bool _block = false);
  bool HasConnections() const;
  std::string GetTopic() const;
};
class Subscriber
{
public:
  std::string GetTopic() const;
  void Unsubscribe() const;
};
typedef boost::shared_ptr<Publisher> PublisherPtr;
typedef boost::shared_ptr<Subscriber> SubscriberPtr;
class Node
{
public:
  Node();
  void Init(const std::string &_space = "");
  void Fini();
  std::string GetTopicNamespace() const;
  template <class M> PublisherPtr Advertise(const std::string &_topic,
                                            unsigned int _limit = 1000, double _hz = 0);
  template <class F, class T> SubscriberPtr Subscribe(const std::string &_topic, F _callback,
                                                      T *_object, bool _latching = false);
  template <class F> SubscriberPtr Subscribe(const std::string &_topic, F _callback,
                                             bool _latching = false);
};
typedef boost::shared_ptr<Node> NodePtr;
}  // namespace transport

template <class T> class PluginT
{
public:
  virtual ~PluginT();
  std::string GetFilename() const;
  std::string GetHandle() const;
};

class WorldPlugin : public PluginT<WorldPlugin>
{
public:
  virtual void Init();
  virtual void Reset();
};

class ModelPlugin : public PluginT<ModelPlugin>
{
public:
  virtual void Init();
  virtual void Reset();
};

class SensorPlugin : public PluginT<SensorPlugin>
{
public:
  virtual void Init();
  virtual void Reset();
};

class SystemPlugin : public PluginT<SystemPlugin>
{
public:
  virtual void Init();
  virtual void Reset();
};

class VisualPlugin : public PluginT<VisualPlugin>
{
public:
  virtual void Init();
  virtual void Reset();
};

class GUIPlugin : public PluginT<GUIPlugin>
{
public:
};
}  // namespace gazebo

#define GZ_REGISTER_WORLD_PLUGIN(classname) \
  HAROS_PLUGIN_EXPORT(classname, gazebo::WorldPlugin) \
  extern "C" void *RegisterPlugin() { return new classname(); }
#define GZ_REGISTER_MODEL_PLUGIN(classname) \
  HAROS_PLUGIN_EXPORT(classname, gazebo::ModelPlugin) \
  extern "C" void *RegisterPlugin() { return new classname(); }
#define GZ_REGISTER_SENSOR_PLUGIN(classname) \
  HAROS_PLUGIN_EXPORT(classname, gazebo::SensorPlugin) \
  extern "C" void *RegisterPlugin() { return new classname(); }
#define GZ_REGISTER_SYSTEM_PLUGIN(classname) \
  HAROS_PLUGIN_EXPORT(classname, gazebo::SystemPlugin) \
  extern "C" void *RegisterPlugin() { return new classname(); }
#define GZ_REGISTER_VISUAL_PLUGIN(classname) \
  HAROS_PLUGIN_EXPORT(classname, gazebo::VisualPlugin) \
  extern "C" void *RegisterPlugin() { return new classname(); }
#define GZ_REGISTER_GUI_PLUGIN(classname) \
  HAROS_PLUGIN_EXPORT(classname, gazebo::GUIPlugin) \
  extern "C" void *RegisterPlugin() { return new classname(); }
#endif
