// haros_arch stand-in: laser_geometry's LaserProjection (ROS 2, declarations only), for a
// workspace that has the package installed, not as sources. It projects a LaserScan into
// a PointCloud2, transformed through the tf2 buffer it is handed: it makes no ROS call of
// its own. ROS 2's has no PointCloud (the first) and takes a tf2::BufferCore.
// The include guard is ROS 1's laser_geometry.h's: a unit has one LaserProjection, of the
// header it includes first.
#ifndef HAROS_STANDIN_LASER_GEOMETRY_H
#define HAROS_STANDIN_LASER_GEOMETRY_H
#include <string>
#include <sensor_msgs/msg/laser_scan.hpp>
#include <sensor_msgs/msg/point_cloud2.hpp>
#include <tf2/buffer_core.h>

namespace laser_geometry {
namespace channel_option {
enum ChannelOption {
  None = 0x00,
  Intensity = 0x01,
  Index = 0x02,
  Distance = 0x04,
  Timestamp = 0x08,
  Viewpoint = 0x10,
  Default = (Intensity | Index),
};
}  // namespace channel_option

class LaserProjection {
 public:
  LaserProjection();
  void projectLaser(const sensor_msgs::msg::LaserScan& scan_in,
                    sensor_msgs::msg::PointCloud2& cloud_out, double range_cutoff = -1.0,
                    int channel_options = channel_option::Default);
  void transformLaserScanToPointCloud(const std::string& target_frame,
                                      const sensor_msgs::msg::LaserScan& scan_in,
                                      sensor_msgs::msg::PointCloud2& cloud_out,
                                      tf2::BufferCore& tf, double range_cutoff = -1.0,
                                      int channel_options = channel_option::Default);
};
}  // namespace laser_geometry
#endif
