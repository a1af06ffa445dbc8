// haros_arch stand-in: ros::CallbackQueue
#ifndef HAROS_STANDIN_ROS_CALLBACK_QUEUE_H
#define HAROS_STANDIN_ROS_CALLBACK_QUEUE_H
#include <ros/forwards.h>
#include <ros/time.h>
namespace ros {
class CallbackQueueInterface {
public:
  virtual ~CallbackQueueInterface();
};
class CallbackQueue : public CallbackQueueInterface {
public:
  explicit CallbackQueue(bool enabled = true);
  void callAvailable();
  void callAvailable(WallDuration timeout);
  void callOne();
  void callOne(WallDuration timeout);
  bool empty();
  bool isEmpty();  // roscpp's other spelling of empty()
  bool isEnabled();
  void clear();
  void enable();
  void disable();
};
}  // namespace ros
#endif
