// haros_arch stand-in: glog (declarations only). LOG / VLOG / CHECK and their variants
// give a stream and never decide anything a ROS call depends on; the check macros take
// their operands by reference, so what the code compares needs no operator here.
// Every glog header (raw_logging.h, stl_logging.h, ...) stands in as this one.
#ifndef HAROS_STANDIN_GLOG_LOGGING_H
#define HAROS_STANDIN_GLOG_LOGGING_H
#include <cstddef>
#include <ctime>
#include <ostream>
#include <string>
#include <vector>
#include <gflags/gflags.h>

namespace google {
typedef int LogSeverity;
const int GLOG_INFO = 0, GLOG_WARNING = 1, GLOG_ERROR = 2, GLOG_FATAL = 3;
const int INFO = GLOG_INFO, WARNING = GLOG_WARNING, ERROR = GLOG_ERROR, FATAL = GLOG_FATAL;
const int NUM_SEVERITIES = 4;
const int GLOG_DFATAL = GLOG_ERROR;
extern const char* const LogSeverityNames[NUM_SEVERITIES];
struct haros_counter_t {};
extern haros_counter_t COUNTER;
std::ostream& operator<<(std::ostream& os, const haros_counter_t&);

void InitGoogleLogging(const char* argv0);
bool IsGoogleLoggingInitialized();
void ShutdownGoogleLogging();
void InstallFailureSignalHandler();
void InstallFailureWriter(void (*writer)(const char* data, std::size_t size));
void InstallFailureFunction(void (*fail_func)());
void SetStderrLogging(LogSeverity min_severity);
void SetLogDestination(LogSeverity severity, const char* base_filename);
void SetLogFilenameExtension(const char* filename_extension);
void SetLogSymlink(LogSeverity severity, const char* symlink_basename);
void LogToStderr();
void FlushLogFiles(LogSeverity min_severity);
int SetVLOGLevel(const char* module_pattern, int log_level);
const std::vector<std::string>& GetLoggingDirectories();

class LogSink {
 public:
  virtual ~LogSink();
  virtual void send(LogSeverity severity, const char* full_filename,
                    const char* base_filename, int line, const struct ::tm* tm_time,
                    const char* message, std::size_t message_len);
  virtual void WaitTillSent();
  static std::string ToString(LogSeverity severity, const char* file, int line,
                              const struct ::tm* tm_time, const char* message,
                              std::size_t message_len);
};
void AddLogSink(LogSink* destination);
void RemoveLogSink(LogSink* destination);

class LogMessage {
 public:
  LogMessage(const char* file, int line);
  LogMessage(const char* file, int line, LogSeverity severity);
  ~LogMessage();
  std::ostream& stream();
};
class LogMessageFatal : public LogMessage {
 public:
  LogMessageFatal(const char* file, int line);
};

std::ostream& haros_log(LogSeverity severity);
std::ostream& haros_log_if(LogSeverity severity, bool condition);
std::ostream& haros_vlog(int level);
template <class C> std::ostream& haros_check(const C& condition);
// DCHECK: CHECK in a debug build only; a release build (NDEBUG) never evaluates it
template <class C> std::ostream& haros_dcheck(const C& condition);
template <class A, class B> std::ostream& haros_check_op(const A& a, const B& b);
template <class A, class B, class M> std::ostream& haros_check_near(const A& a, const B& b,
                                                                    const M& margin);
template <class T> T&& haros_check_notnull(T&& value);
bool haros_vlog_is_on(int level);
void haros_raw_log(LogSeverity severity, const char* format, ...);
}  // namespace google

extern bool FLAGS_logtostderr;
extern bool FLAGS_alsologtostderr;
extern bool FLAGS_colorlogtostderr;
extern bool FLAGS_log_prefix;
extern bool FLAGS_stop_logging_if_full_disk;
extern int32_t FLAGS_stderrthreshold;
extern int32_t FLAGS_minloglevel;
extern int32_t FLAGS_logbuflevel;
extern int32_t FLAGS_logbufsecs;
extern int32_t FLAGS_v;
extern int32_t FLAGS_max_log_size;
extern std::string FLAGS_log_dir;
extern std::string FLAGS_vmodule;

