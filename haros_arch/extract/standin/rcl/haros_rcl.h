// haros_arch stand-in: the rcl / rcutils C API parts node code uses (declarations only);
// every rcl/, rcutils/ and rcpputils/ header maps to this file
#ifndef HAROS_STANDIN_RCL_H
#define HAROS_STANDIN_RCL_H
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>
extern "C" {
typedef int rcutils_ret_t;
typedef int rcl_ret_t;
#define RCUTILS_RET_OK 0
#define RCUTILS_RET_ERROR 2
#define RCL_RET_OK 0
#define RCL_RET_ERROR 1
typedef struct rcutils_error_string_t { char str[1024]; } rcutils_error_string_t;
rcutils_error_string_t rcutils_get_error_string(void);
void rcutils_reset_error(void);
typedef rcutils_error_string_t rcl_error_string_t;
rcl_error_string_t rcl_get_error_string(void);
void rcl_reset_error(void);
typedef struct rcutils_allocator_s { void* state; } rcutils_allocator_t;
typedef rcutils_allocator_t rcl_allocator_t;
rcutils_allocator_t rcutils_get_default_allocator(void);
rcl_allocator_t rcl_get_default_allocator(void);
#define RCUTILS_RET_LOGGING_SEVERITY_STRING_INVALID 1040
#define RCUTILS_RET_LOGGING_SEVERITY_MAP_INVALID 1041
rcutils_ret_t rcutils_logging_severity_level_from_string(const char* severity_string,
                                                         rcutils_allocator_t allocator,
                                                         int* severity);
bool rcutils_error_is_set(void);
bool rcutils_cli_option_exist(char** begin, char** end, const char* option);
char* rcutils_cli_get_option(char** begin, char** end, const char* option);
enum RCUTILS_LOG_SEVERITY { RCUTILS_LOG_SEVERITY_UNSET = 0, RCUTILS_LOG_SEVERITY_DEBUG = 10,
  RCUTILS_LOG_SEVERITY_INFO = 20, RCUTILS_LOG_SEVERITY_WARN = 30,
  RCUTILS_LOG_SEVERITY_ERROR = 40, RCUTILS_LOG_SEVERITY_FATAL = 50 };
rcutils_ret_t rcutils_logging_set_logger_level(const char* name, int level);
int rcutils_logging_get_logger_level(const char* name);
rcutils_ret_t rcutils_logging_initialize(void);
typedef enum rcl_clock_type_e { RCL_CLOCK_UNINITIALIZED = 0, RCL_ROS_TIME, RCL_SYSTEM_TIME,
  RCL_STEADY_TIME } rcl_clock_type_t;
typedef enum rcl_service_introspection_state_e { RCL_SERVICE_INTROSPECTION_OFF = 0,
  RCL_SERVICE_INTROSPECTION_METADATA, RCL_SERVICE_INTROSPECTION_CONTENTS
} rcl_service_introspection_state_t;
typedef int64_t rcl_time_point_value_t;
typedef int64_t rcl_duration_value_t;
// rcl/wait.h: the entities ready after a wait (opaque here: only read by index or size)
typedef struct rcl_subscription_s rcl_subscription_t;
typedef struct rcl_guard_condition_s rcl_guard_condition_t;
typedef struct rcl_timer_s rcl_timer_t;
rcl_ret_t rcl_timer_exchange_period(const rcl_timer_t* timer, int64_t new_period,
                                    int64_t* old_period);
rcl_ret_t rcl_timer_get_period(const rcl_timer_t* timer, int64_t* period);
typedef struct rcl_client_s rcl_client_t;
typedef struct rcl_service_s rcl_service_t;
typedef struct rcl_event_s rcl_event_t;
typedef struct rcl_wait_set_s {
  const rcl_subscription_t** subscriptions; size_t size_of_subscriptions;
  const rcl_guard_condition_t** guard_conditions; size_t size_of_guard_conditions;
  const rcl_timer_t** timers; size_t size_of_timers;
  const rcl_client_t** clients; size_t size_of_clients;
  const rcl_service_t** services; size_t size_of_services;
  const rcl_event_t** events; size_t size_of_events;
  void* impl;
} rcl_wait_set_t;
// rcl/time.h, rcutils/time.h
typedef struct rcl_duration_s { rcl_duration_value_t nanoseconds; } rcl_duration_t;
typedef int64_t rcutils_time_point_value_t;
typedef int64_t rcutils_duration_value_t;
rcutils_ret_t rcutils_system_time_now(rcutils_time_point_value_t* now);
rcutils_ret_t rcutils_steady_time_now(rcutils_time_point_value_t* now);
#define RCUTILS_S_TO_NS(seconds) ((seconds) * (1000LL * 1000LL * 1000LL))
#define RCUTILS_MS_TO_NS(milliseconds) ((milliseconds) * (1000LL * 1000LL))
#define RCUTILS_US_TO_NS(microseconds) ((microseconds) * 1000LL)
#define RCUTILS_NS_TO_S(nanoseconds) ((nanoseconds) / (1000LL * 1000LL * 1000LL))
#define RCUTILS_NS_TO_MS(nanoseconds) ((nanoseconds) / (1000LL * 1000LL))
#define RCUTILS_NS_TO_US(nanoseconds) ((nanoseconds) / 1000LL)
#define RCL_S_TO_NS RCUTILS_S_TO_NS
#define RCL_MS_TO_NS RCUTILS_MS_TO_NS
#define RCL_US_TO_NS RCUTILS_US_TO_NS
#define RCL_NS_TO_S RCUTILS_NS_TO_S
#define RCL_NS_TO_MS RCUTILS_NS_TO_MS
#define RCL_NS_TO_US RCUTILS_NS_TO_US
}
// rcutils/logging_macros.h: every severity with every variant; the arguments that are
// not the message are dropped
template<class... A> void haros_rcutils_log(A&&... args);
#define HAROS_RCUTILS_LOG(...) ::haros_rcutils_log(__VA_ARGS__)
#define RCUTILS_STEADY_TIME rcutils_steady_time_now
#define RCUTILS_SYSTEM_TIME rcutils_system_time_now
#define RCUTILS_LOG_DEBUG(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_ONCE(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_ONCE_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_EXPRESSION(expression, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_EXPRESSION_NAMED(expression, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_FUNCTION(function, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_FUNCTION_NAMED(function, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_SKIPFIRST(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_SKIPFIRST_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_THROTTLE(time_source, duration, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_THROTTLE_NAMED(time_source, duration, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_SKIPFIRST_THROTTLE(time_source, duration, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_SKIPFIRST_THROTTLE_NAMED(time_source, duration, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO_ONCE(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO_ONCE_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO_EXPRESSION(expression, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO_EXPRESSION_NAMED(expression, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO_FUNCTION(function, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO_FUNCTION_NAMED(function, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO_SKIPFIRST(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO_SKIPFIRST_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO_THROTTLE(time_source, duration, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO_THROTTLE_NAMED(time_source, duration, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO_SKIPFIRST_THROTTLE(time_source, duration, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO_SKIPFIRST_THROTTLE_NAMED(time_source, duration, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN_ONCE(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN_ONCE_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN_EXPRESSION(expression, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN_EXPRESSION_NAMED(expression, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN_FUNCTION(function, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN_FUNCTION_NAMED(function, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN_SKIPFIRST(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN_SKIPFIRST_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN_THROTTLE(time_source, duration, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN_THROTTLE_NAMED(time_source, duration, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN_SKIPFIRST_THROTTLE(time_source, duration, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN_SKIPFIRST_THROTTLE_NAMED(time_source, duration, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR_ONCE(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR_ONCE_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR_EXPRESSION(expression, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR_EXPRESSION_NAMED(expression, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR_FUNCTION(function, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR_FUNCTION_NAMED(function, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR_SKIPFIRST(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR_SKIPFIRST_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR_THROTTLE(time_source, duration, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR_THROTTLE_NAMED(time_source, duration, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR_SKIPFIRST_THROTTLE(time_source, duration, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR_SKIPFIRST_THROTTLE_NAMED(time_source, duration, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL_ONCE(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL_ONCE_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL_EXPRESSION(expression, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL_EXPRESSION_NAMED(expression, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL_FUNCTION(function, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL_FUNCTION_NAMED(function, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL_SKIPFIRST(...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL_SKIPFIRST_NAMED(name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL_THROTTLE(time_source, duration, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL_THROTTLE_NAMED(time_source, duration, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL_SKIPFIRST_THROTTLE(time_source, duration, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL_SKIPFIRST_THROTTLE_NAMED(time_source, duration, name, ...) HAROS_RCUTILS_LOG(__VA_ARGS__)
// rcl/arguments.h, rcl/context.h: a process's ROS arguments parsed by hand (a simulator
// plugin gives its controller manager parameter files through the context's global
// arguments: gazebo_ros2_control, gz_ros2_control)
extern "C" {
typedef struct rcl_arguments_impl_s rcl_arguments_impl_t;
typedef struct rcl_arguments_s { rcl_arguments_impl_t* impl; } rcl_arguments_t;
#define RCL_ROS_ARGS_FLAG "--ros-args"
#define RCL_ROS_ARGS_EXPLICIT_END_TOKEN "--"
#define RCL_PARAM_FLAG "--param"
#define RCL_SHORT_PARAM_FLAG "-p"
#define RCL_PARAM_FILE_FLAG "--params-file"
#define RCL_REMAP_FLAG "--remap"
#define RCL_SHORT_REMAP_FLAG "-r"
#define RCL_ENCLAVE_FLAG "--enclave"
#define RCL_SHORT_ENCLAVE_FLAG "-e"
#define RCL_LOG_LEVEL_FLAG "--log-level"
#define RCL_EXTERNAL_LOG_CONFIG_FLAG "--log-config-file"
rcl_arguments_t rcl_get_zero_initialized_arguments(void);
rcl_ret_t rcl_parse_arguments(int argc, const char* const* argv, rcl_allocator_t allocator,
                              rcl_arguments_t* args_output);
int rcl_arguments_get_count_unparsed(const rcl_arguments_t* args);
int rcl_arguments_get_count_unparsed_ros(const rcl_arguments_t* args);
int rcl_arguments_get_param_files_count(const rcl_arguments_t* args);
rcl_ret_t rcl_arguments_get_param_files(const rcl_arguments_t* arguments,
                                        rcl_allocator_t allocator, char*** parameter_files);
rcl_ret_t rcl_remove_ros_arguments(const char* const* argv, const rcl_arguments_t* args,
                                   rcl_allocator_t allocator, int* nonros_argc,
                                   const char*** nonros_argv);
rcl_ret_t rcl_arguments_copy(const rcl_arguments_t* args, rcl_arguments_t* args_out);
rcl_ret_t rcl_arguments_fini(rcl_arguments_t* args);
typedef struct rcl_context_impl_s rcl_context_impl_t;
typedef struct rcl_context_s {
  rcl_arguments_t global_arguments;
  rcl_context_impl_t* impl;
  uint8_t instance_id_storage[8];
} rcl_context_t;
}
namespace rcpputils {
template<class C> std::string join(const C& items, const std::string& delimiter);
bool set_env_var(const char* name, const char* value);
std::string get_env_var(const char* name);
}
#endif
