// haros_arch stand-in: sensor_msgs' point cloud iterators and modifier, ROS 2
#ifndef HAROS_STANDIN_SENSOR_MSGS_POINT_CLOUD2_ITERATOR_HPP
#define HAROS_STANDIN_SENSOR_MSGS_POINT_CLOUD2_ITERATOR_HPP
#include <sensor_msgs/msg/point_cloud2.hpp>
#define HAROS_PC2 msg::PointCloud2
#include "haros_point_cloud2.inc"
#undef HAROS_PC2
#endif
