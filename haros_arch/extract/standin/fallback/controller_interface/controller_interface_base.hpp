// haros_arch stand-in: ros2_control's controller base class (declarations only; read only
// when the workspace has no controller_interface package, headers.FALLBACK). A controller's
// ROS calls go through get_node(), its lifecycle node, and auto_declare (an API row of its
// own: a parameter declaration). Humble's API (init(name, namespace, options), get_state())
// is here beside Jazzy's.
#ifndef HAROS_STANDIN_CONTROLLER_INTERFACE_BASE_HPP
#define HAROS_STANDIN_CONTROLLER_INTERFACE_BASE_HPP
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <hardware_interface/handle.hpp>
#include <hardware_interface/loaned_command_interface.hpp>
#include <hardware_interface/loaned_state_interface.hpp>
#include <joint_limits/joint_limits.hpp>
namespace controller_interface {
using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;
enum class return_type : std::uint8_t { OK = 0, ERROR = 1 };
enum class interface_configuration_type : std::uint8_t {
  ALL = 0, INDIVIDUAL = 1, NONE = 2, INDIVIDUAL_BEST_EFFORT = 3, REGEX = 10 };
struct InterfaceConfiguration {
  interface_configuration_type type;
  std::vector<std::string> names;
};
struct ControllerInterfaceParams {
  std::string controller_name;
  std::string robot_description;
  unsigned int update_rate;
  unsigned int controller_manager_update_rate;
  std::string node_namespace;
  rclcpp::NodeOptions node_options;
  std::unordered_map<std::string, joint_limits::JointLimits> hard_joint_limits;
  std::unordered_map<std::string, joint_limits::SoftJointLimits> soft_joint_limits;
};
struct ControllerUpdateStatus {
  bool successful;
  return_type result;
};
class ControllerInterfaceBase : public rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface {
public:
  ControllerInterfaceBase();
  virtual ~ControllerInterfaceBase();
  virtual InterfaceConfiguration command_interface_configuration() const = 0;
  virtual InterfaceConfiguration state_interface_configuration() const = 0;
  virtual void assign_interfaces(
      std::vector<hardware_interface::LoanedCommandInterface>&& command_interfaces,
      std::vector<hardware_interface::LoanedStateInterface>&& state_interfaces);
  virtual void release_interfaces();
  return_type init(const std::string& controller_name, const std::string& urdf,
                   unsigned int cm_update_rate, const std::string& node_namespace,
                   const rclcpp::NodeOptions& node_options);
  return_type init(const ControllerInterfaceParams& params);
  virtual return_type init(const std::string& controller_name,
                           const std::string& namespace_ = "",
                           const rclcpp::NodeOptions& node_options = rclcpp::NodeOptions());
  const rclcpp_lifecycle::State& configure();
  virtual CallbackReturn on_init() = 0;
  virtual return_type update(const rclcpp::Time& time, const rclcpp::Duration& period) = 0;
  ControllerUpdateStatus trigger_update(const rclcpp::Time& time,
                                        const rclcpp::Duration& period);
  std::shared_ptr<rclcpp_lifecycle::LifecycleNode> get_node();
  std::shared_ptr<const rclcpp_lifecycle::LifecycleNode> get_node() const;
  const rclcpp_lifecycle::State& get_lifecycle_state() const;
  const rclcpp_lifecycle::State& get_state() const;
  uint8_t get_lifecycle_id() const;
  unsigned int get_update_rate() const;
  bool is_async() const;
  const std::string& get_robot_description() const;
  const std::unordered_map<std::string, joint_limits::JointLimits>& get_hard_joint_limits() const;
  const std::unordered_map<std::string, joint_limits::SoftJointLimits>&
  get_soft_joint_limits() const;
  virtual rclcpp::NodeOptions define_custom_node_options() const;
  // declares the parameter on the node, or reads it when it is declared already
  template <typename ParameterT>
  ParameterT auto_declare(const std::string& name, const ParameterT& default_value);
  virtual bool is_chainable() const = 0;
  virtual std::vector<hardware_interface::CommandInterface::SharedPtr>
  export_reference_interfaces() = 0;
  virtual std::vector<hardware_interface::StateInterface::ConstSharedPtr>
  export_state_interfaces() = 0;
  virtual bool set_chained_mode(bool chained_mode) = 0;
  virtual bool is_in_chained_mode() const = 0;
  void wait_for_trigger_update_to_finish();
  void prepare_for_deactivation();
  std::string get_name() const;
  void enable_introspection(bool enable);
protected:
  std::vector<hardware_interface::LoanedCommandInterface> command_interfaces_;
  std::vector<hardware_interface::LoanedStateInterface> state_interfaces_;
  unsigned int update_rate_;
};
using ControllerInterfaceBaseSharedPtr = std::shared_ptr<ControllerInterfaceBase>;
}  // namespace controller_interface
#endif
