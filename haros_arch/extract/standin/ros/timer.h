// haros_arch stand-in: ros::Timer
#ifndef HAROS_STANDIN_ROS_TIMER_H
#define HAROS_STANDIN_ROS_TIMER_H
#include <ros/forwards.h>
#include <ros/time.h>
namespace ros {
struct TimerEvent {
  Time last_expected, last_real, current_expected, current_real;
};
typedef TimerEvent WallTimerEvent;
typedef TimerEvent SteadyTimerEvent;
typedef boost::function<void(const TimerEvent&)> TimerCallback;
class Timer {
public:
  Timer();
  void start();
  void stop();
  void setPeriod(const Duration& period, bool reset = true);
  bool hasPending();
  bool hasStarted() const;
  bool isValid();
  // as roscpp declares it: valid handles convert to a non-null void* (so
  // `if (pub)`, `nullptr == pub` and `bool ok = pub;` all compile)
  operator void*() const;
  bool operator<(const Timer& rhs) const;
  bool operator==(const Timer& rhs) const;
  bool operator!=(const Timer& rhs) const;
};
typedef Timer WallTimer;
typedef Timer SteadyTimer;
class CallbackQueueInterface;
// roscpp's timer_options.h (elevation_mapping's ``nodeHandle_.createTimer(timerOptions)``)
struct TimerOptions {
  TimerOptions();
  TimerOptions(Duration period, const TimerCallback& callback, CallbackQueueInterface* queue,
               bool oneshot = false, bool autostart = true);
  Duration period;
  TimerCallback callback;
  CallbackQueueInterface* callback_queue;
  bool oneshot;
  bool autostart;
};
}  // namespace ros
#endif
