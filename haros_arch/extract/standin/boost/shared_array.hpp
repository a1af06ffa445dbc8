// haros_arch stand-in: boost::shared_array (declarations only)
#ifndef HAROS_STANDIN_BOOST_SHARED_ARRAY_HPP
#define HAROS_STANDIN_BOOST_SHARED_ARRAY_HPP
#include <cstddef>
namespace boost {
template <class T> class shared_array {
public:
  shared_array();
  explicit shared_array(T* p);
  T& operator[](std::ptrdiff_t i) const;
  T* get() const;
  void reset(T* p = 0);
  long use_count() const;
  explicit operator bool() const;
};
}  // namespace boost
#endif
