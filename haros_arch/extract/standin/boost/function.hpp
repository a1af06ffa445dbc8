// haros_arch stand-in: boost::function (declarations only)
#ifndef HAROS_STANDIN_BOOST_FUNCTION_HPP
#define HAROS_STANDIN_BOOST_FUNCTION_HPP
namespace boost {
template<class Signature> class function;
template<class R, class... A> class function<R(A...)> {
public:
  function();
  template<class F> function(F f);
  R operator()(A... args) const;
  void clear();
  bool empty() const;
  explicit operator bool() const;
};
}  // namespace boost
#endif
