// haros_arch stand-in: ROS 1 ros_control's joint_limits_rosparam.h (declarations only),
// for a workspace that has joint_limits_interface installed, not as sources
// (headers.FALLBACK). What the two functions read from the handle given is an API row
// (api.JOINT_LIMITS_INTERFACE).
#ifndef HAROS_STANDIN_JOINT_LIMITS_INTERFACE_JOINT_LIMITS_ROSPARAM_H
#define HAROS_STANDIN_JOINT_LIMITS_INTERFACE_JOINT_LIMITS_ROSPARAM_H
#include <string>
#include <ros/ros.h>
#include <joint_limits_interface/joint_limits.h>

namespace joint_limits_interface {
bool getJointLimits(const std::string& joint_name, const ros::NodeHandle& nh,
                    JointLimits& limits);
bool getSoftJointLimits(const std::string& joint_name, const ros::NodeHandle& nh,
                        SoftJointLimits& soft_limits);
}  // namespace joint_limits_interface
#endif
