// haros_arch stand-in: ros2_control's semantic_components::RangeSensor (declarations only)
#ifndef HAROS_STANDIN_SEMANTIC_COMPONENTS_RANGE
#define HAROS_STANDIN_SEMANTIC_COMPONENTS_RANGE
#include <array>
#include <string>
#include <sensor_msgs/msg/range.hpp>
#include <semantic_components/semantic_component_interface.hpp>
namespace semantic_components {
class RangeSensor : public SemanticComponentInterface<sensor_msgs::msg::Range> {
public:
  explicit RangeSensor(const std::string& name);
  float get_range() const;
  bool get_values_as_message(sensor_msgs::msg::Range& message) const;
};
}  // namespace semantic_components
#endif
