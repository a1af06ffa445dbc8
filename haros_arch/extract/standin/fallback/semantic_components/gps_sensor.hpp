// haros_arch stand-in: ros2_control's semantic_components::GPSSensor (declarations only)
#ifndef HAROS_STANDIN_SEMANTIC_COMPONENTS_GPS
#define HAROS_STANDIN_SEMANTIC_COMPONENTS_GPS
#include <array>
#include <string>
#include <sensor_msgs/msg/nav_sat_fix.hpp>
#include <semantic_components/semantic_component_interface.hpp>
namespace semantic_components {
enum class GPSSensorOption { WithCovariance, WithoutCovariance };
template <GPSSensorOption sensor_option>
class GPSSensor : public SemanticComponentInterface<sensor_msgs::msg::NavSatFix> {
public:
  explicit GPSSensor(const std::string& name);
  int8_t get_status() const;
  uint16_t get_service() const;
  double get_latitude() const;
  double get_longitude() const;
  double get_altitude() const;
  const std::array<double, 9>& get_covariance();
  bool get_values_as_message(sensor_msgs::msg::NavSatFix& message);
};
}  // namespace semantic_components
#endif
