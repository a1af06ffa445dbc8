// haros_arch stand-in: rclcpp_lifecycle::LifecycleNode (declarations only)
#ifndef HAROS_STANDIN_RCLCPP_LIFECYCLE_HPP
#define HAROS_STANDIN_RCLCPP_LIFECYCLE_HPP
#include <rclcpp/rclcpp.hpp>
namespace rclcpp_lifecycle {
class State {
public:
  State();
  State(uint8_t id, const std::string& label);
  uint8_t id() const;
  const std::string& label() const;
};
class Transition {
public:
  Transition(uint8_t id, const std::string& label = "");
  uint8_t id() const;
  const std::string& label() const;
};
class ManagedEntityInterface {
public:
  virtual ~ManagedEntityInterface();
  virtual void on_activate();
  virtual void on_deactivate();
};
// rclcpp's allocator default: a wrapper's ``shared_ptr<LifecyclePublisher<M, A>>`` with
// ``A = std::allocator<void>`` (mocap4r2's ControlledLifecycleNode) is the member's type
template<class M, class A = std::allocator<void>> class LifecyclePublisher
    : public rclcpp::Publisher<M, A>, public ManagedEntityInterface {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(LifecyclePublisher)
  void on_activate();
  void on_deactivate();
  bool is_activated() const;
};
// the options lifecycle_node.hpp makes for its create_publisher / create_subscription
template<class A = std::allocator<void>>
rclcpp::PublisherOptionsWithAllocator<A> create_default_publisher_options();
template<class A = std::allocator<void>>
rclcpp::SubscriptionOptionsWithAllocator<A> create_default_subscription_options();
// the transitions' callbacks: ros2_control's controllers and hardware components derive
// from this interface, not from the node
namespace node_interfaces { class LifecycleNodeInterface {
public:
  enum class CallbackReturn { SUCCESS, FAILURE, ERROR };
  virtual ~LifecycleNodeInterface();
  virtual CallbackReturn on_configure(const State& previous_state);
  virtual CallbackReturn on_cleanup(const State& previous_state);
  virtual CallbackReturn on_shutdown(const State& previous_state);
  virtual CallbackReturn on_activate(const State& previous_state);
  virtual CallbackReturn on_deactivate(const State& previous_state);
  virtual CallbackReturn on_error(const State& previous_state);
}; }
class LifecycleNode : public std::enable_shared_from_this<LifecycleNode>,
                      public node_interfaces::LifecycleNodeInterface {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(LifecycleNode)
  explicit LifecycleNode(const std::string& node_name,
                         const rclcpp::NodeOptions& options = rclcpp::NodeOptions());
  LifecycleNode(const std::string& node_name, const std::string& namespace_,
                const rclcpp::NodeOptions& options = rclcpp::NodeOptions(),
                bool enable_communication_interface = true);
  virtual ~LifecycleNode();
  HAROS_RCLCPP_NODE_API_OF(LifecycleNode, rclcpp_lifecycle::LifecyclePublisher)
  using CallbackReturn = node_interfaces::LifecycleNodeInterface::CallbackReturn;
  virtual CallbackReturn on_configure(const State& state);
  virtual CallbackReturn on_activate(const State& state);
  virtual CallbackReturn on_deactivate(const State& state);
  virtual CallbackReturn on_cleanup(const State& state);
  virtual CallbackReturn on_shutdown(const State& state);
  virtual CallbackReturn on_error(const State& state);
  // a transition's callback set without deriving (ros2_control's controller base)
  bool register_on_configure(std::function<CallbackReturn(const State&)> fcn);
  bool register_on_cleanup(std::function<CallbackReturn(const State&)> fcn);
  bool register_on_shutdown(std::function<CallbackReturn(const State&)> fcn);
  bool register_on_activate(std::function<CallbackReturn(const State&)> fcn);
  bool register_on_deactivate(std::function<CallbackReturn(const State&)> fcn);
  bool register_on_error(std::function<CallbackReturn(const State&)> fcn);
  // a transition the node's own code triggers (book_ros2's object_tracker configures its
  // HeadController so), by id or as a Transition, with the callback's result or not
  const State& trigger_transition(const Transition& transition);
  const State& trigger_transition(const Transition& transition, CallbackReturn& cb_return_code);
  const State& trigger_transition(uint8_t transition_id);
  const State& trigger_transition(uint8_t transition_id, CallbackReturn& cb_return_code);
  std::vector<Transition> get_available_transitions() const;
  std::vector<Transition> get_transition_graph() const;
  const State& configure(CallbackReturn& cb_return_code);
  const State& activate(CallbackReturn& cb_return_code);
  const State& deactivate(CallbackReturn& cb_return_code);
  const State& cleanup(CallbackReturn& cb_return_code);
  const State& shutdown(CallbackReturn& cb_return_code);
  const State& configure();
  const State& activate();
  const State& deactivate();
  const State& cleanup();
  const State& shutdown();
  const State& get_current_state() const;
  std::vector<State> get_available_states() const;
  void add_managed_entity(std::weak_ptr<rclcpp_lifecycle::ManagedEntityInterface> entity);
  void add_timer_handle(std::shared_ptr<rclcpp::TimerBase> timer);
};
}
#endif
