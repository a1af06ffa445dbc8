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
// a filter's callbacks (registerCallback) are held by a Connection until it disconnects
class Connection {
public:
  Connection();
  template<class F> explicit Connection(const F& disconnect);
  void disconnect();
};
// a filter's message pointer, MConstPtr: boost's in ROS 1, std's in ROS 2, either here
template<class M> struct haros_filter_message {
  haros_filter_message();
  haros_filter_message(const boost::shared_ptr<const M>& message);
  haros_filter_message(const std::shared_ptr<const M>& message);
  haros_filter_message(const boost::shared_ptr<M>& message);
  haros_filter_message(const std::shared_ptr<M>& message);
  const M* operator->() const;
  const M& operator*() const;
  explicit operator bool() const;
  operator boost::shared_ptr<const M>() const;
  operator std::shared_ptr<const M>() const;
};
// what every filter with one output gives: callbacks on what it lets through; a filter
// of the node's own (a Subscriber's subclass) passes a message on with signalMessage
template<class M> class SimpleFilter {
public:
  typedef haros_filter_message<M> MConstPtr;
  template<class E> void signalMessage(const E& message);
  template<class C> Connection registerCallback(const C& callback);
  template<class C, class T> Connection registerCallback(const C& callback, T* object);
  // a member function of one parameter, picked among overloads by that form (jsk's
  // ``sub_input_.registerCallback(&Filter::filter, this)`` beside a two-input filter)
  template<class T, class P> Connection registerCallback(void (T::*callback)(P), T* object);
  const std::string& getName() const;
  void setName(const std::string& name);
};
// the base of every Subscriber: ROS 1's SubscriberBase, ROS 2's SubscriberBase<NodeType>
// (a class from Rolling's message_filters on), named below for the unit's ROS
class haros_subscriber_base {
public:
  virtual ~haros_subscriber_base();
  template<class N, class... A> void subscribe(N&& node, const std::string& topic, A&&... more);
  void subscribe();
  void unsubscribe();
};
template<class M, class NodeType = void> class Subscriber
    : public haros_subscriber_base, public SimpleFilter<M> {
public:
  typedef std::shared_ptr<NodeType> NodePtr;  // ROS 2's, for a subclass's constructors
  typedef typename SimpleFilter<M>::MConstPtr MConstPtr;
  Subscriber();
  template<class N, class... A> Subscriber(N&& node, const std::string& topic, A&&... more);
  template<class N, class... A> void subscribe(N&& node, const std::string& topic, A&&... more);
  void subscribe();  // again, to the topic it had (ROS 1's re-subscribe after unsubscribe)
  void unsubscribe();
  std::string getTopic() const;
  const haros_filter_subscription& getSubscriber() const;
  template<class C> Connection registerCallback(const C& callback);
  template<class C, class T> Connection registerCallback(const C& callback, T* object);
  // a member function of one parameter, picked among overloads by that form (jsk's
  // ``sub_input_.registerCallback(&Filter::filter, this)`` beside a two-input filter)
  template<class T, class P> Connection registerCallback(void (T::*callback)(P), T* object);
};
struct NullType {};
template<class P> class Synchronizer;
// a policy names its synchronizer, Sync (``std::make_shared<Policy::Sync>(10, a, b)``:
// the queue size converts to the policy, as the policies' constructors are not explicit)
namespace sync_policies {
template<class... M> struct ApproximateTime {
  typedef Synchronizer<ApproximateTime> Sync;
  ApproximateTime(uint32_t queue_size);
  void setMaxIntervalDuration(...);
  void setAgePenalty(double age_penalty);
  template<class D> void setInterMessageLowerBound(int index, const D& bound);
};
template<class... M> struct ExactTime {
  typedef Synchronizer<ExactTime> Sync;
  ExactTime(uint32_t queue_size);
  // the messages it drops unmatched (a Synchronizer of it derives it)
  template<class C> Connection registerDropCallback(const C& callback);
  template<class C, class T> Connection registerDropCallback(const C& callback, T* object);
};
}
template<class P> class Synchronizer {
public:
  template<class... F> Synchronizer(const P& policy, F&... filters);
  template<class... F> void connectInput(F&... filters);
  template<class C> Connection registerCallback(const C& callback);
  template<class C, class T> Connection registerCallback(const C& callback, T* object);
  template<class D> void setInterMessageLowerBound(int index, const D& bound);
  template<class D> void setInterMessageLowerBound(const D& bound);
  void setAgePenalty(double penalty);
  template<class D> void setMaxIntervalDuration(const D& duration);
  // ExactTime's, which a synchronizer of that policy derives (orca2's fp_node)
  template<class C> Connection registerDropCallback(const C& callback);
  template<class C, class T> Connection registerDropCallback(const C& callback, T* object);
  // the policy it was built with (Autoware's lane_select:
  // ``sync->getPolicy()->setMaxIntervalDuration(ros::Duration(0.1))``)
  P* getPolicy();
};
template<class... M> class TimeSynchronizer {
public:
  template<class... F> TimeSynchronizer(F&&... args);
  template<class... F> void connectInput(F&... filters);  // built with a queue size only
  template<class C> Connection registerCallback(const C& callback);
  template<class C, class T> Connection registerCallback(const C& callback, T* object);
  // a Synchronizer of the ExactTime policy
  template<class C> Connection registerDropCallback(const C& callback);
  template<class C, class T> Connection registerDropCallback(const C& callback, T* object);
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
  template<class C> Connection registerCallback(const C& callback);
};
}
#endif
// SubscriberBase is a class in ROS 1 and a template on the node type in ROS 2 until
// Rolling's message_filters (navigation2 tells them apart by rclcpp 29.6): declared
// here, outside the include guard, once the unit's ROS is known (HAROS_UNIT_ROS, from
// haros_ros1.h / haros_ros2.h, given to each unit after the precompiled stand-ins)
#if defined(HAROS_UNIT_ROS) && !defined(HAROS_STANDIN_MESSAGE_FILTERS_BASE)
#define HAROS_STANDIN_MESSAGE_FILTERS_BASE
namespace message_filters {
#if HAROS_UNIT_ROS == 2 && !(defined(RCLCPP_VERSION_MAJOR) && (RCLCPP_VERSION_MAJOR > 29 || \
    (RCLCPP_VERSION_MAJOR == 29 && RCLCPP_VERSION_MINOR >= 6)))
template<class NodeType = void> using SubscriberBase = haros_subscriber_base;
#else
using SubscriberBase = haros_subscriber_base;
#endif
}
#endif
