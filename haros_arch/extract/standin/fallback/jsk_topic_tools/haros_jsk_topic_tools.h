// haros_arch stand-in: the nodelet bases of jsk_common's jsk_topic_tools (ROS 1), for the
// nodelets of jsk_recognition and the like where the package is installed, not in the
// workspace (every jsk_topic_tools/... header stands in as this one,
// headers.FALLBACK_UMBRELLAS). Written from jsk_common bfa8d0db's headers and sources:
// ConnectionBasedNodelet::onInit makes the node's handles (nh_ the nodelet's, pnh_ its
// private one) and reads three private parameters; DiagnosticNodelet::onInit runs it, then
// publishes diagnostics and reads ``~vital_rate`` and ``~use_warn``; ``advertise<T>(nh,
// topic, queue)`` and its image and camera forms advertise on the handle given, after
// reading ``latch`` there. Their bodies here make the same calls, so a nodelet that runs
// them (``DiagnosticNodelet::onInit()``) makes them too.
#ifndef HAROS_STANDIN_JSK_TOPIC_TOOLS_H
#define HAROS_STANDIN_JSK_TOPIC_TOOLS_H
#include <string>
#include <vector>
#include <boost/shared_ptr.hpp>
#include <boost/thread.hpp>
#include <ros/ros.h>
#include <nodelet/nodelet.h>
#include <image_transport/image_transport.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <std_msgs/ColorRGBA.h>

namespace jsk_topic_tools {

enum ConnectionStatus { NOT_INITIALIZED, NOT_SUBSCRIBED, SUBSCRIBED };

// vital_checker.h: whether a topic is still alive (no ROS call)
class VitalChecker {
public:
  typedef boost::shared_ptr<VitalChecker> Ptr;
  VitalChecker(const double dead_sec);
  void poke();
  double lastAliveTimeRelative();
  bool isAlive();
  double deadSec();
};

// timered_diagnostic_updater.h: a diagnostic updater on the handle given, run by a timer
class TimeredDiagnosticUpdater {
public:
  typedef boost::shared_ptr<TimeredDiagnosticUpdater> Ptr;
  TimeredDiagnosticUpdater(ros::NodeHandle& nh, const ros::Duration& timer_duration)
      : diagnostic_updater_(new diagnostic_updater::Updater) {}
  void start();
  void setHardwareID(const std::string& name);
  void add(const std::string& name, diagnostic_updater::TaskFunction f);
  void add(diagnostic_updater::DiagnosticTask& task);
  void update();
protected:
  boost::shared_ptr<diagnostic_updater::Updater> diagnostic_updater_;
};

// connection_based_nodelet.h
class ConnectionBasedNodelet : public nodelet::Nodelet {
public:
  ConnectionBasedNodelet() : subscribed_(false) {}
protected:
  virtual void onInit() {
    bool use_multithread;
    ros::param::param<bool>("~use_multithread_callback", use_multithread, true);
    nh_.reset(new ros::NodeHandle(getNodeHandle()));
    pnh_.reset(new ros::NodeHandle(getPrivateNodeHandle()));
    pnh_->param("always_subscribe", always_subscribe_, false);
    pnh_->param("verbose_connection", verbose_connection_, false);
    pnh_->param("no_warn_on_init_post_process", on_init_post_process_called_, false);
  }
  virtual void onInitPostProcess();
  virtual void connectionCallback(const ros::SingleSubscriberPublisher& pub);
  virtual void imageConnectionCallback(const image_transport::SingleSubscriberPublisher& pub);
  virtual void cameraConnectionCallback(const image_transport::SingleSubscriberPublisher& pub);
  virtual void cameraInfoConnectionCallback(const ros::SingleSubscriberPublisher& pub);
  virtual void cameraConnectionBaseCallback();
  virtual void subscribe() = 0;
  virtual void unsubscribe() = 0;
  virtual bool isSubscribed();
  virtual bool warnNoRemap(const std::vector<std::string> names);
  template<class T> ros::Publisher advertise(ros::NodeHandle& nh, std::string topic,
                                             int queue_size) {
    bool latch;
    nh.param("latch", latch, false);
    return nh.advertise<T>(topic, queue_size, latch);
  }
  template<class T> ros::Publisher advertise(ros::NodeHandle& nh, std::string topic,
                                             int queue_size, bool latch) {
    return nh.advertise<T>(topic, queue_size, latch);
  }
  image_transport::Publisher advertiseImage(ros::NodeHandle& nh, const std::string& topic,
                                            int queue_size) {
    bool latch;
    nh.param("latch", latch, false);
    return image_transport::ImageTransport(nh).advertise(topic, 1, latch);
  }
  image_transport::CameraPublisher advertiseCamera(ros::NodeHandle& nh,
                                                   const std::string& topic,
                                                   int queue_size) {
    bool latch;
    nh.param("latch", latch, false);
    return image_transport::ImageTransport(nh).advertiseCamera(topic, 1, latch);
  }
  boost::mutex connection_mutex_;
  std::vector<ros::Publisher> publishers_;
  std::vector<image_transport::Publisher> image_publishers_;
  std::vector<image_transport::CameraPublisher> camera_publishers_;
  boost::shared_ptr<ros::NodeHandle> nh_;
  boost::shared_ptr<ros::NodeHandle> pnh_;
  ros::WallTimer timer_warn_never_subscribed_;
  bool subscribed_;
  bool ever_subscribed_;
  bool always_subscribe_;
  ConnectionStatus connection_status_;
  bool verbose_connection_;
  bool on_init_post_process_called_;
  ros::WallTimer timer_warn_on_init_post_process_called_;
};

// diagnostic_nodelet.h
class DiagnosticNodelet : public ConnectionBasedNodelet {
public:
  typedef boost::shared_ptr<DiagnosticNodelet> Ptr;
  DiagnosticNodelet();
  DiagnosticNodelet(const std::string& name) : name_(name) {}
protected:
  virtual void onInit() {
    ConnectionBasedNodelet::onInit();
    diagnostic_updater_.reset(new TimeredDiagnosticUpdater(*pnh_, ros::Duration(1.0)));
    bool use_warn;
    nh_->param("/diagnostic_nodelet/use_warn", use_warn, false);
    if (pnh_->hasParam("use_warn")) {
      pnh_->getParam("use_warn", use_warn);
    }
    double vital_rate;
    pnh_->param("vital_rate", vital_rate, 1.0);
    vital_checker_.reset(new VitalChecker(1 / vital_rate));
  }
  virtual void updateDiagnostic(diagnostic_updater::DiagnosticStatusWrapper& stat);
  const std::string name_;
  TimeredDiagnosticUpdater::Ptr diagnostic_updater_;
  VitalChecker::Ptr vital_checker_;
  uint8_t diagnostic_error_level_;
  ConnectionStatus previous_checked_connection_status_;
};

// rosparam_utils.h: a parameter read on the handle given (an API row)
bool readVectorParameter(ros::NodeHandle& nh, const std::string& param_name,
                         std::vector<double>& result);
bool readVectorParameter(ros::NodeHandle& nh, const std::string& param_name,
                         std::vector<std::vector<double> >& result);
bool readVectorParameter(ros::NodeHandle& nh, const std::string& param_name,
                         std::vector<std::string>& result);
bool readVectorParameter(ros::NodeHandle& nh, const std::string& param_name,
                         std::vector<std::vector<std::string> >& result);
double getXMLDoubleValue(XmlRpc::XmlRpcValue val);
// log_utils.h: whether the names were remapped (ros::names' remappings, no call)
bool warnNoRemap(const std::vector<std::string> names);

// diagnostic_utils.h, color_utils.h, time_accumulator.h: no ROS call
void addDiagnosticInformation(const std::string& string_prefix,
                              class TimeAccumulator& accumulator,
                              diagnostic_updater::DiagnosticStatusWrapper& stat);
void addDiagnosticErrorSummary(const std::string& string_prefix,
                               VitalChecker::Ptr vital_checker,
                               diagnostic_updater::DiagnosticStatusWrapper& stat,
                               const unsigned int error_level);
void addDiagnosticBooleanStat(const std::string& string_prefix, const bool value,
                              diagnostic_updater::DiagnosticStatusWrapper& stat,
                              const unsigned int error_level);
std_msgs::ColorRGBA colorCategory20(int i);
std_msgs::ColorRGBA heatColor(double v);
class ScopedTimer {
public:
  ScopedTimer(class TimeAccumulator* parent);
  ~ScopedTimer();
};
class TimeAccumulator {
public:
  TimeAccumulator();
  ScopedTimer scopedTimer();
  void registerTime(double time);
  double mean();
  double min();
  double max();
  double count();
  double variance();
  void reset();
};
}  // namespace jsk_topic_tools

