// haros_arch stand-in: boost::system's error codes (declarations only). Boost.Asio's
// handlers take a ``const boost::system::error_code&``; without this, ``boost::system``
// named the C library's ``system`` function, an error in every such handler (rosserial's
// sessions, serial drivers), which made their ROS calls uncertain.
#ifndef HAROS_STANDIN_BOOST_SYSTEM_ERROR_CODE_HPP
#define HAROS_STANDIN_BOOST_SYSTEM_ERROR_CODE_HPP
#include <string>
#include <ostream>
namespace boost {
namespace system {
class error_category {
 public:
  const char* name() const;
  std::string message(int ev) const;
};
const error_category& system_category();
const error_category& generic_category();
class error_code {
 public:
  error_code();
  error_code(int value, const error_category& category);
  template<class E> error_code(E e);
  int value() const;
  const error_category& category() const;
  std::string message() const;
  void clear();
  explicit operator bool() const;
  bool operator!() const;
};
template<class E> bool operator==(const error_code& a, E b);
template<class E> bool operator!=(const error_code& a, E b);
std::ostream& operator<<(std::ostream& out, const error_code& code);
class system_error {
 public:
  explicit system_error(const error_code& code);
  system_error(const error_code& code, const std::string& what);
  const error_code& code() const;
  const char* what() const;
};
namespace errc {
enum errc_t { success = 0, operation_canceled = 125, timed_out = 110 };
}  // namespace errc
}  // namespace system
}  // namespace boost
#endif
