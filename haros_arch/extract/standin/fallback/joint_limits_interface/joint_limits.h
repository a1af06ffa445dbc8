// haros_arch stand-in: ROS 1 ros_control's joint limits structs (joint_limits.h), for a
// workspace that has joint_limits_interface installed, not as sources (headers.FALLBACK)
#ifndef HAROS_STANDIN_JOINT_LIMITS_INTERFACE_JOINT_LIMITS_H
#define HAROS_STANDIN_JOINT_LIMITS_INTERFACE_JOINT_LIMITS_H
namespace joint_limits_interface {
struct JointLimits {
  double min_position = 0.0, max_position = 0.0, max_velocity = 0.0,
         max_acceleration = 0.0, max_jerk = 0.0, max_effort = 0.0;
  bool has_position_limits = false, has_velocity_limits = false,
       has_acceleration_limits = false, has_jerk_limits = false,
       has_effort_limits = false, angle_wraparound = false;
};
struct SoftJointLimits {
  double min_position = 0.0, max_position = 0.0, k_position = 0.0, k_velocity = 0.0;
};
}  // namespace joint_limits_interface
#endif
