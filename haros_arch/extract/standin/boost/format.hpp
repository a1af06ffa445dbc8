// haros_arch stand-in: boost::format (declarations only); values.Scope reads
// ``(boost::format("%s/odom") % ns).str()`` with a literal format string
#ifndef HAROS_STANDIN_BOOST_FORMAT_HPP
#define HAROS_STANDIN_BOOST_FORMAT_HPP
#include <string>
#include <ostream>
namespace boost {
class format {
public:
  format();
  explicit format(const char* text);
  explicit format(const std::string& text);
  template<class T> format& operator%(const T& value);
  std::string str() const;
  std::size_t size() const;
  format& parse(const std::string& text);  // image_view's filename_format_.parse(fmt)
  format& clear();
};
std::string str(const format& f);
std::ostream& operator<<(std::ostream& out, const format& f);
namespace io {
class format_error {
public:
  const char* what() const;
};
}  // namespace io
}  // namespace boost
#endif
