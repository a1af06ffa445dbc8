// haros_arch stand-in: the {fmt} library (every ``fmt/...`` header stands in as this
// one). Declarations only; values.Scope reads ``fmt::format`` with a literal format
// string (``fmt::format("bridge.{}.qos", topic)``).
#ifndef HAROS_STANDIN_FMT_FORMAT_H
#define HAROS_STANDIN_FMT_FORMAT_H
#include <string>
#include <cstdio>
// fmt/compile.h's compiled and fmt/format.h's checked format strings: the literal, as
// the format reads it
#define FMT_COMPILE(text) text
#define FMT_STRING(text) text
namespace fmt {
template<class... Args> std::string format(const char* text, const Args&... args);
template<class... Args> std::string format(const std::string& text, const Args&... args);
struct runtime_format_string { const char* text; };
runtime_format_string runtime(const char* text);
runtime_format_string runtime(const std::string& text);
template<class... Args> std::string format(runtime_format_string text, const Args&... args);
template<class... Args> void print(const char* text, const Args&... args);
template<class... Args> void print(std::FILE* f, const char* text, const Args&... args);
template<class... Args> void println(const char* text, const Args&... args);
template<class T> std::string to_string(const T& value);
template<class Range> std::string join(const Range& range, const char* sep);
template<class It> std::string join(It begin, It end, const char* sep);
template<class T> const void* ptr(const T* p);
class format_error {
public:
  explicit format_error(const char* what);
  const char* what() const;
};
}  // namespace fmt
#endif
