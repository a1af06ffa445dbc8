// haros_arch stand-in: ros::Time, ros::Duration, ros::Rate
#ifndef HAROS_STANDIN_ROS_TIME_H
#define HAROS_STANDIN_ROS_TIME_H
#include <stdint.h>
// as rostime declares them: the conversions below return boost's types
namespace boost { namespace posix_time { struct ptime; struct time_duration; } }
namespace ros {
class Rate;
class Duration {
public:
  int32_t sec, nsec;
  Duration();
  explicit Duration(double t);
  Duration(int32_t s, int32_t n);
  explicit Duration(const Rate& r);  // one cycle of the rate (mavros' WallDuration(Rate(f)))
  static const Duration MIN, MAX, ZERO, DAY, HOUR, MINUTE, SECOND, MILLISECOND,
      MICROSECOND, NANOSECOND;
  Duration& fromSec(double t);
  Duration& fromNSec(int64_t t);
  double toSec() const;
  int64_t toNSec() const;
  boost::posix_time::time_duration toBoost() const;
  static Duration fromBoost(const boost::posix_time::time_duration& d);
  bool sleep() const;
  Duration operator+(const Duration& rhs) const;
  Duration operator-(const Duration& rhs) const;
  Duration operator*(double scale) const;
  bool operator<(const Duration& rhs) const;
  bool operator>(const Duration& rhs) const;
  bool operator<=(const Duration& rhs) const;
  bool operator>=(const Duration& rhs) const;
  bool operator==(const Duration& rhs) const;
  bool operator!=(const Duration& rhs) const;
  Duration operator-() const;
  Duration& operator+=(const Duration& rhs);
  Duration& operator-=(const Duration& rhs);
  Duration& operator*=(double scale);
  bool isZero() const;
};
typedef Duration WallDuration;
class Time {
public:
  uint32_t sec, nsec;
  Time();
  explicit Time(double t);
  Time(uint32_t s, uint32_t n);
  static Time now();
  static void init();
  static bool isValid();
  static bool waitForValid();
  static bool waitForValid(const WallDuration& timeout);  // false when it timed out
  static bool isSimTime();
  static bool isSystemTime();
  static bool sleepUntil(const Time& end);
  double toSec() const;
  uint64_t toNSec() const;
  bool isZero() const;
  bool is_zero() const;
  Time& fromSec(double t);
  Time& fromNSec(uint64_t t);
  boost::posix_time::ptime toBoost() const;
  static Time fromBoost(const boost::posix_time::ptime& t);
  Duration operator-(const Time& rhs) const;
  Time operator+(const Duration& rhs) const;
  Time operator-(const Duration& rhs) const;
  bool operator<(const Time& rhs) const;
  bool operator>(const Time& rhs) const;
  bool operator<=(const Time& rhs) const;
  bool operator>=(const Time& rhs) const;
  bool operator==(const Time& rhs) const;
  bool operator!=(const Time& rhs) const;
  Time& operator+=(const Duration& rhs);
  Time& operator-=(const Duration& rhs);
  static const Time MIN, MAX, ZERO, UNINITIALIZED;
};
typedef Time WallTime;
typedef Time SteadyTime;  // rostime's monotonic clock (Melodic and Noetic)
// rostime's bounds (``last_sync_(ros::TIME_MIN)``, novatel_gps_driver)
extern const Time TIME_MIN, TIME_MAX;
extern const Duration DURATION_MIN, DURATION_MAX;
class Rate {
public:
  Rate(double frequency);  // not explicit: createTimer(100, &C::f, this) is 100 Hz
  explicit Rate(const Duration& d);
  bool sleep();
  void reset();
  Duration cycleTime() const;
  Duration expectedCycleTime() const;
};
typedef Rate WallRate;
}  // namespace ros
#endif
