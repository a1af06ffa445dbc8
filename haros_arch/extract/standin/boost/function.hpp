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
  // boost's safe-bool: ``if (cb_ && output)``, ``if (!cb_)``
  explicit operator bool() const;
  bool empty() const;
  void clear();
};
}  // namespace boost
#endif
