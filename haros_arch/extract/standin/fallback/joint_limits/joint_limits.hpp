// haros_arch stand-in: ros2_control's joint limits (declarations only; read only when the
// workspace has no joint_limits package, headers.FALLBACK)
#ifndef HAROS_STANDIN_JOINT_LIMITS_HPP
#define HAROS_STANDIN_JOINT_LIMITS_HPP
namespace joint_limits {
struct JointLimits {
  double min_position, max_position, max_velocity, max_acceleration, max_deceleration,
      max_jerk, max_effort;
  bool has_position_limits, has_velocity_limits, has_acceleration_limits,
      has_deceleration_limits, has_jerk_limits, has_effort_limits, angle_wraparound;
};
struct SoftJointLimits {
  double min_position, max_position, k_position, k_velocity;
};
}  // namespace joint_limits
#endif
