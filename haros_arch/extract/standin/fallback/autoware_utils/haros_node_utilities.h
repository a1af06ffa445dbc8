// haros_arch stand-in: two of Autoware's node utilities (autoware_utils_logging,
// autoware_utils_diagnostics; autoware_utils/ros/ before the split), for workspaces that
// have the library installed, not as sources: declarations only. What building one
// makes on the node given is an API row of the extractor (api.AUTOWARE):
// - the logger level configurator serves ``~/config_logger`` (logging_demo's
//   ConfigLogger), through which the node's logger levels are set;
// - the diagnostics interface publishes its node's status on ``/diagnostics`` (the
//   topic its older, compiled form took as a third argument);
// - the transform listener keeps a tf2 buffer fed by a tf2_ros::TransformListener: the
//   node listens to ``/tf`` and ``/tf_static``, as the extractor reads tf2_ros' own.
// The node is any pointer (the library takes the node class as a template parameter).
#ifndef HAROS_STANDIN_AUTOWARE_NODE_UTILITIES_H
#define HAROS_STANDIN_AUTOWARE_NODE_UTILITIES_H
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/transform_stamped.hpp>
#define HAROS_AUTOWARE_LOGGER_LEVEL_CONFIGURE                                               \
  template<class NodeT = rclcpp::Node> class BasicLoggerLevelConfigure {                    \
   public:                                                                                  \
    template<class N> explicit BasicLoggerLevelConfigure(N* node);                          \
  };                                                                                        \
  using LoggerLevelConfigure = BasicLoggerLevelConfigure<rclcpp::Node>;
#define HAROS_AUTOWARE_DIAGNOSTICS_INTERFACE                                                \
  template<class NodeT = rclcpp::Node> class BasicDiagnosticsInterface {                    \
   public:                                                                                  \
    template<class N> BasicDiagnosticsInterface(N* node, const std::string& diagnostic_name, \
        const std::string& diagnostic_topic_name = "/diagnostics");                         \
    void clear();                                                                           \
    template<class K> void add_key_value(const K& key_value);                               \
    template<class T> void add_key_value(const std::string& key, const T& value);          \
    void update_level_and_message(const int8_t level, const std::string& message);         \
    void publish(const rclcpp::Time& stamp);                                               \
  };                                                                                        \
  using DiagnosticsInterface = BasicDiagnosticsInterface<rclcpp::Node>;
#define HAROS_AUTOWARE_TRANSFORM_LISTENER                                                   \
  class TransformListener {                                                                 \
   public:                                                                                  \
    template<class N> explicit TransformListener(N* node);                                  \
    geometry_msgs::msg::TransformStamped::ConstSharedPtr get_latest_transform(              \
        const std::string& from, const std::string& to);                                    \
    geometry_msgs::msg::TransformStamped::ConstSharedPtr get_transform(                     \
        const std::string& from, const std::string& to, const rclcpp::Time& time,          \
        const rclcpp::Duration& duration);                                                  \
    rclcpp::Logger get_logger();                                                            \
  };
namespace autoware_utils_logging { HAROS_AUTOWARE_LOGGER_LEVEL_CONFIGURE }
namespace autoware_utils_tf { HAROS_AUTOWARE_TRANSFORM_LISTENER }
namespace autoware_utils_diagnostics { HAROS_AUTOWARE_DIAGNOSTICS_INTERFACE }
namespace autoware_utils { HAROS_AUTOWARE_LOGGER_LEVEL_CONFIGURE
                           HAROS_AUTOWARE_DIAGNOSTICS_INTERFACE
                           HAROS_AUTOWARE_TRANSFORM_LISTENER }
#undef HAROS_AUTOWARE_LOGGER_LEVEL_CONFIGURE
#undef HAROS_AUTOWARE_DIAGNOSTICS_INTERFACE
#undef HAROS_AUTOWARE_TRANSFORM_LISTENER
#endif
