// haros_arch stand-in: realtime_tools' AsyncFunctionHandler and its parameters (jazzy API;
// declarations only). AsyncFunctionHandlerParams::initialize(node, prefix) reads the
// handler's settings from the node's parameters named prefix + thread_priority,
// cpu_affinity, scheduling_policy, execution_rate, wait_until_initial_trigger and
// print_warnings, each only when the node has it (an API row, api.py).
#ifndef HAROS_STANDIN_REALTIME_TOOLS_ASYNC_FUNCTION_HANDLER_HPP
#define HAROS_STANDIN_REALTIME_TOOLS_ASYNC_FUNCTION_HANDLER_HPP
#include <atomic>
#include <chrono>
#include <functional>
#include <string>
#include <thread>
#include <utility>
#include <vector>
#include <rclcpp/rclcpp.hpp>

namespace realtime_tools {
class AsyncSchedulingPolicy {
public:
  enum Value : int8_t { UNKNOWN = -1, SYNCHRONIZED, DETACHED };
  AsyncSchedulingPolicy();
  constexpr AsyncSchedulingPolicy(Value value) : value_(value) {}
  explicit AsyncSchedulingPolicy(const std::string& data_type);
  operator Value() const;
  constexpr bool operator==(AsyncSchedulingPolicy other) const { return value_ == other.value_; }
  constexpr bool operator!=(AsyncSchedulingPolicy other) const { return value_ != other.value_; }
  constexpr bool operator==(Value other) const { return value_ == other; }
  constexpr bool operator!=(Value other) const { return value_ != other; }
  std::string to_string() const;
  AsyncSchedulingPolicy from_string(const std::string& data_type);
private:
  Value value_ = UNKNOWN;
};

struct AsyncFunctionHandlerParams {
  bool validate() const;
  template<typename NodeT> void initialize(NodeT& node, const std::string& prefix);
  int thread_priority = 50;
  std::vector<int> cpu_affinity_cores;
  AsyncSchedulingPolicy scheduling_policy = AsyncSchedulingPolicy::SYNCHRONIZED;
  unsigned int exec_rate = 0u;
  rclcpp::Clock::SharedPtr clock;
  rclcpp::Logger logger = rclcpp::get_logger("AsyncFunctionHandler");
  std::function<bool()> trigger_predicate;
  bool wait_until_initial_trigger = true;
  bool print_warnings = true;
};

template<typename T>
class AsyncFunctionHandler {
public:
  AsyncFunctionHandler();
  ~AsyncFunctionHandler();
  void init(std::function<T(const rclcpp::Time&, const rclcpp::Duration&)> callback,
            int thread_priority = 50);
  void init(std::function<T(const rclcpp::Time&, const rclcpp::Duration&)> callback,
            std::function<bool()> trigger_predicate, int thread_priority = 50);
  void init(std::function<T(const rclcpp::Time&, const rclcpp::Duration&)> callback,
            const AsyncFunctionHandlerParams& params);
  std::pair<bool, T> trigger_async_callback(const rclcpp::Time& time,
                                            const rclcpp::Duration& period);
  const rclcpp::Time& get_current_callback_time() const;
  const rclcpp::Duration& get_current_callback_period() const;
  void reset_variables();
  bool wait_for_trigger_cycle_to_finish();
  bool pause_execution();
  bool is_initialized() const;
  void join_async_callback_thread();
  bool is_running() const;
  bool is_stopped() const;
  bool is_paused() const;
  std::thread& get_thread();
  const std::thread& get_thread() const;
  const AsyncFunctionHandlerParams& get_params() const;
  bool is_trigger_cycle_in_progress() const;
  void stop_thread();
  std::chrono::nanoseconds get_last_execution_time() const;
  void start_thread();
};
}  // namespace realtime_tools
#endif
