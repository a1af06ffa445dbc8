// haros_arch stand-in: boost::shared_ptr (declarations only)
#ifndef HAROS_STANDIN_BOOST_SHARED_PTR_HPP
#define HAROS_STANDIN_BOOST_SHARED_PTR_HPP
namespace boost {
template<class T> class shared_ptr {
public:
  typedef T element_type;
  shared_ptr();
  shared_ptr(decltype(nullptr));  // ``boost::shared_ptr<T> p_ = nullptr;`` (Boost 1.53 on)
  template<class Y> explicit shared_ptr(Y* p);
  template<class Y> shared_ptr(const shared_ptr<Y>& other);
  T* operator->() const;
  template<class U = T> U& operator*() const;
  T* get() const;
  void reset();
  template<class Y> void reset(Y* p);
  explicit operator bool() const;
  long use_count() const;  // ``if (msg.use_count() > 0)`` of a waitForMessage result
  bool unique() const;
  void swap(shared_ptr& other);
};
// comparisons: with another pointer, nullptr and NULL (``p != NULL``)
template<class T, class U> bool operator==(const shared_ptr<T>& a, const shared_ptr<U>& b);
template<class T, class U> bool operator!=(const shared_ptr<T>& a, const shared_ptr<U>& b);
template<class T> bool operator==(const shared_ptr<T>& a, decltype(nullptr));
template<class T> bool operator!=(const shared_ptr<T>& a, decltype(nullptr));
template<class T> bool operator==(const shared_ptr<T>& a, long);
template<class T> bool operator!=(const shared_ptr<T>& a, long);
template<class T, class... A> shared_ptr<T> make_shared(A&&... args);
template<class T, class U> shared_ptr<T> static_pointer_cast(const shared_ptr<U>& p);
template<class T, class U> shared_ptr<T> dynamic_pointer_cast(const shared_ptr<U>& p);
template<class T, class U> shared_ptr<T> const_pointer_cast(const shared_ptr<U>& p);
}  // namespace boost
#endif