#define LOG(severity) ::google::haros_log(::google::GLOG_##severity)
#define SYSLOG(severity) LOG(severity)
#define PLOG(severity) LOG(severity)
#define DLOG(severity) LOG(severity)
#define LOG_IF(severity, condition) ::google::haros_log_if(::google::GLOG_##severity, (condition))
#define SYSLOG_IF(severity, condition) LOG_IF(severity, condition)
#define PLOG_IF(severity, condition) LOG_IF(severity, condition)
#define DLOG_IF(severity, condition) LOG_IF(severity, condition)
#define LOG_EVERY_N(severity, n) LOG(severity)
#define LOG_EVERY_T(severity, seconds) LOG(severity)
#define LOG_FIRST_N(severity, n) LOG(severity)
#define LOG_IF_EVERY_N(severity, condition, n) LOG_IF(severity, condition)
#define SYSLOG_EVERY_N(severity, n) LOG(severity)
#define PLOG_EVERY_N(severity, n) LOG(severity)
#define DLOG_EVERY_N(severity, n) LOG(severity)
#define DLOG_FIRST_N(severity, n) LOG(severity)
#define DLOG_IF_EVERY_N(severity, condition, n) LOG_IF(severity, condition)
#define LOG_ASSERT(condition) ::google::haros_check(condition)
#define DLOG_ASSERT(condition) LOG_ASSERT(condition)
#define LOG_STRING(severity, outvec) LOG(severity)
#define LOG_TO_SINK(sink, severity) LOG(severity)
#define LOG_TO_SINK_BUT_NOT_TO_LOGFILE(sink, severity) LOG(severity)
#define LOG_TO_STRING(severity, message) LOG(severity)
#define VLOG(level) ::google::haros_vlog(level)
#define DVLOG(level) VLOG(level)
#define VLOG_IF(level, condition) ::google::haros_log_if(::google::GLOG_INFO, (condition))
#define VLOG_EVERY_N(level, n) VLOG(level)
#define VLOG_IF_EVERY_N(level, condition, n) VLOG_IF(level, condition)
#define VLOG_IS_ON(level) ::google::haros_vlog_is_on(level)
#define RAW_LOG(severity, ...) ::google::haros_raw_log(::google::GLOG_##severity, __VA_ARGS__)
#define RAW_VLOG(level, ...) ::google::haros_raw_log(::google::GLOG_INFO, __VA_ARGS__)
#define RAW_CHECK(condition, message) ::google::haros_check(condition)
#define RAW_DCHECK(condition, message) ::google::haros_dcheck(condition)

#define CHECK(condition) ::google::haros_check(condition)
#define PCHECK(condition) CHECK(condition)
#define CHECK_EQ(a, b) ::google::haros_check_op((a), (b))
#define CHECK_NE(a, b) ::google::haros_check_op((a), (b))
#define CHECK_LE(a, b) ::google::haros_check_op((a), (b))
#define CHECK_LT(a, b) ::google::haros_check_op((a), (b))
#define CHECK_GE(a, b) ::google::haros_check_op((a), (b))
#define CHECK_GT(a, b) ::google::haros_check_op((a), (b))
#define CHECK_STREQ(a, b) ::google::haros_check_op((a), (b))
#define CHECK_STRNE(a, b) ::google::haros_check_op((a), (b))
#define CHECK_STRCASEEQ(a, b) ::google::haros_check_op((a), (b))
#define CHECK_STRCASENE(a, b) ::google::haros_check_op((a), (b))
#define CHECK_INDEX(i, n) ::google::haros_check_op((i), (n))
#define CHECK_BOUND(b, n) ::google::haros_check_op((b), (n))
#define CHECK_DOUBLE_EQ(a, b) ::google::haros_check_op((a), (b))
#define CHECK_NEAR(a, b, margin) ::google::haros_check_near((a), (b), (margin))
#define CHECK_ERR(invocation) ::google::haros_check(invocation)
#define CHECK_NOTNULL(value) ::google::haros_check_notnull(value)
#define DCHECK(condition) ::google::haros_dcheck(condition)
#define DCHECK_EQ(a, b) CHECK_EQ(a, b)
#define DCHECK_NE(a, b) CHECK_NE(a, b)
#define DCHECK_LE(a, b) CHECK_LE(a, b)
#define DCHECK_LT(a, b) CHECK_LT(a, b)
#define DCHECK_GE(a, b) CHECK_GE(a, b)
#define DCHECK_GT(a, b) CHECK_GT(a, b)
#define DCHECK_STREQ(a, b) CHECK_STREQ(a, b)
#define DCHECK_STRNE(a, b) CHECK_STRNE(a, b)
#define DCHECK_STRCASEEQ(a, b) CHECK_STRCASEEQ(a, b)
#define DCHECK_STRCASENE(a, b) CHECK_STRCASENE(a, b)
#define DCHECK_NOTNULL(value) CHECK_NOTNULL(value)
#define DCHECK_IS_ON() 1
#endif
