// haros_arch stand-in: ROS 1 laser_proc's LaserTransport (declarations only), for a
// workspace that has laser_proc installed, not as sources (urg_node's multi-echo scans).
#ifndef HAROS_STANDIN_LASER_PROC_LASER_TRANSPORT_H
#define HAROS_STANDIN_LASER_PROC_LASER_TRANSPORT_H
#include <laser_proc/LaserPublisher.h>

namespace laser_proc {
class LaserTransport {
 public:
  static LaserPublisher advertiseLaser(ros::NodeHandle& nh, uint32_t queue_size,
                                       bool latch = false);
  static LaserPublisher advertiseLaser(ros::NodeHandle& nh, uint32_t queue_size,
                                       const ros::SubscriberStatusCallback& connect_cb,
                                       const ros::SubscriberStatusCallback& disconnect_cb,
                                       const ros::VoidPtr& tracked_object, bool latch,
                                       bool publish_echoes = true);
};
}  // namespace laser_proc
#endif
