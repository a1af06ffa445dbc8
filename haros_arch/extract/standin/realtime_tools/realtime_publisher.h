// haros_arch stand-in: realtime_tools, ROS 1 and 2 (declarations only): the publisher, the
// buffers, boxes and queues controllers keep their commands in, the mutexes. Every other
// realtime_tools header stands in as this one (headers.UMBRELLAS).
#ifndef HAROS_STANDIN_REALTIME_TOOLS_REALTIME_PUBLISHER_H
#define HAROS_STANDIN_REALTIME_TOOLS_REALTIME_PUBLISHER_H
#include <ros/ros.h>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
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
  bool try_publish(const Msg &msg);
  bool can_publish() const;
  void init(const ros::NodeHandle &node, const std::string &topic, int queue_size,
            bool latched = false);
  void stop();
  bool trylock();
  void lock();
  void unlock();
  void unlockAndPublish();
};
template <class Msg> using RealtimePublisherSharedPtr = std::shared_ptr<RealtimePublisher<Msg>>;
// a value written outside the control loop and read inside it
template <class T>
class RealtimeBuffer {
public:
  RealtimeBuffer();
  explicit RealtimeBuffer(const T &data);
  RealtimeBuffer(const RealtimeBuffer &source);
  RealtimeBuffer &operator=(const RealtimeBuffer &source);
  T *readFromRT();
  T *readFromNonRT() const;
  void writeFromNonRT(const T &data);
  void initRT(const T &data);
  void reset();
};
using prio_inherit_mutex = std::mutex;
using prio_inherit_recursive_mutex = std::recursive_mutex;
// a value shared under a lock (RealtimeBox in ROS 1 and Humble, RealtimeThreadSafeBox later)
template <class T, class Mutex = std::mutex>
class RealtimeThreadSafeBox {
public:
  using mutex_t = Mutex;
  using type = T;
  explicit RealtimeThreadSafeBox(const T &init = T());
  RealtimeThreadSafeBox(const RealtimeThreadSafeBox &other);
  RealtimeThreadSafeBox &operator=(const RealtimeThreadSafeBox &other);
  bool try_set(const T &value);
  bool try_set(const std::function<void(T &)> &func);
  bool trySet(const T &value);
  std::optional<T> try_get() const;
  bool try_get(const std::function<void(const T &)> &func);
  bool tryGet(const std::function<void(const T &)> &func);
  void set(const T &value);
  void set(const std::function<void(T &)> &func);
  T get() const;
  void get(T &out) const;
  void get(const std::function<void(const T &)> &func);
  mutex_t &get_mutex();
};
template <class T, class Mutex = std::mutex> using RealtimeBox = RealtimeThreadSafeBox<T, Mutex>;
// lock-free queues between the control loop and the rest
template <class T, std::size_t Capacity = 0>
class LockFreeSPSCQueue {
public:
  LockFreeSPSCQueue();
  explicit LockFreeSPSCQueue(std::size_t capacity);
  bool pop(T &data);
  template <class U> bool pop(U &data);
  template <class U> bool push(const U &data);
  template <class U> bool bounded_push(const U &data);
  bool get_latest(T &data);
  bool empty() const;
  std::size_t capacity() const;
  std::size_t size() const;
  bool is_lock_free() const;
};
template <class T, std::size_t Capacity = 0, bool FixedSize = true>
class LockFreeMPMCQueue : public LockFreeSPSCQueue<T, Capacity> {
public:
  LockFreeMPMCQueue();
  explicit LockFreeMPMCQueue(std::size_t capacity);
};
}  // namespace realtime_tools
#endif
