// haros_arch stand-in: ros2_control's lifecycle state labels
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_LIFECYCLE_STATE_NAMES_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_LIFECYCLE_STATE_NAMES_HPP
namespace hardware_interface { namespace lifecycle_state_names {
constexpr char UNKNOWN[] = "unknown";
constexpr char UNCONFIGURED[] = "unconfigured";
constexpr char INACTIVE[] = "inactive";
constexpr char ACTIVE[] = "active";
constexpr char FINALIZED[] = "finalized";
} }  // namespace hardware_interface::lifecycle_state_names
#endif
