// haros_arch stand-in: ros2_control's hardware_interface return values (declarations only;
// read only when the workspace has no hardware_interface package, headers.FALLBACK)
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_RETURN_VALUES_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_RETURN_VALUES_HPP
#include <chrono>
#include <cstdint>
#include <optional>
namespace hardware_interface {
enum class return_type : std::uint8_t { OK = 0, ERROR = 1, DEACTIVATE = 2 };
struct HardwareComponentCycleStatus {
  bool successful = true;
  return_type result = return_type::OK;
  std::optional<std::chrono::nanoseconds> execution_time;
};
}  // namespace hardware_interface
#endif
