// haros_arch stand-in: boost::array (declarations only), the type of a ROS 1 message's
// fixed-size array field (gencpp: ``float64[9] K`` is ``boost::array<double, 9> K``)
#ifndef HAROS_STANDIN_BOOST_ARRAY_HPP
#define HAROS_STANDIN_BOOST_ARRAY_HPP
#include <cstddef>
namespace boost {
template <class T, std::size_t N> class array {
public:
  T elems[N];  // public, as boost's: an aggregate (``boost::array<double, 9>{{...}}``)
  typedef T value_type;
  typedef T* iterator;
  typedef const T* const_iterator;
  typedef T& reference;
  typedef const T& const_reference;
  typedef std::size_t size_type;
  typedef std::ptrdiff_t difference_type;
  iterator begin();
  const_iterator begin() const;
  const_iterator cbegin() const;
  iterator end();
  const_iterator end() const;
  const_iterator cend() const;
  reference operator[](size_type i);
  const_reference operator[](size_type i) const;
  reference at(size_type i);
  const_reference at(size_type i) const;
  reference front();
  const_reference front() const;
  reference back();
  const_reference back() const;
  static constexpr size_type size() { return N; }
  static constexpr bool empty() { return N == 0; }
  static constexpr size_type max_size() { return N; }
  T* data();
  const T* data() const;
  T* c_array();
  void fill(const T& value);
  void assign(const T& value);
  void swap(array& other);
};
template <class T, std::size_t N> bool operator==(const array<T, N>&, const array<T, N>&);
template <class T, std::size_t N> bool operator!=(const array<T, N>&, const array<T, N>&);
}  // namespace boost
#endif
