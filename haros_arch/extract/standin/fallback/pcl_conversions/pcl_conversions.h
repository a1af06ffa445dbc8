// haros_arch stand-in: perception_pcl's pcl_conversions (declarations only), for ROS 1
// (sensor_msgs::PointCloud2, std_msgs::Header, ros::Time) and ROS 2 (their ::msg:: types,
// rclcpp::Time) alike: the message side of every conversion is a template parameter, so
// this header includes no message header. Read only when the workspace has no
// pcl_conversions of its own.
#ifndef HAROS_STANDIN_PCL_CONVERSIONS
#define HAROS_STANDIN_PCL_CONVERSIONS
#include <pcl/point_cloud.h>
#include <pcl/PCLPointCloud2.h>

namespace pcl_conversions {
// the one-argument forms return the message side (ROS 1 ros::Time / std_msgs::Header,
// ROS 2 rclcpp::Time / std_msgs::msg::Header; std::uint64_t / pcl::PCLHeader the other
// way): a value that converts to what it initialises (hdl_graph_slam's ``ros::Time stamp
// = pcl_conversions::fromPCL(cloud->header.stamp);``)
struct haros_converted { template<class T> operator T() const; };
haros_converted fromPCL(const std::uint64_t& pcl_stamp);
haros_converted fromPCL(const pcl::PCLHeader& pcl_header);
template<class T> haros_converted toPCL(const T& value);
template<class Stamp> void fromPCL(const std::uint64_t& pcl_stamp, Stamp& stamp);
template<class Stamp> void toPCL(const Stamp& stamp, std::uint64_t& pcl_stamp);
template<class Header> void fromPCL(const pcl::PCLHeader& pcl_header, Header& header);
template<class Header> void toPCL(const Header& header, pcl::PCLHeader& pcl_header);
template<class Message> void fromPCL(const pcl::PCLPointCloud2& pcl_pc2, Message& pc2);
template<class Message> void toPCL(const Message& pc2, pcl::PCLPointCloud2& pcl_pc2);
template<class Message> void moveFromPCL(pcl::PCLPointCloud2& pcl_pc2, Message& pc2);
template<class Message> void moveToPCL(Message& pc2, pcl::PCLPointCloud2& pcl_pc2);
template<class Message> void fromPCL(const pcl::PointIndices& pcl_indices, Message& indices);
template<class Message> void toPCL(const Message& indices, pcl::PointIndices& pcl_indices);
template<class Message> void fromPCL(const pcl::ModelCoefficients& pcl_coefficients,
                                     Message& coefficients);
template<class Message> void toPCL(const Message& coefficients,
                                   pcl::ModelCoefficients& pcl_coefficients);
}  // namespace pcl_conversions

namespace pcl {
template<class PointT, class Message> void fromROSMsg(const Message& cloud,
                                                      pcl::PointCloud<PointT>& pcl_cloud);
template<class PointT, class Message> void moveFromROSMsg(Message& cloud,
                                                          pcl::PointCloud<PointT>& pcl_cloud);
template<class PointT, class Message> void toROSMsg(const pcl::PointCloud<PointT>& pcl_cloud,
                                                    Message& cloud);
template<class Message> void toROSMsg(const pcl::PCLPointCloud2& pcl_pc2, Message& cloud);
template<class Message> void fromROSMsg(const Message& cloud, pcl::PCLPointCloud2& pcl_pc2);
template<class PointT, class Message> void createMapping(const std::vector<Message>& fields,
                                                         std::vector<int>& field_map);
// a sensor_msgs PointCloud2's fields
template<class Message> int getFieldIndex(const Message& cloud, const std::string& field_name);
template<class Message> std::string getFieldsList(const Message& cloud);
template<class Message> bool concatenatePointCloud(const Message& cloud1, const Message& cloud2,
                                                   Message& cloud_out);
}  // namespace pcl
#endif
