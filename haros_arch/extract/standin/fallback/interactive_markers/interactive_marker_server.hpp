// haros_arch stand-in: ROS 2 interactive_markers' InteractiveMarkerServer (declarations
// only), for a workspace that has interactive_markers installed, not as sources. What it
// publishes, subscribes and serves is said by its API row (extract/cpp/api.py). The ROS 2
// headers share the ROS 1 ones' include guards: a unit includes one ROS's.
#ifndef HAROS_STANDIN_INTERACTIVE_MARKERS_SERVER_H
#define HAROS_STANDIN_INTERACTIVE_MARKERS_SERVER_H
#include <functional>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/header.hpp>
#include <geometry_msgs/msg/pose.hpp>
#include <visualization_msgs/msg/interactive_marker.hpp>
#include <visualization_msgs/msg/interactive_marker_feedback.hpp>
#include <visualization_msgs/msg/interactive_marker_update.hpp>
#include <visualization_msgs/srv/get_interactive_markers.hpp>

namespace interactive_markers {
class InteractiveMarkerServer {
 public:
  typedef visualization_msgs::msg::InteractiveMarkerFeedback::ConstSharedPtr
      FeedbackConstSharedPtr;
  typedef std::function<void(FeedbackConstSharedPtr)> FeedbackCallback;
  static const uint8_t DEFAULT_FEEDBACK_CB = 255;
  InteractiveMarkerServer(
      const std::string& topic_namespace,
      rclcpp::node_interfaces::NodeBaseInterface::SharedPtr base_interface,
      rclcpp::node_interfaces::NodeClockInterface::SharedPtr clock_interface,
      rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr logging_interface,
      rclcpp::node_interfaces::NodeTopicsInterface::SharedPtr topics_interface,
      rclcpp::node_interfaces::NodeServicesInterface::SharedPtr services_interface,
      const rclcpp::QoS& update_pub_qos = rclcpp::QoS(100),
      const rclcpp::QoS& feedback_sub_qos = rclcpp::QoS(1));
  template<typename NodePtr>
  InteractiveMarkerServer(const std::string& topic_namespace, NodePtr node,
                          const rclcpp::QoS& update_pub_qos = rclcpp::QoS(100),
                          const rclcpp::QoS& feedback_sub_qos = rclcpp::QoS(1));
  ~InteractiveMarkerServer();
  void insert(const visualization_msgs::msg::InteractiveMarker& int_marker);
  void insert(const visualization_msgs::msg::InteractiveMarker& int_marker,
              FeedbackCallback feedback_cb, uint8_t feedback_type = DEFAULT_FEEDBACK_CB);
  bool setPose(const std::string& name, const geometry_msgs::msg::Pose& pose,
               const std_msgs::msg::Header& header = std_msgs::msg::Header());
  bool erase(const std::string& name);
  void clear();
  bool empty() const;
  std::size_t size() const;
  bool setCallback(const std::string& name, FeedbackCallback feedback_cb,
                   uint8_t feedback_type = DEFAULT_FEEDBACK_CB);
  void applyChanges();
  bool get(std::string name, visualization_msgs::msg::InteractiveMarker& int_marker) const;
};
}  // namespace interactive_markers
#endif
