// haros_arch stand-in: nodelet::Nodelet (declarations only)
#ifndef HAROS_STANDIN_NODELET_NODELET_H
#define HAROS_STANDIN_NODELET_NODELET_H
#include <ros/ros.h>
#define NODELET_DEBUG(...) ROS_DEBUG(__VA_ARGS__)
#define NODELET_INFO(...) ROS_INFO(__VA_ARGS__)
#define NODELET_WARN(...) ROS_WARN(__VA_ARGS__)
#define NODELET_ERROR(...) ROS_ERROR(__VA_ARGS__)
#define NODELET_FATAL(...) ROS_FATAL(__VA_ARGS__)
#define NODELET_DEBUG_STREAM(args) ROS_DEBUG_STREAM(args)
#define NODELET_INFO_STREAM(args) ROS_INFO_STREAM(args)
#define NODELET_WARN_STREAM(args) ROS_WARN_STREAM(args)
#define NODELET_ERROR_STREAM(args) ROS_ERROR_STREAM(args)
#define NODELET_INFO_THROTTLE(rate, ...) ROS_INFO(__VA_ARGS__)
#define NODELET_WARN_THROTTLE(rate, ...) ROS_WARN(__VA_ARGS__)
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
}
#endif
