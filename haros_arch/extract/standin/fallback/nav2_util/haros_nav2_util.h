// haros_arch stand-in: the parts of navigation2's nav2_util (Humble and Jazzy) that
// plugins and servers outside navigation2 use (declarations only; every nav2_util/...
// header stands in as this one, read only when the workspace has no nav2_util package,
// headers.FALLBACK_UMBRELLAS). Its ROS calls are API rows (api.NAV2): the parameter
// helpers declare on the node they are given; SimpleActionServer serves its action,
// ServiceClient is a client of its service.
// Classes of nav2_util that make calls the rows do not describe (TwistPublisher,
// OdomSmoother, ...) are left out: the parse declares them as unknown names, and a node
// given to one is partial.
#ifndef HAROS_STANDIN_NAV2_UTIL_H
#define HAROS_STANDIN_NAV2_UTIL_H
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_action/rclcpp_action.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <tf2_ros/buffer.h>
#include <bondcpp/bond.hpp>
#include <geometry_msgs/msg/point.hpp>
#include <geometry_msgs/msg/pose.hpp>
#include <geometry_msgs/msg/pose_stamped.hpp>
#include <geometry_msgs/msg/quaternion.hpp>
#include <geometry_msgs/msg/transform_stamped.hpp>
#include <geometry_msgs/msg/twist.hpp>
#include <geometry_msgs/msg/twist_stamped.hpp>
#include <nav_msgs/msg/path.hpp>

