// haros_arch stand-in: the interface names of ros2_control's hardware_interface (their
// values are the library's: a controller builds names from them)
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_TYPE_VALUES_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_TYPE_VALUES_HPP
namespace hardware_interface {
constexpr char HW_IF_POSITION[] = "position";
constexpr char HW_IF_VELOCITY[] = "velocity";
constexpr char HW_IF_ACCELERATION[] = "acceleration";
constexpr char HW_IF_EFFORT[] = "effort";
constexpr char HW_IF_TORQUE[] = "torque";
constexpr char HW_IF_FORCE[] = "force";
constexpr char HW_IF_CURRENT[] = "current";
constexpr char HW_IF_TEMPERATURE[] = "temperature";
constexpr char HW_IF_PROPORTIONAL_GAIN[] = "proportional";
constexpr char HW_IF_INTEGRAL_GAIN[] = "integral";
constexpr char HW_IF_DERIVATIVE_GAIN[] = "derivative";
constexpr char HW_IF_INTEGRAL_CLAMP_MAX[] = "integral_clamp_max";
constexpr char HW_IF_INTEGRAL_CLAMP_MIN[] = "integral_clamp_min";
constexpr char HW_IF_FEEDFORWARD[] = "feedforward";
}  // namespace hardware_interface
#endif
