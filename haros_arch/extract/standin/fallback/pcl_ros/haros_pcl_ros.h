// haros_arch stand-in: perception_pcl's pcl_ros (declarations only): <pcl_ros/point_cloud.h>
// (in ROS 1, a pcl::PointCloud<T> is a message: sensor_msgs/PointCloud2 on the wire) and
// <pcl_ros/transforms.h> / <pcl_ros/transforms.hpp> (ROS 1 tf, ROS 2 tf2: the transform,
// listener or buffer and the message are template parameters). Every <pcl_ros/...> header
// the workspace does not have stands in as this file.
#ifndef HAROS_STANDIN_PCL_ROS
#define HAROS_STANDIN_PCL_ROS
#include <string>
#include <pcl/point_cloud.h>
#include <pcl_conversions/pcl_conversions.h>

namespace pcl_ros {
// a cloud (or a sensor_msgs PointCloud2) through a transform
template<class Cloud, class Transform> void transformPointCloud(
    const Cloud& cloud_in, Cloud& cloud_out, const Transform& transform);
// the cloud through a transform (tf::Transform, geometry_msgs TransformStamped, Eigen)
template<class PointT, class Transform> void transformPointCloud(
    const pcl::PointCloud<PointT>& cloud_in, pcl::PointCloud<PointT>& cloud_out,
    const Transform& transform);
// the cloud into ``target_frame`` with a tf listener / tf2 buffer
template<class Cloud, class Listener> bool transformPointCloud(
    const std::string& target_frame, const Cloud& cloud_in, Cloud& cloud_out,
    const Listener& tf_listener);
template<class Cloud, class Time, class Listener> bool transformPointCloud(
    const std::string& target_frame, const Time& target_time, const Cloud& cloud_in,
    const std::string& fixed_frame, Cloud& cloud_out, const Listener& tf_listener);
// a sensor_msgs PointCloud2 through a 4x4 matrix
template<class Message> void transformPointCloud(const Eigen::Matrix4f& transform,
                                                 const Message& in, Message& out);
template<class Transform> void transformAsMatrix(const Transform& transform,
                                                 Eigen::Matrix4f& out_mat);
template<class Transform> Eigen::Matrix4f transformAsMatrix(const Transform& transform);
}  // namespace pcl_ros
#endif
