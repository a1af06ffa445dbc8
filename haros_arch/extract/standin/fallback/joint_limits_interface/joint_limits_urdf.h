// haros_arch stand-in: ROS 1 ros_control's joint_limits_urdf.h (declarations only), for
// a workspace that has joint_limits_interface installed, not as sources
// (headers.FALLBACK): the limits of a joint as its URDF gives them, no ROS call. The
// overloads that read the handle given are joint_limits_rosparam.h's.
#ifndef HAROS_STANDIN_JOINT_LIMITS_INTERFACE_JOINT_LIMITS_URDF_H
#define HAROS_STANDIN_JOINT_LIMITS_INTERFACE_JOINT_LIMITS_URDF_H
#include <urdf/model.h>
#include <joint_limits_interface/joint_limits.h>

namespace joint_limits_interface {
bool getJointLimits(urdf::JointConstSharedPtr urdf_joint, JointLimits& limits);
bool getSoftJointLimits(urdf::JointConstSharedPtr urdf_joint, SoftJointLimits& soft_limits);
}  // namespace joint_limits_interface
#endif
