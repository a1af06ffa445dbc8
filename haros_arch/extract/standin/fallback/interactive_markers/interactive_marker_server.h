// haros_arch stand-in: ROS 1 interactive_markers' InteractiveMarkerServer (declarations
// only), for a workspace that has interactive_markers installed, not as sources. What it
// publishes and subscribes is said by its API row (extract/cpp/api.py).
#ifndef HAROS_STANDIN_INTERACTIVE_MARKERS_SERVER_H
#define HAROS_STANDIN_INTERACTIVE_MARKERS_SERVER_H
#include <string>
#include <vector>
#include <boost/function.hpp>
#include <ros/ros.h>
#include <std_msgs/Header.h>
#include <geometry_msgs/Pose.h>
#include <visualization_msgs/InteractiveMarker.h>
#include <visualization_msgs/InteractiveMarkerFeedback.h>
#include <visualization_msgs/InteractiveMarkerUpdate.h>
#include <visualization_msgs/InteractiveMarkerInit.h>

namespace interactive_markers {
class InteractiveMarkerServer {
 public:
  typedef visualization_msgs::InteractiveMarkerFeedbackConstPtr FeedbackConstPtr;
  typedef boost::function<void(const FeedbackConstPtr&)> FeedbackCallback;
  static const uint8_t DEFAULT_FEEDBACK_CB = 255;
  InteractiveMarkerServer(const std::string& topic_ns, const std::string& server_id = "",
                          bool spin_thread = false);
  ~InteractiveMarkerServer();
  void insert(const visualization_msgs::InteractiveMarker& int_marker);
  void insert(const visualization_msgs::InteractiveMarker& int_marker,
              FeedbackCallback feedback_cb, uint8_t feedback_type = DEFAULT_FEEDBACK_CB);
  bool setPose(const std::string& name, const geometry_msgs::Pose& pose,
               const std_msgs::Header& header = std_msgs::Header());
  bool erase(const std::string& name);
  void clear();
  bool empty() const;
  std::size_t size() const;
  bool setCallback(const std::string& name, FeedbackCallback feedback_cb,
                   uint8_t feedback_type = DEFAULT_FEEDBACK_CB);
  void applyChanges();
  bool get(std::string name, visualization_msgs::InteractiveMarker& int_marker) const;
  std::vector<std::string> getNames();
};
}  // namespace interactive_markers
#endif
