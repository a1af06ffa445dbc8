// haros_arch stand-in: realtime_tools' publisher, ROS 1 and 2 (declarations only)
#ifndef HAROS_STANDIN_REALTIME_TOOLS_REALTIME_PUBLISHER_H
#define HAROS_STANDIN_REALTIME_TOOLS_REALTIME_PUBLISHER_H
#include <ros/ros.h>
#include <string>
namespace realtime_tools {
template <class Msg>
class RealtimePublisher {
public:
  Msg msg_;
  RealtimePublisher();
  RealtimePublisher(const ros::NodeHandle &node, const std::string &topic, int queue_size,
                    bool latched = false);
  // ROS 2: made on a publisher the node created before (that call is the publisher's)
  template <class Publisher> explicit RealtimePublisher(Publisher publisher);
  ~RealtimePublisher();
  bool tryPublish(const Msg &msg);
  void init(const ros::NodeHandle &node, const std::string &topic, int queue_size,
            bool latched = false);
  void stop();
  bool trylock();
  void lock();
  void unlock();
  void unlockAndPublish();
};
}  // namespace realtime_tools
#endif
