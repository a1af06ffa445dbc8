// haros_arch stand-in: the parts of navigation2's nav2_ros_common (Kilted and later: the
// namespace nav2) that plugins and servers outside navigation2 use (declarations only;
// every nav2_ros_common/... header stands in as this one, read only when the workspace
// has no nav2_ros_common package, headers.FALLBACK_UMBRELLAS). Its ROS calls are API rows
// (api.NAV2): the lifecycle node's factories make the topic, service or action they
// name; the parameter helpers declare on the node they are given. The parameters the
// library's own code reads beside them (allow_parameter_qos_overrides, the lifecycle
// node's bond_heartbeat_period / autostart_node) are not described.
#ifndef HAROS_STANDIN_NAV2_ROS_COMMON_H
#define HAROS_STANDIN_NAV2_ROS_COMMON_H
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_action/rclcpp_action.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <tf2_ros/buffer.h>
#include <bondcpp/bond.hpp>

namespace nav2 {

using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;
using ParameterDescriptor = rcl_interfaces::msg::ParameterDescriptor;
using TransformBuffer = tf2_ros::Buffer;

namespace qos {
class StandardTopicQoS : public rclcpp::QoS {
public:
  explicit StandardTopicQoS(const int depth = 10);
};
class LatchedPublisherQoS : public rclcpp::QoS {
public:
  explicit LatchedPublisherQoS(const int depth = 1);
};
class LatchedSubscriptionQoS : public rclcpp::QoS {
public:
  explicit LatchedSubscriptionQoS(const int depth = 1);
};
class SensorDataQoS : public rclcpp::QoS {
public:
  explicit SensorDataQoS(const int depth = 10);
};
}  // namespace qos

template<typename MessageT> using Publisher = rclcpp_lifecycle::LifecyclePublisher<MessageT>;
template<typename MessageT> using Subscription = rclcpp::Subscription<MessageT>;
template<typename ActionT> using ActionClient = rclcpp_action::Client<ActionT>;

// node_utils.hpp
std::string sanitize_node_name(const std::string& potential_node_name);
std::string add_namespaces(const std::string& top_ns, const std::string& sub_ns = "");
std::string generate_internal_node_name(const std::string& prefix = "");
rclcpp::Node::SharedPtr generate_internal_node(const std::string& prefix = "");
std::string time_to_string(size_t len);
template<typename NodeT>
void declare_parameter_if_not_declared(
  NodeT node, const std::string& parameter_name, const rclcpp::ParameterValue& default_value,
  const ParameterDescriptor& parameter_descriptor = ParameterDescriptor());
template<typename NodeT>
void declare_parameter_if_not_declared(
  NodeT node, const std::string& parameter_name, const rclcpp::ParameterType& param_type,
  const ParameterDescriptor& parameter_descriptor = ParameterDescriptor());
template<typename ParameterT, typename NodeT>
ParameterT declare_or_get_parameter(
  NodeT node, const std::string& parameter_name, const rclcpp::ParameterType& param_type,
  const ParameterDescriptor& parameter_descriptor = ParameterDescriptor());
template<typename ParamType, typename NodeT>
ParamType declare_or_get_parameter(
  NodeT node, const std::string& parameter_name, const ParamType& default_value,
  const ParameterDescriptor& parameter_descriptor = ParameterDescriptor());
template<typename NodeT>
std::string get_plugin_type_param(NodeT node, const std::string& plugin_name);
void setSoftRealTimePriority();

// simple_action_server.hpp
template<typename ActionT>
class SimpleActionServer {
public:
  using SharedPtr = std::shared_ptr<nav2::SimpleActionServer<ActionT>>;
  using UniquePtr = std::unique_ptr<nav2::SimpleActionServer<ActionT>>;
  typedef std::function<void()> ExecuteCallback;
  typedef std::function<bool(std::shared_ptr<const typename ActionT::Goal>)>
    GoalReceivedCallback;
  typedef std::function<void()> CompletionCallback;
  template<typename NodeT>
  explicit SimpleActionServer(
    NodeT node, const std::string& action_name, ExecuteCallback execute_callback,
    GoalReceivedCallback goal_received_callback = nullptr,
    CompletionCallback completion_callback = nullptr,
    std::chrono::milliseconds server_timeout = std::chrono::milliseconds(500),
    bool spin_thread = false, const bool realtime = false);
  ~SimpleActionServer();
  void activate();
  void deactivate();
  bool is_running();
  bool is_server_active();
  bool is_preempt_requested() const;
  const std::shared_ptr<const typename ActionT::Goal> accept_pending_goal();
  void terminate_pending_goal();
  const std::shared_ptr<const typename ActionT::Goal> get_current_goal() const;
  const rclcpp_action::GoalUUID get_current_goal_id() const;
  const std::shared_ptr<const typename ActionT::Goal> get_pending_goal() const;
  bool is_cancel_requested() const;
  void terminate_all(typename std::shared_ptr<typename ActionT::Result> result =
                       std::make_shared<typename ActionT::Result>());
  void terminate_current(typename std::shared_ptr<typename ActionT::Result> result =
                           std::make_shared<typename ActionT::Result>());
  void succeeded_current(typename std::shared_ptr<typename ActionT::Result> result =
                           std::make_shared<typename ActionT::Result>());
  void publish_feedback(typename std::shared_ptr<typename ActionT::Feedback> feedback);
};

// node_thread.hpp
class NodeThread {
public:
  explicit NodeThread(rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_base);
  explicit NodeThread(rclcpp::executors::SingleThreadedExecutor::SharedPtr executor);
  template<typename NodeT> explicit NodeThread(NodeT node);
  ~NodeThread();
};

// lifecycle_node.hpp: its factories take the topic first and the QoS after the callback,
// and default the QoS; rclcpp's stay visible, as Humble- and Jazzy-style code calls them
// on such a node (a costmap layer's): where both would take a call, the stand-in leaves
// it to rclcpp's, whose row reads the same arguments (the callback group of the forms
// here is not defaulted)
class LifecycleNode : public rclcpp_lifecycle::LifecycleNode {
public:
  using SharedPtr = std::shared_ptr<nav2::LifecycleNode>;
  using WeakPtr = std::weak_ptr<nav2::LifecycleNode>;
  using SharedConstPointer = std::shared_ptr<const nav2::LifecycleNode>;
  LifecycleNode(const std::string& node_name, const std::string& ns,
                const rclcpp::NodeOptions& options = rclcpp::NodeOptions());
  LifecycleNode(const std::string& node_name,
                const rclcpp::NodeOptions& options = rclcpp::NodeOptions());
  virtual ~LifecycleNode();
  template<typename ParameterT>
  ParameterT declare_or_get_parameter(
    const std::string& parameter_name,
    const ParameterDescriptor& parameter_descriptor = ParameterDescriptor());
  template<typename ParamType>
  ParamType declare_or_get_parameter(
    const std::string& parameter_name, const ParamType& default_value,
    const ParameterDescriptor& parameter_descriptor = ParameterDescriptor());
  using rclcpp_lifecycle::LifecycleNode::create_subscription;
  using rclcpp_lifecycle::LifecycleNode::create_publisher;
  using rclcpp_lifecycle::LifecycleNode::create_service;
  using rclcpp_lifecycle::LifecycleNode::create_client;
  template<typename MessageT, typename CallbackT>
  typename nav2::Subscription<MessageT>::SharedPtr create_subscription(
    const std::string& topic_name, CallbackT&& callback,
    const rclcpp::QoS& qos = nav2::qos::StandardTopicQoS(),
    const rclcpp::CallbackGroup::SharedPtr& callback_group = nullptr);
  template<typename MessageT>
  typename nav2::Publisher<MessageT>::SharedPtr create_publisher(const std::string& topic_name);
  template<typename MessageT>
  typename nav2::Publisher<MessageT>::SharedPtr create_publisher(
    const std::string& topic_name, const rclcpp::QoS& qos,
    const rclcpp::CallbackGroup::SharedPtr& callback_group);
  template<typename ServiceT>
  std::shared_ptr<rclcpp::Client<ServiceT>> create_client(
    const std::string& service_name, bool use_internal_executor);
  template<typename ServiceT, typename CallbackT>
  std::shared_ptr<rclcpp::Service<ServiceT>> create_service(
    const std::string& service_name, CallbackT&& cb,
    rclcpp::CallbackGroup::SharedPtr callback_group);
  // (action_name, execute_callback, goal_received_callback, completion_callback,
  // server_timeout, spin_thread, realtime)
  template<typename ActionT, typename... Args>
  typename nav2::SimpleActionServer<ActionT>::SharedPtr create_action_server(
    const std::string& action_name, Args&&... args);
  template<typename ActionT>
  typename nav2::ActionClient<ActionT>::SharedPtr create_action_client(
    const std::string& action_name, rclcpp::CallbackGroup::SharedPtr callback_group = nullptr);
  nav2::LifecycleNode::SharedPtr shared_from_this();
  nav2::LifecycleNode::WeakPtr weak_from_this();
  nav2::CallbackReturn on_error(const rclcpp_lifecycle::State& state);
  void autostart();
  virtual void on_rcl_preshutdown();
  void createBond();
  void destroyBond();
protected:
  void printLifecycleNodeNotification();
  void register_rcl_preshutdown_callback();
  void runCleanups();
  std::unique_ptr<rclcpp::PreShutdownCallbackHandle> rcl_preshutdown_cb_handle_;
  std::shared_ptr<bond::Bond> bond_;
  double bond_heartbeat_period;
  rclcpp::TimerBase::SharedPtr autostart_timer_;
};

}  // namespace nav2
#endif
