// haros_arch stand-in: sensor_msgs' point cloud iterators and modifier, ROS 1
#ifndef HAROS_STANDIN_SENSOR_MSGS_POINT_CLOUD2_ITERATOR_H
#define HAROS_STANDIN_SENSOR_MSGS_POINT_CLOUD2_ITERATOR_H
#include <sensor_msgs/PointCloud2.h>
#define HAROS_PC2 PointCloud2
#include "haros_point_cloud2.inc"
#undef HAROS_PC2
#endif
