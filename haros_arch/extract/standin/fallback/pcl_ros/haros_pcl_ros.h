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
#if HAROS_UNIT_ROS == 1
// <pcl_ros/pcl_nodelet.h> (ROS 1; written from perception_pcl 2f70209f): the base of PCL's
// nodelets and of those that derive from it (jsk_pcl_ros'), a NodeletLazy, whose nh_ and
// pnh_ its onInit() sets (api.HANDLE_MEMBERS) and whose onInit() reads four private
// parameters after the NodeletLazy's (an API row, api.PCL_ROS)
#include <vector>
#include <boost/shared_ptr.hpp>
#include <nodelet_topic_tools/nodelet_lazy.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf/transform_listener.h>
namespace pcl_ros {
class PCLNodelet : public nodelet_topic_tools::NodeletLazy {
public:
  typedef sensor_msgs::PointCloud2 PointCloud2;
  typedef pcl::PointCloud<pcl::PointXYZ> PointCloud;
  typedef PointCloud::Ptr PointCloudPtr;
  typedef PointCloud::ConstPtr PointCloudConstPtr;
  // (pcl_msgs' PointIndices and ModelCoefficients in ROS 1: the PCL structs here)
  typedef pcl::PointIndices PointIndices;
  typedef PointIndices::Ptr PointIndicesPtr;
  typedef PointIndices::ConstPtr PointIndicesConstPtr;
  typedef pcl::ModelCoefficients ModelCoefficients;
  typedef ModelCoefficients::Ptr ModelCoefficientsPtr;
  typedef ModelCoefficients::ConstPtr ModelCoefficientsConstPtr;
  typedef boost::shared_ptr<std::vector<int> > IndicesPtr;
  typedef boost::shared_ptr<const std::vector<int> > IndicesConstPtr;
  PCLNodelet();
protected:
  bool use_indices_;
  bool latched_indices_;
  ros::Publisher pub_output_;
  int max_queue_size_;
  bool approximate_sync_;
  tf::TransformListener tf_listener_;
  bool isValid(const PointCloud2::ConstPtr& cloud, const std::string& topic_name = "input");
  bool isValid(const PointCloudConstPtr& cloud, const std::string& topic_name = "input");
  bool isValid(const PointIndicesConstPtr& indices, const std::string& topic_name = "indices");
  bool isValid(const ModelCoefficientsConstPtr& model,
               const std::string& topic_name = "model");
  virtual void subscribe() {}
  virtual void unsubscribe() {}
  virtual void onInit();
};
}  // namespace pcl_ros
#endif
#endif
