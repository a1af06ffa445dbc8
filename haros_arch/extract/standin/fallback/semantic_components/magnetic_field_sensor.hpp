// haros_arch stand-in: ros2_control's semantic_components::MagneticFieldSensor (declarations only)
#ifndef HAROS_STANDIN_SEMANTIC_COMPONENTS_MAGNETIC_FIELD
#define HAROS_STANDIN_SEMANTIC_COMPONENTS_MAGNETIC_FIELD
#include <array>
#include <string>
#include <sensor_msgs/msg/magnetic_field.hpp>
#include <semantic_components/semantic_component_interface.hpp>
namespace semantic_components {
class MagneticFieldSensor
    : public SemanticComponentInterface<sensor_msgs::msg::MagneticField> {
public:
  explicit MagneticFieldSensor(const std::string& name);
  bool get_values_as_message(sensor_msgs::msg::MagneticField& message);
};
}  // namespace semantic_components
#endif
