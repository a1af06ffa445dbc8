// haros_arch stand-in: nodelet_topic_tools::NodeletLazy (declarations only). A nodelet
// that subscribes its inputs only while its outputs have subscribers: its subclasses
// use the handles nh_ / pnh_ its onInit() sets (api.HANDLE_MEMBERS) and publish through
// its advertise<T>(), an API row (api.LIBRARIES) that advertises on the handle given.
#ifndef HAROS_STANDIN_NODELET_TOPIC_TOOLS_NODELET_LAZY_H
#define HAROS_STANDIN_NODELET_TOPIC_TOOLS_NODELET_LAZY_H
#include <ros/ros.h>
#include <nodelet/nodelet.h>
#include <boost/shared_ptr.hpp>
#include <boost/thread.hpp>
#include <string>
#include <vector>
namespace nodelet_topic_tools {
enum ConnectionStatus { NOT_INITIALIZED, NOT_SUBSCRIBED, SUBSCRIBED };
template <class T> bool has_subscribers(const std::vector<T>& publishers);
class NodeletLazy : public nodelet::Nodelet {
public:
  NodeletLazy();
protected:
  virtual void onInit();
  virtual void onInitPostProcess();
  virtual void connectionCallback();
  virtual void warnNeverSubscribedCallback(const ros::WallTimerEvent& event);
  virtual void subscribe() = 0;
  virtual void unsubscribe() = 0;
  template <class T>
  ros::Publisher advertise(ros::NodeHandle& nh, const std::string& topic, int queue_size,
                           bool latch = false);
  virtual bool hasSubscribers() const;
  boost::mutex connection_mutex_;
  // set by onInit() to the node handle and the private node handle (api.HANDLE_MEMBERS)
  boost::shared_ptr<ros::NodeHandle> nh_;
  boost::shared_ptr<ros::NodeHandle> pnh_;
  std::vector<ros::Publisher> publishers_;
  ros::WallTimer timer_ever_subscribed_;
  bool ever_subscribed_;
  bool lazy_;
  ConnectionStatus connection_status_;
  bool verbose_connection_;
};
}  // namespace nodelet_topic_tools
#endif
