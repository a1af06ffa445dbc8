// haros_arch stand-in: ROS 1 interactive_markers' tools (declarations only; no ROS call)
#ifndef HAROS_STANDIN_INTERACTIVE_MARKERS_TOOLS_H
#define HAROS_STANDIN_INTERACTIVE_MARKERS_TOOLS_H
#include <geometry_msgs/Quaternion.h>
#include <visualization_msgs/InteractiveMarker.h>
#include <visualization_msgs/InteractiveMarkerControl.h>
#include <visualization_msgs/Marker.h>

namespace interactive_markers {
void autoComplete(visualization_msgs::InteractiveMarker& msg,
                  bool enable_autocomplete_transparency = true);
void autoComplete(const visualization_msgs::InteractiveMarker& msg,
                  visualization_msgs::InteractiveMarkerControl& control,
                  bool enable_autocomplete_transparency = true);
void uniqueifyControlNames(visualization_msgs::InteractiveMarker& msg);
geometry_msgs::Quaternion makeQuaternion(float x, float y, float z);
void makeArrow(const visualization_msgs::InteractiveMarker& msg,
               visualization_msgs::InteractiveMarkerControl& control, float pos);
void makeDisc(const visualization_msgs::InteractiveMarker& msg,
              visualization_msgs::InteractiveMarkerControl& control, float width = 0.3);
void makeViewFacingButton(const visualization_msgs::InteractiveMarker& msg,
                          visualization_msgs::InteractiveMarkerControl& control,
                          std::string text);
void assignDefaultColor(visualization_msgs::Marker& marker,
                        const geometry_msgs::Quaternion& quat);
visualization_msgs::InteractiveMarkerControl makeTitle(
    const visualization_msgs::InteractiveMarker& msg);
}  // namespace interactive_markers
#endif
