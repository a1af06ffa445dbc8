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
}
namespace rcpputils {
template<class C> std::string join(const C& items, const std::string& delimiter);
bool set_env_var(const char* name, const char* value);
std::string get_env_var(const char* name);
}
#endif