namespace nav2_util {

using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;
using ParameterDescriptor = rcl_interfaces::msg::ParameterDescriptor;

// the lifecycle node of navigation2's servers (its pointers are the base's)
class LifecycleNode : public rclcpp_lifecycle::LifecycleNode {
public:
  LifecycleNode(const std::string& node_name, const std::string& ns = "",
                const rclcpp::NodeOptions& options = rclcpp::NodeOptions());
  virtual ~LifecycleNode();
  struct floating_point_range { double from_value; double to_value; double step; };
  struct integer_range { int from_value; int to_value; int step; };
  // declares ``name`` with that default (an API row, as declare_parameter)
  void add_parameter(const std::string& name, const rclcpp::ParameterValue& default_value,
                     const std::string& description = "",
                     const std::string& additional_constraints = "", bool read_only = false);
  void add_parameter(const std::string& name, const rclcpp::ParameterValue& default_value,
                     const floating_point_range fp_range, const std::string& description = "",
                     const std::string& additional_constraints = "", bool read_only = false);
  void add_parameter(const std::string& name, const rclcpp::ParameterValue& default_value,
                     const integer_range int_range, const std::string& description = "",
                     const std::string& additional_constraints = "", bool read_only = false);
  std::shared_ptr<nav2_util::LifecycleNode> shared_from_this();
  CallbackReturn on_error(const rclcpp_lifecycle::State& state);
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

// node_utils.hpp
std::string sanitize_node_name(const std::string& potential_node_name);
std::string add_namespaces(const std::string& top_ns, const std::string& sub_ns = "");
std::string generate_internal_node_name(const std::string& prefix = "");
rclcpp::Node::SharedPtr generate_internal_node(const std::string& prefix = "");
std::string time_to_string(size_t len);
// the parameter declared on ``node`` unless it is already (API rows)
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
// the type of plugin ``plugin_name``: its parameter ``<plugin_name>.plugin`` (API row)
template<typename NodeT>
std::string get_plugin_type_param(NodeT node, const std::string& plugin_name);
void setSoftRealTimePriority();

// robot_utils.hpp: transforms looked up in the buffer given (no ROS call)
bool getCurrentPose(
  geometry_msgs::msg::PoseStamped& global_pose, tf2_ros::Buffer& tf_buffer,
  const std::string global_frame = "map", const std::string robot_frame = "base_link",
  const double transform_timeout = 0.1, const rclcpp::Time stamp = rclcpp::Time());
bool transformPoseInTargetFrame(
  const geometry_msgs::msg::PoseStamped& input_pose,
  geometry_msgs::msg::PoseStamped& transformed_pose, tf2_ros::Buffer& tf_buffer,
  const std::string target_frame, const double transform_timeout = 0.1);
bool getTransform(
  const std::string& source_frame_id, const std::string& target_frame_id,
  const tf2::Duration& transform_tolerance, const std::shared_ptr<tf2_ros::Buffer> tf_buffer,
  tf2::Transform& tf2_transform);
bool getTransform(
  const std::string& source_frame_id, const rclcpp::Time& source_time,
  const std::string& target_frame_id, const rclcpp::Time& target_time,
  const std::string& fixed_frame_id, const tf2::Duration& transform_tolerance,
  const std::shared_ptr<tf2_ros::Buffer> tf_buffer, tf2::Transform& tf2_transform);
bool getTransform(
  const std::string& source_frame_id, const std::string& target_frame_id,
  const tf2::Duration& transform_tolerance, const std::shared_ptr<tf2_ros::Buffer> tf_buffer,
  geometry_msgs::msg::TransformStamped& transform_msg);
bool getTransform(
  const std::string& source_frame_id, const rclcpp::Time& source_time,
  const std::string& target_frame_id, const rclcpp::Time& target_time,
  const std::string& fixed_frame_id, const tf2::Duration& transform_tolerance,
  const std::shared_ptr<tf2_ros::Buffer> tf_buffer,
  geometry_msgs::msg::TransformStamped& transform_msg);
bool validateTwist(const geometry_msgs::msg::Twist& msg);
bool validateTwist(const geometry_msgs::msg::TwistStamped& msg);

// geometry_utils.hpp
namespace geometry_utils {
geometry_msgs::msg::Quaternion orientationAroundZAxis(double angle);
double euclidean_distance(const geometry_msgs::msg::Point& pos1,
                          const geometry_msgs::msg::Point& pos2, const bool is_3d = false);
double euclidean_distance(const geometry_msgs::msg::Pose& pos1,
                          const geometry_msgs::msg::Pose& pos2, const bool is_3d = false);
double euclidean_distance(const geometry_msgs::msg::PoseStamped& pos1,
                          const geometry_msgs::msg::PoseStamped& pos2, const bool is_3d = false);
template<typename Iter, typename Getter>
Iter min_by(Iter begin, Iter end, Getter getCompareVal);
template<typename Iter, typename Getter>
Iter first_after_integrated_distance(Iter begin, Iter end, Getter getCompareVal);
double calculate_path_length(const nav_msgs::msg::Path& path, size_t start_index = 0);
}  // namespace geometry_utils

// line_iterator.hpp: the cells of a line between two cells (no ROS call)
class LineIterator {
public:
  LineIterator(int x0, int y0, int x1, int y1);
  bool isValid() const;
  void advance();
  int getX() const;
  int getY() const;
  int getX0() const;
  int getY0() const;
  int getX1() const;
  int getY1() const;
};

// node_thread.hpp: spins the node it is given (no ROS call)
class NodeThread {
public:
  explicit NodeThread(rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_base);
  explicit NodeThread(rclcpp::executors::SingleThreadedExecutor::SharedPtr executor);
  template<typename NodeT> explicit NodeThread(NodeT node);
  ~NodeThread();
};

// simple_action_server.hpp: serves the action ``action_name`` on the node (API row)
template<typename ActionT>
class SimpleActionServer {
public:
  typedef std::function<void()> ExecuteCallback;
  typedef std::function<void()> CompletionCallback;
  template<typename NodeT>
  explicit SimpleActionServer(
    NodeT node, const std::string& action_name, ExecuteCallback execute_callback,
    CompletionCallback completion_callback = nullptr,
    std::chrono::milliseconds server_timeout = std::chrono::milliseconds(500),
    bool spin_thread = false,
    const rcl_action_server_options_t& options = rcl_action_server_get_default_options(),
    const bool realtime = false);
  explicit SimpleActionServer(
    rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_base_interface,
    rclcpp::node_interfaces::NodeClockInterface::SharedPtr node_clock_interface,
    rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr node_logging_interface,
    rclcpp::node_interfaces::NodeWaitablesInterface::SharedPtr node_waitables_interface,
    const std::string& action_name, ExecuteCallback execute_callback,
    CompletionCallback completion_callback = nullptr,
    std::chrono::milliseconds server_timeout = std::chrono::milliseconds(500),
    bool spin_thread = false,
    const rcl_action_server_options_t& options = rcl_action_server_get_default_options(),
    const bool realtime = false);
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

// service_client.hpp: a client of ServiceT named ``service_name`` on the node given
// (API row); Jazzy adds use_internal_executor
template<class ServiceT, typename NodeT = rclcpp::Node::SharedPtr>
class ServiceClient {
public:
  using RequestType = typename ServiceT::Request;
  using ResponseType = typename ServiceT::Response;
  using SharedPtr = std::shared_ptr<ServiceClient<ServiceT, NodeT>>;
  explicit ServiceClient(const std::string& service_name, const NodeT& provided_node,
                         bool use_internal_executor = false);
  typename ResponseType::SharedPtr invoke(
    typename RequestType::SharedPtr& request,
    const std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1));
  bool invoke(typename RequestType::SharedPtr& request,
              typename ResponseType::SharedPtr& response);
  bool wait_for_service(const std::chrono::nanoseconds timeout = std::chrono::nanoseconds::max());
  std::string getServiceName();
};

}  // namespace nav2_util
#endif
