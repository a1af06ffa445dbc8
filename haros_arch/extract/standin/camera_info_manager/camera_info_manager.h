// haros_arch stand-in: camera_info_manager for ROS 1 (declarations only). Its
// constructor advertises the set_camera_info service in the namespace of the handle it
// is given (api.LIBRARIES).
#ifndef HAROS_STANDIN_CAMERA_INFO_MANAGER_H
#define HAROS_STANDIN_CAMERA_INFO_MANAGER_H
#include <string>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
namespace camera_info_manager {
class CameraInfoManager {
public:
  explicit CameraInfoManager(ros::NodeHandle nh, const std::string& cname = "camera",
                             const std::string& url = "");
  virtual ~CameraInfoManager();
  virtual sensor_msgs::CameraInfo getCameraInfo(void);
  virtual bool isCalibrated(void);
  virtual bool loadCameraInfo(const std::string& url);
  virtual std::string resolveURL(const std::string& url, const std::string& cname);
  virtual bool setCameraName(const std::string& cname);
  virtual bool setCameraInfo(const sensor_msgs::CameraInfo& camera_info);
  virtual bool validateURL(const std::string& url);
};
}  // namespace camera_info_manager
#endif
