// haros_arch stand-in: boost::circular_buffer (declarations only), a fixed-capacity
// sequence (spencer_people_tracking's nnt_node keeps its last tracks in one)
#ifndef HAROS_STANDIN_BOOST_CIRCULAR_BUFFER_HPP
#define HAROS_STANDIN_BOOST_CIRCULAR_BUFFER_HPP
#include <cstddef>
namespace boost {
template <class T, class Alloc = void> class circular_buffer {
public:
  typedef T value_type;
  typedef T* iterator;
  typedef const T* const_iterator;
  typedef T* reverse_iterator;  // a pointer, as the stand-in vector's (direction aside)
  typedef const T* const_reverse_iterator;
  typedef T& reference;
  typedef const T& const_reference;
  typedef std::size_t size_type;
  typedef std::size_t capacity_type;
  typedef std::ptrdiff_t difference_type;
  circular_buffer();
  explicit circular_buffer(capacity_type capacity);
  circular_buffer(capacity_type capacity, const T& item);
  iterator begin();
  const_iterator begin() const;
  iterator end();
  const_iterator end() const;
  reverse_iterator rbegin();
  const_reverse_iterator rbegin() const;
  reverse_iterator rend();
  const_reverse_iterator rend() const;
  reference operator[](size_type i);
  const_reference operator[](size_type i) const;
  reference at(size_type i);
  const_reference at(size_type i) const;
  reference front();
  const_reference front() const;
  reference back();
  const_reference back() const;
  size_type size() const;
  size_type capacity() const;
  size_type reserve() const;
  bool empty() const;
  bool full() const;
  void set_capacity(capacity_type capacity);
  void resize(size_type n, const T& item = T());
  void push_back(const T& item = T());
  void push_front(const T& item = T());
  void pop_back();
  void pop_front();
  iterator erase(iterator pos);
  iterator insert(iterator pos, const T& item);
  void clear();
  T* linearize();
};
template <class T> class circular_buffer_space_optimized : public circular_buffer<T> {
public:
  circular_buffer_space_optimized();
  explicit circular_buffer_space_optimized(std::size_t capacity);
};
}  // namespace boost
#endif
