// haros_arch stand-in: boost::hash and its helpers (declarations only); every
// boost/functional/hash/... and boost/container_hash/... header stands in as this one.
// No ROS call.
#ifndef HAROS_STANDIN_BOOST_FUNCTIONAL_HASH_HPP
#define HAROS_STANDIN_BOOST_FUNCTIONAL_HASH_HPP
#include <cstddef>
namespace boost {
template <class T> struct hash {
  typedef T argument_type;
  typedef std::size_t result_type;
  std::size_t operator()(const T& value) const;
};
template <class T> std::size_t hash_value(const T& value);
template <class T> void hash_combine(std::size_t& seed, const T& value);
template <class It> std::size_t hash_range(It first, It last);
template <class It> void hash_range(std::size_t& seed, It first, It last);
}  // namespace boost
#endif
