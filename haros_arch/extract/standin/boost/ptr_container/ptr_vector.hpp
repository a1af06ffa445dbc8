// haros_arch stand-in: boost::ptr_vector (declarations only), a vector that owns the
// objects its pointers hold; iterating it gives the objects, not the pointers
#ifndef HAROS_STANDIN_BOOST_PTR_VECTOR_HPP
#define HAROS_STANDIN_BOOST_PTR_VECTOR_HPP
#include <cstddef>
namespace boost {
template <class T> class ptr_vector {
public:
  typedef T value_type;
  typedef T& reference;
  typedef const T& const_reference;
  typedef std::size_t size_type;
  class iterator {
  public:
    T& operator*() const;
    T* operator->() const;
    iterator& operator++();
    iterator operator++(int);
    bool operator==(const iterator& other) const;
    bool operator!=(const iterator& other) const;
  };
  typedef iterator const_iterator;
  ptr_vector();
  explicit ptr_vector(size_type capacity);
  iterator begin() const;
  iterator end() const;
  reference operator[](size_type i) const;
  reference at(size_type i) const;
  reference front() const;
  reference back() const;
  size_type size() const;
  bool empty() const;
  void reserve(size_type n);
  void push_back(T* object);
  template <class P> void push_back(P object);  // a std::unique_ptr / auto_ptr
  void pop_back();
  iterator erase(iterator pos);
  void clear();
  T* replace(size_type i, T* object);
  bool is_null(size_type i) const;
};
}  // namespace boost
#endif
