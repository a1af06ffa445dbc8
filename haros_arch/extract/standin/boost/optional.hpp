// haros_arch stand-in: boost::optional and boost::none (declarations only); every
// boost/optional/... header and boost/none.hpp stand in as this one
#ifndef HAROS_STANDIN_BOOST_OPTIONAL_HPP
#define HAROS_STANDIN_BOOST_OPTIONAL_HPP
#include <utility>
namespace boost {
struct none_t { explicit constexpr none_t(int) {} };
extern const none_t none;
template<class T> class optional {
public:
  typedef T value_type;
  optional() noexcept;
  optional(none_t) noexcept;
  optional(const T& v);
  optional(T&& v);
  optional(bool condition, const T& v);
  template<class U> optional(const optional<U>& other);
  optional& operator=(none_t) noexcept;
  optional& operator=(const optional& other);
  template<class U> optional& operator=(U&& v);
  T& get();
  const T& get() const;
  T* get_ptr();
  const T* get_ptr() const;
  T& value();
  const T& value() const;
  template<class U> T value_or(U&& v) const;
  template<class U> T get_value_or(U&& v) const;
  T* operator->();
  const T* operator->() const;
  T& operator*();
  const T& operator*() const;
  bool is_initialized() const;
  bool has_value() const;
  bool operator!() const;
  explicit operator bool() const;
  void reset();
  template<class... A> void emplace(A&&... args);
};
template<class T> optional<T> make_optional(const T& v);
template<class T> optional<T> make_optional(bool condition, const T& v);
template<class T> bool operator==(const optional<T>& o, none_t);
template<class T> bool operator!=(const optional<T>& o, none_t);
template<class T> bool operator==(none_t, const optional<T>& o);
template<class T> bool operator!=(none_t, const optional<T>& o);
template<class T> bool operator==(const optional<T>& a, const optional<T>& b);
template<class T> bool operator!=(const optional<T>& a, const optional<T>& b);
template<class T> bool operator<(const optional<T>& a, const optional<T>& b);
template<class T> T& get(optional<T>& o);
template<class T> const T& get(const optional<T>& o);
}  // namespace boost
#endif
