// haros_arch stand-in: rclcpp_action (declarations only)
#ifndef HAROS_STANDIN_RCLCPP_ACTION_HPP
#define HAROS_STANDIN_RCLCPP_ACTION_HPP
#include <rclcpp/rclcpp.hpp>
#include <array>
// rcl_action/action_server.h, action_client.h: the options nav2's servers start from
typedef struct rcl_action_server_options_s {
  rmw_qos_profile_t goal_service_qos, cancel_service_qos, result_service_qos,
    feedback_topic_qos, status_topic_qos;
  rcl_duration_t result_timeout;
} rcl_action_server_options_t;
typedef struct rcl_action_client_options_s {
  rmw_qos_profile_t goal_service_qos, result_service_qos, cancel_service_qos,
    feedback_topic_qos, status_topic_qos;
} rcl_action_client_options_t;
rcl_action_server_options_t rcl_action_server_get_default_options(void);
rcl_action_client_options_t rcl_action_client_get_default_options(void);
namespace rclcpp_action {
using GoalUUID = std::array<uint8_t, 16>;
enum class GoalResponse { REJECT = 1, ACCEPT_AND_EXECUTE = 2, ACCEPT_AND_DEFER = 3 };
enum class CancelResponse { REJECT = 1, ACCEPT = 2 };
enum class ResultCode { UNKNOWN = 0, SUCCEEDED = 4, CANCELED = 5, ABORTED = 6 };
template<class A> class ServerGoalHandle {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(ServerGoalHandle)
  bool is_canceling() const;
  bool is_active() const;
  bool is_executing() const;
  std::shared_ptr<const typename A::Goal> get_goal() const;
  const GoalUUID& get_goal_id() const;
  void publish_feedback(std::shared_ptr<typename A::Feedback> feedback);
  void succeed(std::shared_ptr<typename A::Result> result);
  void abort(std::shared_ptr<typename A::Result> result);
  void canceled(std::shared_ptr<typename A::Result> result);
  void execute();
};
template<class A> class ClientGoalHandle {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(ClientGoalHandle)
  struct WrappedResult {
    GoalUUID goal_id;
    ResultCode code;
    std::shared_ptr<typename A::Result> result;
  };
  using Feedback = typename A::Feedback;
  using Result = typename A::Result;
  using FeedbackCallback = std::function<void(std::shared_ptr<ClientGoalHandle>,
                                              const std::shared_ptr<const Feedback>)>;
  using ResultCallback = std::function<void(const WrappedResult&)>;
  const GoalUUID& get_goal_id() const;
  rclcpp::Time get_goal_stamp() const;
  int8_t get_status();
  bool is_feedback_aware();
  bool is_result_aware();
};
// an action's Goal, void for a type with none (a message known only by name: the
// server's handler types must not make every use of Server<A> an error)
template<class A, class = void> struct haros_action_goal { using type = void; };
template<class A> struct haros_action_goal<A, std::void_t<typename A::Goal>> {
  using type = typename A::Goal;
};
template<class A> class Server {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Server)
  // the handlers' types, as a member holds them before create_server is called
  // (moveit_task_constructor's ExecuteTaskSolutionCapability)
  using GoalCallback = std::function<GoalResponse(
      const GoalUUID&, std::shared_ptr<const typename haros_action_goal<A>::type>)>;
  using CancelCallback = std::function<CancelResponse(std::shared_ptr<ServerGoalHandle<A>>)>;
  using AcceptedCallback = std::function<void(std::shared_ptr<ServerGoalHandle<A>>)>;
  // as from Kilted (rclcpp_action 29): what an action's services and feedback show to
  // introspection
  void configure_introspection(std::shared_ptr<rclcpp::Clock> clock, const rclcpp::QoS& qos,
                               rcl_service_introspection_state_t state);
};
template<class A> class Client {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Client)
  void configure_introspection(std::shared_ptr<rclcpp::Clock> clock, const rclcpp::QoS& qos,
                               rcl_service_introspection_state_t state);
  using Goal = typename A::Goal;
  using GoalHandle = ClientGoalHandle<A>;
  using WrappedResult = typename GoalHandle::WrappedResult;
  using Feedback = typename A::Feedback;
  using Result = typename A::Result;
  using FeedbackCallback = typename GoalHandle::FeedbackCallback;
  using ResultCallback = typename GoalHandle::ResultCallback;
  // action_msgs' CancelGoal response, as the client hands it back
  struct CancelResponse {
    RCLCPP_SMART_PTR_DEFINITIONS(CancelResponse)
    static const int8_t ERROR_NONE = 0, ERROR_REJECTED = 1, ERROR_UNKNOWN_GOAL_ID = 2,
                        ERROR_GOAL_TERMINATED = 3;
    int8_t return_code;
    std::vector<GoalUUID> goals_canceling;
  };
  struct SendGoalOptions {
    SendGoalOptions();
    std::function<void(std::shared_ptr<GoalHandle>)> goal_response_callback;
    std::function<void(std::shared_ptr<GoalHandle>, const std::shared_ptr<const typename A::Feedback>)> feedback_callback;
    std::function<void(const WrappedResult&)> result_callback;
  };
  bool action_server_is_ready() const;
  template<class R = long, class P = std::ratio<1>>
  bool wait_for_action_server(std::chrono::duration<R, P> timeout = std::chrono::duration<R, P>(-1));
  std::shared_future<std::shared_ptr<GoalHandle>> async_send_goal(
      const Goal& goal, const SendGoalOptions& options = SendGoalOptions());
  std::shared_future<WrappedResult> async_get_result(std::shared_ptr<GoalHandle> handle,
                                                     ResultCallback callback = nullptr);
  // the cancel callback takes the response (any callable here: code names its type in
  // several ways)
  template<class F = std::nullptr_t>
  std::shared_future<typename CancelResponse::SharedPtr> async_cancel_goal(
      std::shared_ptr<GoalHandle> handle, F callback = nullptr);
  template<class F = std::nullptr_t>
  std::shared_future<typename CancelResponse::SharedPtr> async_cancel_all_goals(
      F callback = nullptr);
  template<class F = std::nullptr_t>
  std::shared_future<typename CancelResponse::SharedPtr> async_cancel_goals_before(
      const rclcpp::Time& stamp, F callback = nullptr);
  void stop_callbacks(std::shared_ptr<GoalHandle> handle);
};
template<class A, class N, class G, class C, class H>
typename Server<A>::SharedPtr create_server(N node, const std::string& name, G handle_goal,
    C handle_cancel, H handle_accepted,
    const rcl_action_server_options_t& options = rcl_action_server_get_default_options(),
    rclcpp::CallbackGroup::SharedPtr group = nullptr);
template<class A, class N>
typename Client<A>::SharedPtr create_client(N node, const std::string& name,
    rclcpp::CallbackGroup::SharedPtr group = nullptr,
    const rcl_action_client_options_t& options = rcl_action_client_get_default_options());
template<class A, class B, class G, class L, class W>
typename Client<A>::SharedPtr create_client(B base, G graph, L logging, W waitables,
    const std::string& name, rclcpp::CallbackGroup::SharedPtr group = nullptr);
template<class A, class B, class C, class L, class W, class G, class X, class H>
typename Server<A>::SharedPtr create_server(B base, C clock, L logging, W waitables,
    const std::string& name, G handle_goal, X handle_cancel, H handle_accepted, ...);
}
#endif
