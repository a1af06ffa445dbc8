// haros_arch stand-in: tf_conversions' conversions between tf, Eigen and geometry_msgs
// (ROS 1, declarations only), for a workspace that has the package installed, not as
// sources. Each converts its first argument into its second: no ROS call.
#ifndef HAROS_STANDIN_TF_CONVERSIONS_TF_EIGEN_H
#define HAROS_STANDIN_TF_CONVERSIONS_TF_EIGEN_H
#include <Eigen/Dense>
#include <tf/transform_datatypes.h>
#include <geometry_msgs/Point.h>
#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3.h>
#include <geometry_msgs/Wrench.h>

namespace tf {
void matrixTFToEigen(const tf::Matrix3x3& t, Eigen::Matrix3d& e);
void matrixEigenToTF(const Eigen::Matrix3d& e, tf::Matrix3x3& t);
void poseTFToEigen(const tf::Pose& t, Eigen::Affine3d& e);
void poseTFToEigen(const tf::Pose& t, Eigen::Isometry3d& e);
void poseEigenToTF(const Eigen::Affine3d& e, tf::Pose& t);
void poseEigenToTF(const Eigen::Isometry3d& e, tf::Pose& t);
void poseMsgToEigen(const geometry_msgs::Pose& m, Eigen::Affine3d& e);
void poseMsgToEigen(const geometry_msgs::Pose& m, Eigen::Isometry3d& e);
void poseEigenToMsg(const Eigen::Affine3d& e, geometry_msgs::Pose& m);
void poseEigenToMsg(const Eigen::Isometry3d& e, geometry_msgs::Pose& m);
void quaternionTFToEigen(const tf::Quaternion& t, Eigen::Quaterniond& e);
void quaternionEigenToTF(const Eigen::Quaterniond& e, tf::Quaternion& t);
void quaternionMsgToEigen(const geometry_msgs::Quaternion& m, Eigen::Quaterniond& e);
void quaternionEigenToMsg(const Eigen::Quaterniond& e, geometry_msgs::Quaternion& m);
void transformTFToEigen(const tf::Transform& t, Eigen::Affine3d& e);
void transformTFToEigen(const tf::Transform& t, Eigen::Isometry3d& e);
void transformEigenToTF(const Eigen::Affine3d& e, tf::Transform& t);
void transformEigenToTF(const Eigen::Isometry3d& e, tf::Transform& t);
void transformMsgToEigen(const geometry_msgs::Transform& m, Eigen::Affine3d& e);
void transformMsgToEigen(const geometry_msgs::Transform& m, Eigen::Isometry3d& e);
void transformEigenToMsg(const Eigen::Affine3d& e, geometry_msgs::Transform& m);
void transformEigenToMsg(const Eigen::Isometry3d& e, geometry_msgs::Transform& m);
void twistMsgToEigen(const geometry_msgs::Twist& m, Eigen::Matrix<double, 6, 1>& e);
void twistEigenToMsg(const Eigen::Matrix<double, 6, 1>& e, geometry_msgs::Twist& m);
void vectorTFToEigen(const tf::Vector3& t, Eigen::Vector3d& e);
void vectorEigenToTF(const Eigen::Vector3d& e, tf::Vector3& t);
void vectorMsgToEigen(const geometry_msgs::Vector3& m, Eigen::Vector3d& e);
void vectorEigenToMsg(const Eigen::Vector3d& e, geometry_msgs::Vector3& m);
void pointMsgToEigen(const geometry_msgs::Point& m, Eigen::Vector3d& e);
void pointEigenToMsg(const Eigen::Vector3d& e, geometry_msgs::Point& m);
void wrenchMsgToEigen(const geometry_msgs::Wrench& m, Eigen::Matrix<double, 6, 1>& e);
void wrenchEigenToMsg(const Eigen::Matrix<double, 6, 1>& e, geometry_msgs::Wrench& m);
}  // namespace tf
#endif
