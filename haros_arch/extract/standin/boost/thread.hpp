// haros_arch stand-in: boost threads (declarations only)
#ifndef HAROS_STANDIN_BOOST_THREAD_HPP
#define HAROS_STANDIN_BOOST_THREAD_HPP
#include <string>
#include <boost/function.hpp>
namespace boost {
namespace posix_time {
struct time_duration {
  long total_seconds() const;
  long total_milliseconds() const;
  long total_microseconds() const;
  long total_nanoseconds() const;
  long ticks() const;
  static long ticks_per_second();
};
// classes, as boost's: a variable of one is a duration (``posix_time::seconds
// interval(period);``)
struct hours : time_duration { explicit hours(long n); };
struct minutes : time_duration { explicit minutes(long n); };
struct seconds : time_duration { explicit seconds(long n); };
struct milliseconds : time_duration { explicit milliseconds(long n); };
struct microseconds : time_duration { explicit microseconds(long n); };
// a point in time (ros::Time::toBoost gives one)
struct ptime {
  ptime();
  time_duration operator-(const ptime& other) const;
  bool operator<(const ptime& other) const;
  bool operator==(const ptime& other) const;
};
struct microsec_clock { static ptime local_time(); static ptime universal_time(); };
struct second_clock { static ptime local_time(); static ptime universal_time(); };
std::string to_iso_extended_string(const ptime& t);
std::string to_iso_string(const ptime& t);
std::string to_simple_string(const ptime& t);
}
class thread_interrupted { };  // what an interrupted thread's wait throws
class thread {
public:
  struct id_type { };
  thread();
  template<class F, class... A> explicit thread(F f, A... args);
  void join();
  template<class D> bool timed_join(const D& duration);
  void detach();
  bool joinable() const;
  void interrupt();
  static unsigned hardware_concurrency();
};
namespace this_thread {
void sleep(const posix_time::time_duration& d);
template<class D> void sleep_for(const D& d);
void yield();
void interruption_point();
thread::id_type get_id();
}
class thread_group {
public:
  template<class F> thread* create_thread(F f);
  void join_all();
  void add_thread(thread* t);
  void remove_thread(thread* t);
  bool is_this_thread_in();
  void interrupt_all();
  unsigned long size() const;
};
class mutex {
public:
  mutex(); void lock(); void unlock(); bool try_lock();
  class scoped_lock { public: explicit scoped_lock(mutex& m); void lock(); void unlock(); };
};
typedef mutex recursive_mutex;
typedef mutex timed_mutex;
class shared_mutex : public mutex { public: void lock_shared(); void unlock_shared(); };
template<class M> class lock_guard { public: explicit lock_guard(M& m); };
template<class M> class unique_lock { public: explicit unique_lock(M& m); void lock(); void unlock(); };
template<class M> class shared_lock { public: explicit shared_lock(M& m); };
template<class M> class upgrade_lock { public: explicit upgrade_lock(M& m); };
namespace detail { template<class M> struct scoped { explicit scoped(M& m); }; }
enum class cv_status { no_timeout, timeout };
class condition_variable {
public:
  void notify_one();
  void notify_all();
  template<class L> void wait(L& lock);
  template<class L, class D> bool timed_wait(L& lock, const D& d);
  template<class L, class P> void wait(L& lock, P predicate);
  // with a predicate, whether it holds; without, whether the time ran out (cv_status)
  template<class L, class D> cv_status wait_for(L& lock, const D& d);
  template<class L, class D, class P> bool wait_for(L& lock, const D& d, P predicate);
  template<class L, class T> cv_status wait_until(L& lock, const T& t);
  template<class L, class T, class P> bool wait_until(L& lock, const T& t, P predicate);
};
typedef condition_variable condition_variable_any;
}
#define BOOST_FOREACH(var, col) for (var : col)
#endif
