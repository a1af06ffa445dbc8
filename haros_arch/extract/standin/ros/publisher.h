// haros_arch stand-in: ros::Publisher and ros::Subscriber
#ifndef HAROS_STANDIN_ROS_PUBLISHER_H
#define HAROS_STANDIN_ROS_PUBLISHER_H
#include <ros/forwards.h>
namespace ros {
class Publisher {
public:
  Publisher();
  template<class M> void publish(const M& message) const;
  template<class M> void publish(const boost::shared_ptr<M>& message) const;
  void shutdown();
  std::string getTopic() const;
  uint32_t getNumSubscribers() const;
  bool isLatched() const;
  explicit operator bool() const;
};
class Subscriber {
public:
  Subscriber();
  void shutdown();
  std::string getTopic() const;
  uint32_t getNumPublishers() const;
  explicit operator bool() const;
};
}  // namespace ros
#endif
