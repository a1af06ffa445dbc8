// haros_arch stand-in: diagnostic_updater (an Updater publishes /diagnostics)
#pragma once
#include <string>
#include <boost/function.hpp>
#include <ros/ros.h>

namespace diagnostic_updater {
class DiagnosticStatusWrapper {
public:
  // the levels of diagnostic_msgs' DiagnosticStatus, its base
  static const unsigned char OK = 0;
  static const unsigned char WARN = 1;
  static const unsigned char ERROR = 2;
  static const unsigned char STALE = 3;
  std::string name, message, hardware_id;
  unsigned char level;
  void summary(unsigned char level, const std::string& message);
  void summaryf(unsigned char level, const char* format, ...);
  void mergeSummary(unsigned char level, const std::string& message);
  void mergeSummaryf(unsigned char level, const char* format, ...);
  void clearSummary();
  void clear();
  template<class T> void add(const std::string& key, const T& value);
  void addf(const std::string& key, const char* format, ...);
};
typedef boost::function<void(DiagnosticStatusWrapper&)> TaskFunction;
class DiagnosticTask {
public:
  explicit DiagnosticTask(const std::string& name);
  virtual ~DiagnosticTask();
  const std::string& getName();
  virtual void run(DiagnosticStatusWrapper& stat) = 0;
};
// a task of a function (a bound method): what a composite task adds (guardian_sim's
// ``subs_command_freq->addTask(&command_freq_)``)
template<class T>
class GenericFunctionDiagnosticTask : public DiagnosticTask {
public:
  GenericFunctionDiagnosticTask(const std::string& name, boost::function<void(T&)> fn);
  void run(DiagnosticStatusWrapper& stat);
};
typedef GenericFunctionDiagnosticTask<DiagnosticStatusWrapper> FunctionDiagnosticTask;
class Updater {
public:
  Updater();
  explicit Updater(ros::NodeHandle h, ros::NodeHandle ph = ros::NodeHandle("~"),
                   std::string node_name = std::string());
  // ROS 2: Updater(node, period) with an rclcpp node (or its interfaces)
  template<class N> explicit Updater(N node, double period = 1.0);
  void setHardwareID(const std::string& id);
  void setHardwareIDf(const char* format, ...);
  template<class T> void add(const std::string& name, T* object,
                             void (T::*method)(DiagnosticStatusWrapper&));
  void add(const std::string& name, TaskFunction f);
  void add(DiagnosticTask& task);
  bool removeByName(const std::string& name);
  void update();
  void force_update();
  void broadcast(int level, const std::string& message);
  // ROS 1: seconds (ros_canopen's ``ros::Duration(updater.getPeriod() / 2.0)``); ROS 2:
  // a duration (robot_localization's ``nanoseconds()``). rclcpp is precompiled into every
  // unit, so the unit's own ROS (HAROS_UNIT_ROS, given to it after the precompiled
  // stand-ins) chooses, not whether rclcpp is there.
#if defined(HAROS_UNIT_ROS) && HAROS_UNIT_ROS == 1
  double getPeriod();
#elif defined(HAROS_STANDIN_RCLCPP_HPP)
  rclcpp::Duration getPeriod();
#else
  double getPeriod();
#endif
  template<class D> void setPeriod(D period);  // seconds, or an rclcpp::Duration
};
struct FrequencyStatusParam {
  FrequencyStatusParam(double* min_freq, double* max_freq, double tolerance = 0.1,
                       int window_size = 5);
};
struct TimeStampStatusParam {
  TimeStampStatusParam(double min_acceptable = -1, double max_acceptable = 5);
};
class FrequencyStatus : public DiagnosticTask {
public:
  explicit FrequencyStatus(const FrequencyStatusParam& params);
  void tick();
  void clear();
  void run(DiagnosticStatusWrapper& stat);
};
class TimeStampStatus : public DiagnosticTask {
public:
  TimeStampStatus();
  explicit TimeStampStatus(const TimeStampStatusParam& params);
  template<class T> void tick(const T& stamp);  // a ros::Time, rclcpp::Time or double
  void run(DiagnosticStatusWrapper& stat);
};
class CompositeDiagnosticTask : public DiagnosticTask {
public:
  explicit CompositeDiagnosticTask(const std::string& name);
  void addTask(DiagnosticTask* task);
  void run(DiagnosticStatusWrapper& stat);
};
class HeaderlessTopicDiagnostic : public CompositeDiagnosticTask {
public:
  // ROS 2 takes a clock last
  template<class... C>
  HeaderlessTopicDiagnostic(std::string name, Updater& diag,
                            const FrequencyStatusParam& freq, C&&... clock);
  void tick();
  void clear_window();
};
class TopicDiagnostic : public HeaderlessTopicDiagnostic {
public:
  template<class... C>
  TopicDiagnostic(std::string name, Updater& diag, const FrequencyStatusParam& freq,
                  const TimeStampStatusParam& stamp, C&&... clock);
  template<class T> void tick(const T& stamp);
};
// a publisher whose publish() ticks a TopicDiagnostic: the publisher it wraps is the
// ROS call (made where it is advertised)
template<class T>
class DiagnosedPublisher : public TopicDiagnostic {
public:
  template<class P>
  DiagnosedPublisher(const P& pub, Updater& diag, const FrequencyStatusParam& freq,
                     const TimeStampStatusParam& stamp);
  template<class M> void publish(const M& message);
};
}  // namespace diagnostic_updater
