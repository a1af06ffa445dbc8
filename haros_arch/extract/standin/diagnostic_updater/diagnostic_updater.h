// haros_arch stand-in: diagnostic_updater (an Updater publishes /diagnostics)
#pragma once
#include <string>
#include <boost/function.hpp>
#include <ros/ros.h>

namespace diagnostic_updater {
class DiagnosticStatusWrapper {
public:
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
#ifdef HAROS_STANDIN_RCLCPP_HPP
  rclcpp::Duration getPeriod();  // ROS 2: a duration (robot_localization's nanoseconds())
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
class HeaderlessTopicDiagnostic {
public:
  HeaderlessTopicDiagnostic(std::string name, Updater& diag,
                            const FrequencyStatusParam& freq);
  void tick();
};
}  // namespace diagnostic_updater
