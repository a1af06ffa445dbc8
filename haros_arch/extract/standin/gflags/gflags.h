// haros_arch stand-in: gflags (declarations only). A flag defined with DEFINE_<type>
// holds what the command line gives it, so its variable is declared without a value (a
// name taken from it is not known statically), not defined with the default.
// Declared in namespace google, as Debian's and Ubuntu's build does (glog's namespace too),
// and named in namespace gflags by using-declarations, as its gflags_gflags.h does.
#ifndef HAROS_STANDIN_GFLAGS_GFLAGS_H
#define HAROS_STANDIN_GFLAGS_GFLAGS_H
#include <cstdint>
#include <string>
#include <vector>
#define DEFINE_bool(name, value, help) extern bool FLAGS_##name
#define DEFINE_int32(name, value, help) extern int32_t FLAGS_##name
#define DEFINE_uint32(name, value, help) extern uint32_t FLAGS_##name
#define DEFINE_int64(name, value, help) extern int64_t FLAGS_##name
#define DEFINE_uint64(name, value, help) extern uint64_t FLAGS_##name
#define DEFINE_double(name, value, help) extern double FLAGS_##name
#define DEFINE_string(name, value, help) extern std::string FLAGS_##name
#define DECLARE_bool(name) extern bool FLAGS_##name
#define DECLARE_int32(name) extern int32_t FLAGS_##name
#define DECLARE_uint32(name) extern uint32_t FLAGS_##name
#define DECLARE_int64(name) extern int64_t FLAGS_##name
#define DECLARE_uint64(name) extern uint64_t FLAGS_##name
#define DECLARE_double(name) extern double FLAGS_##name
#define DECLARE_string(name) extern std::string FLAGS_##name
#define DEFINE_validator(name, validator) static const bool haros_##name##_validator = true
namespace google {
uint32_t ParseCommandLineFlags(int* argc, char*** argv, bool remove_flags);
uint32_t ParseCommandLineNonHelpFlags(int* argc, char*** argv, bool remove_flags);
void AllowCommandLineReparsing();
void SetUsageMessage(const std::string& usage);
void SetVersionString(const std::string& version);
const char* ProgramUsage();
void ShowUsageWithFlags(const char* argv0);
void ShutDownCommandLineFlags();
bool GetCommandLineOption(const char* name, std::string* value);
std::string SetCommandLineOption(const char* name, const char* value);
}  // namespace google
namespace gflags {
using google::ParseCommandLineFlags;
using google::ParseCommandLineNonHelpFlags;
using google::AllowCommandLineReparsing;
using google::SetUsageMessage;
using google::SetVersionString;
using google::ProgramUsage;
using google::ShowUsageWithFlags;
using google::ShutDownCommandLineFlags;
using google::GetCommandLineOption;
using google::SetCommandLineOption;
}  // namespace gflags
#endif
