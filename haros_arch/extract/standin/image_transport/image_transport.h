// haros_arch stand-in: image_transport for ROS 1 and ROS 2 (declarations only)
#ifndef HAROS_STANDIN_IMAGE_TRANSPORT_H
#define HAROS_STANDIN_IMAGE_TRANSPORT_H
#include <string>
#include <memory>
#include <functional>
#include <boost/shared_ptr.hpp>
#include <boost/function.hpp>
namespace image_transport {
class SingleSubscriberPublisher;
typedef boost::function<void(const SingleSubscriberPublisher&)> SubscriberStatusCallback;
class Publisher {
public:
  Publisher();
  template<class M> void publish(const M& message) const;
  uint32_t getNumSubscribers() const;
  std::string getTopic() const;
  void shutdown();
  operator void*() const;
};
class Subscriber {
public:
  Subscriber();
  std::string getTopic() const;
  uint32_t getNumPublishers() const;
  std::string getTransport() const;
  void shutdown();
  operator void*() const;
};
class CameraPublisher {
public:
  CameraPublisher();
  // ROS 2: (node, base_topic, qos, options)
  template<class N, class... A> CameraPublisher(N&& node, const std::string& base_topic,
      const A&... more);
  template<class I, class C> void publish(const I& image, const C& info) const;
  // ROS 1: the image and info stamped with ``stamp`` first (non-const references)
  template<class I, class C, class T> void publish(I& image, C& info, T stamp) const;
  uint32_t getNumSubscribers() const;
  std::string getTopic() const;
  std::string getInfoTopic() const;
  void shutdown();
  operator void*() const;
};
class CameraSubscriber {
public:
  CameraSubscriber();
  // ROS 2: (node, base_topic, callback, transport, qos)
  template<class N, class C, class... A> CameraSubscriber(N&& node,
      const std::string& base_topic, const C& callback, const A&... more);
  std::string getTopic() const;
  std::string getInfoTopic() const;
  uint32_t getNumPublishers() const;
  void shutdown();
  operator void*() const;
};
// ROS 1 (default_transport, ros_hints, parameter_nh, parameter_name), ROS 2 (node,
// default_transport, parameter_name): each taken by value or const reference
class TransportHints {
public:
  template<class... A> explicit TransportHints(const A&... args);
  const std::string& getTransport() const;
};
class ImageTransport {
public:
  template<class N> explicit ImageTransport(const N& handle);
  Publisher advertise(const std::string& base_topic, uint32_t queue_size, bool latch = false);
  // the overloads with (dis)connect callbacks: roscpp's or image_transport's callback types
  template<class C, class... A> Publisher advertise(const std::string& base_topic,
      uint32_t queue_size, const C& connect_cb, const A&... more);
  template<class C> Subscriber subscribe(const std::string& base_topic, uint32_t queue_size,
      const C& callback);
  template<class C, class... A> Subscriber subscribe(const std::string& base_topic,
      uint32_t queue_size, const C& callback, const A&... more);
  CameraPublisher advertiseCamera(const std::string& base_topic, uint32_t queue_size,
      bool latch = false);
  template<class C, class... A> CameraPublisher advertiseCamera(const std::string& base_topic,
      uint32_t queue_size, const C& image_connect_cb, const A&... more);
  template<class C, class... A> CameraSubscriber subscribeCamera(const std::string& base_topic,
      uint32_t queue_size, const C& callback, const A&... more);
};
// a message_filters source (subscriber_filter.h / .hpp): ROS 1 (it, base_topic, queue_size,
// hints), ROS 2 (node, base_topic, transport, qos, options)
class SubscriberFilter {
public:
  SubscriberFilter();
  template<class N, class... A> SubscriberFilter(N&& node, const std::string& base_topic,
      const A&... more);
  template<class N, class... A> void subscribe(N&& node, const std::string& base_topic,
      const A&... more);
  void unsubscribe();
  std::string getTopic() const;
  uint32_t getNumPublishers() const;
  const Subscriber& getSubscriber() const;
  template<class C> void registerCallback(const C& callback);
};
// the camera_info topic beside an image topic (camera_common.h / .hpp)
std::string getCameraInfoTopic(const std::string& base_topic);
// the QoS profile and options that follow (rmw_qos_profile_t, PublisherOptions, ...)
template<class N, class... A> Publisher create_publisher(N node, const std::string& base_topic,
    const A&... qos_and_options);
template<class N, class C, class... A> Subscriber create_subscription(N node,
    const std::string& base_topic, const C& callback, const std::string& transport = "raw",
    const A&... qos_and_options);
template<class N, class... A> CameraPublisher create_camera_publisher(N node,
    const std::string& base_topic, const A&... qos_and_options);
template<class N, class C, class... A> CameraSubscriber create_camera_subscription(N node,
    const std::string& base_topic, const C& callback, const std::string& transport = "raw",
    const A&... qos_and_options);
}
#endif
