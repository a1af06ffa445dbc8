// haros_arch stand-in: camera_info_manager for ROS 2 (declarations only). Its
// constructors create the node's private ~/set_camera_info service, as from Jazzy on
// (Humble's is relative, set_camera_info); api.RCLCPP_LIBRARIES.
#ifndef HAROS_STANDIN_CAMERA_INFO_MANAGER_HPP
#define HAROS_STANDIN_CAMERA_INFO_MANAGER_HPP
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <rmw/qos_profiles.h>
#include <sensor_msgs/msg/camera_info.hpp>
namespace camera_info_manager {
class CameraInfoManager {
public:
  explicit CameraInfoManager(rclcpp::Node* node, const std::string& cname = "camera",
                             const std::string& url = "", const std::string& ns = "~");
  explicit CameraInfoManager(rclcpp_lifecycle::LifecycleNode* node,
                             const std::string& cname = "camera", const std::string& url = "",
                             const std::string& ns = "~");
  CameraInfoManager(
      rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_base_interface,
      rclcpp::node_interfaces::NodeServicesInterface::SharedPtr node_services_interface,
      rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr node_logger_interface,
      const std::string& cname = "camera", const std::string& url = "",
      rmw_qos_profile_t custom_qos = rmw_qos_profile_default, const std::string& ns = "~");
  sensor_msgs::msg::CameraInfo getCameraInfo(void);
  bool isCalibrated(void);
  bool loadCameraInfo(const std::string& url);
  std::string resolveURL(const std::string& url, const std::string& cname);
  bool setCameraName(const std::string& cname);
  bool setCameraInfo(const sensor_msgs::msg::CameraInfo& camera_info);
  bool validateURL(const std::string& url);
};
}  // namespace camera_info_manager
#endif