#define JSK_ROS_DEBUG(...) ROS_DEBUG(__VA_ARGS__)
#define JSK_ROS_INFO(...) ROS_INFO(__VA_ARGS__)
#define JSK_ROS_WARN(...) ROS_WARN(__VA_ARGS__)
#define JSK_ROS_ERROR(...) ROS_ERROR(__VA_ARGS__)
#define JSK_ROS_FATAL(...) ROS_FATAL(__VA_ARGS__)
#define JSK_NODELET_DEBUG(...) NODELET_DEBUG(__VA_ARGS__)
#define JSK_NODELET_INFO(...) NODELET_INFO(__VA_ARGS__)
#define JSK_NODELET_WARN(...) NODELET_WARN(__VA_ARGS__)
#define JSK_NODELET_ERROR(...) NODELET_ERROR(__VA_ARGS__)
#define JSK_NODELET_FATAL(...) NODELET_FATAL(__VA_ARGS__)
#define JSK_NODELET_DEBUG_THROTTLE(r, ...) NODELET_DEBUG_THROTTLE(r, __VA_ARGS__)
#define JSK_NODELET_INFO_THROTTLE(r, ...) NODELET_INFO_THROTTLE(r, __VA_ARGS__)
#define JSK_NODELET_WARN_THROTTLE(r, ...) NODELET_WARN_THROTTLE(r, __VA_ARGS__)
#define JSK_NODELET_ERROR_THROTTLE(r, ...) NODELET_ERROR_THROTTLE(r, __VA_ARGS__)
#endif
