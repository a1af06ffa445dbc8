// haros_arch stand-in: rosconsole logging macros
#ifndef HAROS_STANDIN_ROS_CONSOLE_H
#define HAROS_STANDIN_ROS_CONSOLE_H
#include <sstream>
namespace ros { namespace console {
void haros_log(const char* fmt, ...);
enum Level { Debug, Info, Warn, Error, Fatal };
bool set_logger_level(const std::string& name, Level level);
} }
#define HAROS_STANDIN_LOG(...) ::ros::console::haros_log(__VA_ARGS__)
#define HAROS_STANDIN_STREAM(args) do { std::stringstream haros_ss; haros_ss << args; } while (0)
#define ROS_DEBUG(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_INFO(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_WARN(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_ERROR(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_FATAL(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_DEBUG_STREAM(args) HAROS_STANDIN_STREAM(args)
#define ROS_INFO_STREAM(args) HAROS_STANDIN_STREAM(args)
#define ROS_WARN_STREAM(args) HAROS_STANDIN_STREAM(args)
#define ROS_ERROR_STREAM(args) HAROS_STANDIN_STREAM(args)
#define ROS_FATAL_STREAM(args) HAROS_STANDIN_STREAM(args)
#define ROS_DEBUG_NAMED(name, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_INFO_NAMED(name, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_WARN_NAMED(name, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_ERROR_NAMED(name, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_FATAL_NAMED(name, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_DEBUG_COND(cond, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_INFO_COND(cond, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_WARN_COND(cond, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_ERROR_COND(cond, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_FATAL_COND(cond, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_DEBUG_ONCE(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_INFO_ONCE(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_WARN_ONCE(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_ERROR_ONCE(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_FATAL_ONCE(...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_DEBUG_THROTTLE(period, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_INFO_THROTTLE(period, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_WARN_THROTTLE(period, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_ERROR_THROTTLE(period, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_FATAL_THROTTLE(period, ...) HAROS_STANDIN_LOG(__VA_ARGS__)
#define ROS_DEBUG_STREAM_NAMED(name, args) HAROS_STANDIN_STREAM(args)
#define ROS_INFO_STREAM_NAMED(name, args) HAROS_STANDIN_STREAM(args)
#define ROS_WARN_STREAM_NAMED(name, args) HAROS_STANDIN_STREAM(args)
#define ROS_ERROR_STREAM_NAMED(name, args) HAROS_STANDIN_STREAM(args)
#define ROS_FATAL_STREAM_NAMED(name, args) HAROS_STANDIN_STREAM(args)
#define ROS_DEBUG_STREAM_THROTTLE(period, args) HAROS_STANDIN_STREAM(args)
#define ROS_INFO_STREAM_THROTTLE(period, args) HAROS_STANDIN_STREAM(args)
#define ROS_WARN_STREAM_THROTTLE(period, args) HAROS_STANDIN_STREAM(args)
#define ROS_ERROR_STREAM_THROTTLE(period, args) HAROS_STANDIN_STREAM(args)
#define ROS_FATAL_STREAM_THROTTLE(period, args) HAROS_STANDIN_STREAM(args)
#define ROS_ASSERT(cond) ((void)(cond))
#define ROS_BREAK() ((void)0)
#endif
