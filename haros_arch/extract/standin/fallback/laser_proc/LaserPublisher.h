// haros_arch stand-in: ROS 1 laser_proc's LaserPublisher (declarations only), for a
// workspace that has laser_proc installed, not as sources. What it publishes is said by
// the API row of LaserTransport::advertiseLaser (extract/cpp/api.py), which makes it.
#ifndef HAROS_STANDIN_LASER_PROC_LASER_PUBLISHER_H
#define HAROS_STANDIN_LASER_PROC_LASER_PUBLISHER_H
#include <string>
#include <vector>
#include <ros/ros.h>
#include <sensor_msgs/MultiEchoLaserScan.h>

namespace laser_proc {
class LaserPublisher {
 public:
  LaserPublisher();
  uint32_t getNumSubscribers() const;
  std::vector<std::string> getTopics() const;
  void publish(const sensor_msgs::MultiEchoLaserScan& msg) const;
  void publish(const sensor_msgs::MultiEchoLaserScanConstPtr& msg) const;
  void shutdown();
  operator void*() const;
};
}  // namespace laser_proc
#endif
