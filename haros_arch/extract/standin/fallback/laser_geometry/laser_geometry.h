// haros_arch stand-in: laser_geometry's LaserProjection (ROS 1, declarations only), for a
// workspace that has the package installed, not as sources. It projects a LaserScan into
// a PointCloud or PointCloud2, transformed through the tf transformer or tf2 buffer it is
// handed: it makes no ROS call of its own.
#ifndef HAROS_STANDIN_LASER_GEOMETRY_H
#define HAROS_STANDIN_LASER_GEOMETRY_H
#include <string>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud.h>
#include <sensor_msgs/PointCloud2.h>

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
  ~LaserProjection();
  void projectLaser(const sensor_msgs::LaserScan& scan_in, sensor_msgs::PointCloud& cloud_out,
                    double range_cutoff = -1.0,
                    int channel_options = channel_option::Default);
  void projectLaser(const sensor_msgs::LaserScan& scan_in, sensor_msgs::PointCloud2& cloud_out,
                    double range_cutoff = -1.0,
                    int channel_options = channel_option::Default);
  // the target frame, the scan, then the cloud (PointCloud or PointCloud2), the
  // tf::Transformer or tf2::BufferCore and the range cut-off / channel options
  template<class... Rest>
  void transformLaserScanToPointCloud(const std::string& target_frame,
                                      const sensor_msgs::LaserScan& scan_in, Rest&&... rest);
};
}  // namespace laser_geometry
#endif
