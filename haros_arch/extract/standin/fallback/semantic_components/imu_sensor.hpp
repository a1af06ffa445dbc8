// haros_arch stand-in: ros2_control's semantic_components::IMUSensor (declarations only)
#ifndef HAROS_STANDIN_SEMANTIC_COMPONENTS_IMU
#define HAROS_STANDIN_SEMANTIC_COMPONENTS_IMU
#include <array>
#include <string>
#include <sensor_msgs/msg/imu.hpp>
#include <semantic_components/semantic_component_interface.hpp>
namespace semantic_components {
class IMUSensor : public SemanticComponentInterface<sensor_msgs::msg::Imu> {
public:
  explicit IMUSensor(const std::string& name);
  std::array<double, 4> get_orientation() const;
  std::array<double, 3> get_angular_velocity() const;
  std::array<double, 3> get_linear_acceleration() const;
  bool get_values_as_message(sensor_msgs::msg::Imu& message) const;
};
}  // namespace semantic_components
#endif
