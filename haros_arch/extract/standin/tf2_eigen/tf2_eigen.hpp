// haros_arch stand-in: tf2_eigen's conversions between Eigen and the geometry messages
// (declarations only; every tf2_eigen header stands in as this one)
#ifndef HAROS_STANDIN_TF2_EIGEN_HPP
#define HAROS_STANDIN_TF2_EIGEN_HPP
#include <Eigen/Dense>
#include <tf2_ros/buffer.h>
namespace tf2 {
template<class T> Eigen::Isometry3d transformToEigen(const T& t);
template<class T> haros_standin::any_transform_stamped eigenToTransform(const T& t);
// an Eigen value as its geometry_msgs message (lidar_localization_ros2's
// ``geometry_msgs::msg::Quaternion quat_msg = tf2::toMsg(quat_eig);``): a quaternion
// becomes a Quaternion, a vector a Point (``toMsg2``: a Vector3), an isometry or an affine
// transform a Pose, a 6-vector a Twist
haros_standin::any_quaternion toMsg(const Eigen::Quaterniond& in);
haros_standin::any_message toMsg(const Eigen::Vector3d& in);
haros_standin::any_vector3 toMsg2(const Eigen::Vector3d& in);
haros_standin::any_message toMsg(const Eigen::Isometry3d& in);
haros_standin::any_message toMsg(const Eigen::Affine3d& in);
haros_standin::any_message toMsg(const Eigen::Matrix<double, 6, 1>& in);
}  // namespace tf2
#endif
