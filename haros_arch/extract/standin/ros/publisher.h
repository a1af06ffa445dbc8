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
  // as roscpp declares it: valid handles convert to a non-null void* (so
  // `if (pub)`, `nullptr == pub` and `bool ok = pub;` all compile)
  operator void*() const;
  bool operator<(const Publisher& rhs) const;
  bool operator==(const Publisher& rhs) const;
  bool operator!=(const Publisher& rhs) const;
};
class Subscriber {
public:
  Subscriber();
  void shutdown();
  std::string getTopic() const;
  uint32_t getNumPublishers() const;
  // as roscpp declares it: valid handles convert to a non-null void* (so
  // `if (pub)`, `nullptr == pub` and `bool ok = pub;` all compile)
  operator void*() const;
  bool operator<(const Subscriber& rhs) const;
  bool operator==(const Subscriber& rhs) const;
  bool operator!=(const Subscriber& rhs) const;
};
}  // namespace ros
#endif
