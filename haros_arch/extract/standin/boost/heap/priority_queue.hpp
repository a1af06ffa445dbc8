// haros_arch stand-in: Boost.Heap (declarations only), which every boost/heap/... header
// stands in as: the priority queue and the mutable heaps (fibonacci, binomial, pairing,
// skew, d-ary) with their options. tauv's state_estimation_cpp keeps its sensor messages
// in ``boost::heap::priority_queue<Ptr, boost::heap::compare<std::greater_equal<Ptr>>>``
// members; without these the members were errors, and so the constructor's subscriptions.
#ifndef HAROS_STANDIN_BOOST_HEAP_HPP
#define HAROS_STANDIN_BOOST_HEAP_HPP
#include <cstddef>
#include <functional>
namespace boost {
namespace heap {
// the options: each a type that names its argument
template<class T> struct compare {};
template<class T> struct allocator {};
template<bool B> struct stable {};
template<bool B> struct mutable_ {};
template<bool B> struct constant_time_size {};
template<class T> struct stability_counter_type {};
template<unsigned N> struct arity {};
template<bool B> struct store_parent_pointer {};
// what every heap of Boost.Heap offers (its priority_queue's interface)
template<class T> class haros_heap_base {
public:
  typedef T value_type;
  typedef std::size_t size_type;
  typedef const T& const_reference;
  typedef const T* iterator;
  typedef const T* const_iterator;
  bool empty() const;
  size_type size() const;
  size_type max_size() const;
  void clear();
  const_reference top() const;
  void pop();
  void reserve(size_type n);
  iterator begin() const;
  iterator end() const;
  template<class... A> void emplace(A&&... args);
};
template<class T, class... Options> class priority_queue : public haros_heap_base<T> {
public:
  priority_queue();
  void push(const T& value);
  void swap(priority_queue& other);
};
// the mutable heaps: ``push`` gives a handle that ``update`` / ``increase`` / ``decrease``
// / ``erase`` take
template<class T> class haros_mutable_heap : public haros_heap_base<T> {
public:
  struct handle_type { T& operator*() const; };
  handle_type push(const T& value);
  void update(handle_type handle, const T& value);
  void update(handle_type handle);
  void increase(handle_type handle, const T& value);
  void increase(handle_type handle);
  void decrease(handle_type handle, const T& value);
  void decrease(handle_type handle);
  void erase(handle_type handle);
  static handle_type s_handle_from_iterator(const T* it);
};
template<class T, class... Options> class fibonacci_heap : public haros_mutable_heap<T> {};
template<class T, class... Options> class binomial_heap : public haros_mutable_heap<T> {};
template<class T, class... Options> class pairing_heap : public haros_mutable_heap<T> {};
template<class T, class... Options> class skew_heap : public haros_mutable_heap<T> {};
template<class T, class... Options> class d_ary_heap : public haros_mutable_heap<T> {};
}  // namespace heap
}  // namespace boost
#endif
