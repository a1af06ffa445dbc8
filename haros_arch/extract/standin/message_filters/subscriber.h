// haros_arch stand-in: message_filters (declarations only)
#ifndef HAROS_STANDIN_MESSAGE_FILTERS_H
#define HAROS_STANDIN_MESSAGE_FILTERS_H
#include <string>
#include <memory>
#include <functional>
#include <boost/shared_ptr.hpp>
#include <boost/function.hpp>
namespace ros { class Subscriber; }
namespace message_filters {
// getSubscriber(): ROS 1 gives the ros::Subscriber, ROS 2 the rclcpp subscription's
// shared pointer; one stand-in answers both uses (sub.getSubscriber().getTopic(),
// sub.getSubscriber()->get_topic_name())
struct haros_filter_subscription {
  const haros_filter_subscription* operator->() const;
  operator const ros::Subscriber&() const;
  explicit operator bool() const;
  std::string getTopic() const;
  uint32_t getNumPublishers() const;
  const char* get_topic_name() const;
  size_t get_publisher_count() const;
};
template<class M, class NodeType = void> class Subscriber {
public:
  Subscriber();
  template<class N, class... A> Subscriber(N&& node, const std::string& topic, A&&... more);
  template<class N, class... A> void subscribe(N&& node, const std::string& topic, A&&... more);
  void unsubscribe();
  std::string getTopic() const;
  const haros_filter_subscription& getSubscriber() const;
  template<class C> void registerCallback(const C& callback);
  template<class C, class T> void registerCallback(const C& callback, T* object);
};
struct NullType {};
namespace sync_policies {
template<class... M> struct ApproximateTime { explicit ApproximateTime(uint32_t queue_size); void setMaxIntervalDuration(...); };
template<class... M> struct ExactTime { explicit ExactTime(uint32_t queue_size); };
}
template<class P> class Synchronizer {
public:
  template<class... F> Synchronizer(const P& policy, F&... filters);
  template<class... F> void connectInput(F&... filters);
  template<class C> void registerCallback(const C& callback);
  template<class C, class T> void registerCallback(const C& callback, T* object);
  template<class D> void setInterMessageLowerBound(int index, const D& bound);
  template<class D> void setInterMessageLowerBound(const D& bound);
  void setAgePenalty(double penalty);
  template<class D> void setMaxIntervalDuration(const D& duration);
};
template<class... M> class TimeSynchronizer {
public:
  template<class... F> TimeSynchronizer(F&&... args);
  template<class... F> void connectInput(F&... filters);  // built with a queue size only
  template<class C> void registerCallback(const C& callback);
  template<class C, class T> void registerCallback(const C& callback, T* object);
};
// what a Cache gives: a message pointer of either ROS (ROS 1 boost, ROS 2 std), a time
// of either (``toSec()`` / ``seconds()``)
template<class M> struct haros_cached_message {
  const M* operator->() const;
  const M& operator*() const;
  explicit operator bool() const;
  operator boost::shared_ptr<const M>() const;
  operator std::shared_ptr<const M>() const;
};
struct haros_cached_time {
  double toSec() const;
  unsigned long long toNSec() const;
  double seconds() const;
  long long nanoseconds() const;
  bool isZero() const;
  template<class T> operator T() const;
};
template<class M> class Cache {
public:
  Cache(unsigned int size = 1);
  template<class F> Cache(F& filter, unsigned int size = 1);
  template<class F> void connectInput(F& filter);
  void setCacheSize(unsigned int size);
  template<class T> haros_cached_message<M> getElemBeforeTime(const T& time) const;
  template<class T> haros_cached_message<M> getElemAfterTime(const T& time) const;
  haros_cached_time getLatestTime() const;
  haros_cached_time getOldestTime() const;
  template<class C> void registerCallback(const C& callback);
};
}
#endif
