// haros_arch stand-in: the angles package's functions (declarations only)
#ifndef HAROS_STANDIN_ANGLES_H
#define HAROS_STANDIN_ANGLES_H
namespace angles {
double from_degrees(double degrees);
double to_degrees(double radians);
double normalize_angle_positive(double angle);
double normalize_angle(double angle);
double shortest_angular_distance(double from, double to);
double two_pi_complement(double angle);
bool find_min_max_delta(double from, double left_limit, double right_limit,
                        double &result_min_delta, double &result_max_delta);
bool shortest_angular_distance_with_limits(double from, double to, double left_limit,
                                           double right_limit, double &shortest_angle);
// limits wider than a turn (joint_trajectory_controller's wrapping of continuous joints)
bool shortest_angular_distance_with_large_limits(double from, double to, double left_limit,
                                                 double right_limit, double &shortest_angle);
}  // namespace angles
#endif
