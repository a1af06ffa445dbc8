// haros_arch stand-in: ros2_control's hardware description (the <ros2_control> tag of a
// robot description as a hardware component reads it; declarations only)
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_HARDWARE_INFO_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_HARDWARE_INFO_HPP
#include <cstdint>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>
#include <joint_limits/joint_limits.hpp>
namespace hardware_interface {
struct InterfaceInfo {
  std::string name;
  std::string min;
  std::string max;
  std::string initial_value;
  std::string data_type;
  int size;
  bool enable_limits;
  std::unordered_map<std::string, std::string> parameters;
};
struct MimicJoint {
  std::size_t joint_index;
  std::size_t mimicked_joint_index;
  double multiplier;
  double offset;
};
enum class MimicAttribute { NOT_SET, TRUE, FALSE };
struct ComponentInfo {
  std::string name;
  std::string type;
  MimicAttribute is_mimic;
  bool enable_limits;
  std::vector<InterfaceInfo> command_interfaces;
  std::vector<InterfaceInfo> state_interfaces;
  std::unordered_map<std::string, std::string> parameters;
};
struct JointInfo {
  std::string name;
  std::vector<std::string> state_interfaces;
  std::vector<std::string> command_interfaces;
  std::string role;
  double mechanical_reduction;
  double offset;
};
struct ActuatorInfo {
  std::string name;
  std::vector<std::string> state_interfaces;
  std::vector<std::string> command_interfaces;
  std::string role;
  double mechanical_reduction;
  double offset;
};
struct TransmissionInfo {
  std::string name;
  std::string type;
  std::vector<JointInfo> joints;
  std::vector<ActuatorInfo> actuators;
  std::unordered_map<std::string, std::string> parameters;
};
using HANDLE_DATATYPE = std::variant<std::monostate, double, float, bool, uint8_t, int8_t,
                                     uint16_t, int16_t, uint32_t, int32_t>;
class HandleDataType {
public:
  enum Value : int8_t { UNKNOWN = -1, DOUBLE, FLOAT32, BOOL, UINT8, INT8, UINT16, INT16,
                        UINT32, INT32 };
  HandleDataType();
  constexpr HandleDataType(Value value) : value_(value) {}
  explicit HandleDataType(const std::string& data_type);
  operator Value() const;
  bool operator==(HandleDataType other) const;
  bool operator!=(HandleDataType other) const;
  bool operator==(Value other) const;
  bool operator!=(Value other) const;
  std::string to_string() const;
  bool is_castable_to_double() const;
  double cast_to_double(const HANDLE_DATATYPE& value) const;
  HandleDataType from_string(const std::string& data_type);
private:
  Value value_;
};
struct InterfaceDescription {
  InterfaceDescription(const std::string& prefix_name_in, const InterfaceInfo& interface_info_in);
  std::string prefix_name;
  InterfaceInfo interface_info;
  std::string interface_name;
  const std::string& get_prefix_name() const;
  const std::string& get_interface_name() const;
  const std::string& get_name() const;
  const std::string& get_data_type_string() const;
  HandleDataType get_data_type() const;
};
struct HardwareAsyncParams {
  int thread_priority;
  std::string scheduling_policy;
  std::vector<int> cpu_affinity_cores;
  bool print_warnings;
};
struct HardwareInfo {
  std::string name;
  std::string type;
  std::string group;
  unsigned int rw_rate;
  bool is_async;
  int thread_priority;
  HardwareAsyncParams async_params;
  std::string hardware_plugin_name;
  std::string hardware_class_type;  // Humble's name of the plugin
  std::unordered_map<std::string, std::string> hardware_parameters;
  std::vector<ComponentInfo> joints;
  std::vector<MimicJoint> mimic_joints;
  std::vector<ComponentInfo> sensors;
  std::vector<ComponentInfo> gpios;
  std::vector<TransmissionInfo> transmissions;
  std::string original_xml;
  std::unordered_map<std::string, joint_limits::JointLimits> limits;
  std::unordered_map<std::string, joint_limits::SoftJointLimits> soft_limits;
};
}  // namespace hardware_interface
#endif
