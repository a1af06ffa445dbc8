// haros_arch stand-in: ros2_control's semantic_components::PoseSensor (declarations only)
#ifndef HAROS_STANDIN_SEMANTIC_COMPONENTS_POSE
#define HAROS_STANDIN_SEMANTIC_COMPONENTS_POSE
#include <array>
#include <string>
#include <geometry_msgs/msg/pose.hpp>
#include <semantic_components/semantic_component_interface.hpp>
namespace semantic_components {
class PoseSensor : public SemanticComponentInterface<geometry_msgs::msg::Pose> {
public:
  explicit PoseSensor(const std::string& name);
  std::array<double, 3> get_position() const;
  std::array<double, 4> get_orientation() const;
  bool get_values_as_message(geometry_msgs::msg::Pose& message) const;
};
}  // namespace semantic_components
#endif
