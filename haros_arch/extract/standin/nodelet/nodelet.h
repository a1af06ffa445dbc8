// haros_arch stand-in: nodelet::Nodelet (declarations only)
#ifndef HAROS_STANDIN_NODELET_NODELET_H
#define HAROS_STANDIN_NODELET_NODELET_H
#include <ros/ros.h>
// every level and variant nodelet's own header defines (the nodelet's name prefixes the
// message there; the ROS calls around them are what matters here)
#define NODELET_DEBUG(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_DEBUG_STREAM(args) HAROS_STANDIN_STREAM(args)
#define NODELET_DEBUG_ONCE(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_DEBUG_STREAM_ONCE(args) HAROS_STANDIN_STREAM(args)
#define NODELET_DEBUG_COND(cond, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_DEBUG_STREAM_COND(cond, args) HAROS_STANDIN_STREAM(args)
#define NODELET_DEBUG_THROTTLE(rate, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_DEBUG_STREAM_THROTTLE(rate, args) HAROS_STANDIN_STREAM(args)
#define NODELET_DEBUG_DELAYED_THROTTLE(rate, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_DEBUG_STREAM_DELAYED_THROTTLE(rate, args) HAROS_STANDIN_STREAM(args)
#define NODELET_DEBUG_FILTER(filter, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_DEBUG_STREAM_FILTER(filter, args) HAROS_STANDIN_STREAM(args)
#define NODELET_INFO(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_INFO_STREAM(args) HAROS_STANDIN_STREAM(args)
#define NODELET_INFO_ONCE(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_INFO_STREAM_ONCE(args) HAROS_STANDIN_STREAM(args)
#define NODELET_INFO_COND(cond, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_INFO_STREAM_COND(cond, args) HAROS_STANDIN_STREAM(args)
#define NODELET_INFO_THROTTLE(rate, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_INFO_STREAM_THROTTLE(rate, args) HAROS_STANDIN_STREAM(args)
#define NODELET_INFO_DELAYED_THROTTLE(rate, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_INFO_STREAM_DELAYED_THROTTLE(rate, args) HAROS_STANDIN_STREAM(args)
#define NODELET_INFO_FILTER(filter, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_INFO_STREAM_FILTER(filter, args) HAROS_STANDIN_STREAM(args)
#define NODELET_WARN(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_WARN_STREAM(args) HAROS_STANDIN_STREAM(args)
#define NODELET_WARN_ONCE(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_WARN_STREAM_ONCE(args) HAROS_STANDIN_STREAM(args)
#define NODELET_WARN_COND(cond, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_WARN_STREAM_COND(cond, args) HAROS_STANDIN_STREAM(args)
#define NODELET_WARN_THROTTLE(rate, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_WARN_STREAM_THROTTLE(rate, args) HAROS_STANDIN_STREAM(args)
#define NODELET_WARN_DELAYED_THROTTLE(rate, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_WARN_STREAM_DELAYED_THROTTLE(rate, args) HAROS_STANDIN_STREAM(args)
#define NODELET_WARN_FILTER(filter, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_WARN_STREAM_FILTER(filter, args) HAROS_STANDIN_STREAM(args)
#define NODELET_ERROR(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_ERROR_STREAM(args) HAROS_STANDIN_STREAM(args)
#define NODELET_ERROR_ONCE(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_ERROR_STREAM_ONCE(args) HAROS_STANDIN_STREAM(args)
#define NODELET_ERROR_COND(cond, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_ERROR_STREAM_COND(cond, args) HAROS_STANDIN_STREAM(args)
#define NODELET_ERROR_THROTTLE(rate, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_ERROR_STREAM_THROTTLE(rate, args) HAROS_STANDIN_STREAM(args)
#define NODELET_ERROR_DELAYED_THROTTLE(rate, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_ERROR_STREAM_DELAYED_THROTTLE(rate, args) HAROS_STANDIN_STREAM(args)
#define NODELET_ERROR_FILTER(filter, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_ERROR_STREAM_FILTER(filter, args) HAROS_STANDIN_STREAM(args)
#define NODELET_FATAL(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_FATAL_STREAM(args) HAROS_STANDIN_STREAM(args)
#define NODELET_FATAL_ONCE(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_FATAL_STREAM_ONCE(args) HAROS_STANDIN_STREAM(args)
#define NODELET_FATAL_COND(cond, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_FATAL_STREAM_COND(cond, args) HAROS_STANDIN_STREAM(args)
#define NODELET_FATAL_THROTTLE(rate, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_FATAL_STREAM_THROTTLE(rate, args) HAROS_STANDIN_STREAM(args)
#define NODELET_FATAL_DELAYED_THROTTLE(rate, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_FATAL_STREAM_DELAYED_THROTTLE(rate, args) HAROS_STANDIN_STREAM(args)
#define NODELET_FATAL_FILTER(filter, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define NODELET_FATAL_STREAM_FILTER(filter, args) HAROS_STANDIN_STREAM(args)
namespace nodelet {
typedef std::vector<std::string> V_string;
typedef std::map<std::string, std::string> M_string;
class Nodelet {
protected:
  const std::string& getName() const;
  ros::NodeHandle& getNodeHandle() const;
  ros::NodeHandle& getPrivateNodeHandle() const;
  ros::NodeHandle& getMTNodeHandle() const;
  ros::NodeHandle& getMTPrivateNodeHandle() const;
  ros::CallbackQueueInterface& getMTCallbackQueue() const;
  const V_string& getMyArgv() const;
  const M_string& getRemappingArgs() const;
  virtual void onInit() = 0;
public:
  Nodelet();
  virtual ~Nodelet();
};
// nodelet/loader.h: a process that loads nodelets by name (its loads are
// CPP_PLUGINS_LOADED, found in the source's text)
class Loader {
public:
  explicit Loader(bool provide_ros_api = true);
  explicit Loader(const ros::NodeHandle& server_nh);
  ~Loader();
  bool load(const std::string& name, const std::string& type, const M_string& remappings,
            const V_string& my_argv);
  bool unload(const std::string& name);
  bool clear();
  std::vector<std::string> listLoadedNodelets();
};
}
#endif
