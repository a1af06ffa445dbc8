// haros_arch stand-in: ROS 2 interactive_markers' tools (declarations only; no ROS call)
#ifndef HAROS_STANDIN_INTERACTIVE_MARKERS_TOOLS_H
#define HAROS_STANDIN_INTERACTIVE_MARKERS_TOOLS_H
#include <string>
#include <geometry_msgs/msg/quaternion.hpp>
#include <visualization_msgs/msg/interactive_marker.hpp>
#include <visualization_msgs/msg/interactive_marker_control.hpp>
#include <visualization_msgs/msg/marker.hpp>

namespace interactive_markers {
void autoComplete(visualization_msgs::msg::InteractiveMarker& msg,
                  bool enable_autocomplete_transparency = true);
void autoComplete(const visualization_msgs::msg::InteractiveMarker& msg,
                  visualization_msgs::msg::InteractiveMarkerControl& control,
                  bool enable_autocomplete_transparency = true);
void uniqueifyControlNames(visualization_msgs::msg::InteractiveMarker& msg);
void makeArrow(const visualization_msgs::msg::InteractiveMarker& msg,
               visualization_msgs::msg::InteractiveMarkerControl& control, float pos);
void makeDisc(const visualization_msgs::msg::InteractiveMarker& msg,
              visualization_msgs::msg::InteractiveMarkerControl& control, float width = 0.3);
void makeViewFacingButton(const visualization_msgs::msg::InteractiveMarker& msg,
                          visualization_msgs::msg::InteractiveMarkerControl& control,
                          std::string text);
void assignDefaultColor(visualization_msgs::msg::Marker& marker,
                        const geometry_msgs::msg::Quaternion& quat);
visualization_msgs::msg::InteractiveMarkerControl makeTitle(
    const visualization_msgs::msg::InteractiveMarker& msg);
}  // namespace interactive_markers
#endif
