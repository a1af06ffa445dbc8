// haros_arch stand-in: tf2_eigen's conversions between Eigen and the geometry messages
// (declarations only; every tf2_eigen header stands in as this one)
#ifndef HAROS_STANDIN_TF2_EIGEN_HPP
#define HAROS_STANDIN_TF2_EIGEN_HPP
#include <Eigen/Dense>
#include <tf2_ros/buffer.h>
namespace tf2 {
template<class T> Eigen::Isometry3d transformToEigen(const T& t);
template<class T> haros_standin::any_transform_stamped eigenToTransform(const T& t);
}  // namespace tf2
#endif
