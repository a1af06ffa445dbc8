// haros_arch stand-in: ros2_control's semantic_components::ForceTorqueSensor (declarations only)
#ifndef HAROS_STANDIN_SEMANTIC_COMPONENTS_FORCE_TORQUE
#define HAROS_STANDIN_SEMANTIC_COMPONENTS_FORCE_TORQUE
#include <array>
#include <string>
#include <geometry_msgs/msg/wrench.hpp>
#include <semantic_components/semantic_component_interface.hpp>
namespace semantic_components {
class ForceTorqueSensor : public SemanticComponentInterface<geometry_msgs::msg::Wrench> {
public:
  explicit ForceTorqueSensor(const std::string& name);
  ForceTorqueSensor(const std::string& interface_force_x, const std::string& interface_force_y,
                    const std::string& interface_force_z, const std::string& interface_torque_x,
                    const std::string& interface_torque_y, const std::string& interface_torque_z);
  std::array<double, 3> get_forces() const;
  std::array<double, 3> get_torques() const;
  bool get_values_as_message(geometry_msgs::msg::Wrench& message) const;
};
}  // namespace semantic_components
#endif
