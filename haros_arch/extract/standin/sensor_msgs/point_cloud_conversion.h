// haros_arch stand-in: ROS 1 sensor_msgs' conversions between PointCloud and PointCloud2
// (declarations only; no ROS call): costmap_2d's obstacle layer converts its clouds so
#ifndef HAROS_STANDIN_SENSOR_MSGS_POINT_CLOUD_CONVERSION_H
#define HAROS_STANDIN_SENSOR_MSGS_POINT_CLOUD_CONVERSION_H
#include <string>
#include <sensor_msgs/PointCloud.h>
#include <sensor_msgs/PointCloud2.h>
namespace sensor_msgs {
int getPointCloud2FieldIndex(const sensor_msgs::PointCloud2& cloud,
                             const std::string& field_name);
bool convertPointCloudToPointCloud2(const sensor_msgs::PointCloud& input,
                                    sensor_msgs::PointCloud2& output);
bool convertPointCloud2ToPointCloud(const sensor_msgs::PointCloud2& input,
                                    sensor_msgs::PointCloud& output);
}  // namespace sensor_msgs
#endif
