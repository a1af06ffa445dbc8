// haros_arch stand-in: boost::scoped_ptr (declarations only)
#ifndef HAROS_STANDIN_BOOST_SCOPED_PTR_HPP
#define HAROS_STANDIN_BOOST_SCOPED_PTR_HPP
namespace boost {
template<class T> class scoped_ptr {
public:
  typedef T element_type;
  explicit scoped_ptr(T* p = 0);
  void reset(T* p = 0);
  T* operator->() const;
  T& operator*() const;
  T* get() const;
  explicit operator bool() const;
  void swap(scoped_ptr& other);
};
template<class T> bool operator==(const scoped_ptr<T>& p, decltype(nullptr));
template<class T> bool operator!=(const scoped_ptr<T>& p, decltype(nullptr));
}  // namespace boost
#endif
