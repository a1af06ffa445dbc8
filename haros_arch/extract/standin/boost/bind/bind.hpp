// haros_arch stand-in: boost::bind and boost::placeholders (declarations only)
#ifndef HAROS_STANDIN_BOOST_BIND_BIND_HPP
#define HAROS_STANDIN_BOOST_BIND_BIND_HPP
namespace boost {
namespace _bi { struct bind_t { template<class... A> void operator()(A&&...) const; }; }
template<class F, class... A> _bi::bind_t bind(F f, A... args);
template<class R, class F, class... A> _bi::bind_t bind(F f, A... args);
// a member or free function by its arity, as boost's own overloads take it: the
// address of an overloaded function (bind(&C::goalCB, this, _1) beside a goalCB of two
// parameters) names the one whose parameters the bound arguments fill
template<class R, class T, class O> _bi::bind_t bind(R (T::*f)(), O o);
template<class R, class T, class O> _bi::bind_t bind(R (T::*f)() const, O o);
template<class R> _bi::bind_t bind(R (*f)());
template<class R, class T, class B1, class O, class A1> _bi::bind_t bind(R (T::*f)(B1), O o, A1);
template<class R, class T, class B1, class O, class A1> _bi::bind_t bind(R (T::*f)(B1) const, O o, A1);
template<class R, class B1, class A1> _bi::bind_t bind(R (*f)(B1), A1);
template<class R, class T, class B1, class B2, class O, class A1, class A2> _bi::bind_t bind(R (T::*f)(B1, B2), O o, A1, A2);
template<class R, class T, class B1, class B2, class O, class A1, class A2> _bi::bind_t bind(R (T::*f)(B1, B2) const, O o, A1, A2);
template<class R, class B1, class B2, class A1, class A2> _bi::bind_t bind(R (*f)(B1, B2), A1, A2);
template<class R, class T, class B1, class B2, class B3, class O, class A1, class A2, class A3> _bi::bind_t bind(R (T::*f)(B1, B2, B3), O o, A1, A2, A3);
template<class R, class T, class B1, class B2, class B3, class O, class A1, class A2, class A3> _bi::bind_t bind(R (T::*f)(B1, B2, B3) const, O o, A1, A2, A3);
template<class R, class B1, class B2, class B3, class A1, class A2, class A3> _bi::bind_t bind(R (*f)(B1, B2, B3), A1, A2, A3);
template<class R, class T, class B1, class B2, class B3, class B4, class O, class A1, class A2, class A3, class A4> _bi::bind_t bind(R (T::*f)(B1, B2, B3, B4), O o, A1, A2, A3, A4);
template<class R, class T, class B1, class B2, class B3, class B4, class O, class A1, class A2, class A3, class A4> _bi::bind_t bind(R (T::*f)(B1, B2, B3, B4) const, O o, A1, A2, A3, A4);
template<class R, class B1, class B2, class B3, class B4, class A1, class A2, class A3, class A4> _bi::bind_t bind(R (*f)(B1, B2, B3, B4), A1, A2, A3, A4);
template<class R, class T, class B1, class B2, class B3, class B4, class B5, class O, class A1, class A2, class A3, class A4, class A5> _bi::bind_t bind(R (T::*f)(B1, B2, B3, B4, B5), O o, A1, A2, A3, A4, A5);
template<class R, class T, class B1, class B2, class B3, class B4, class B5, class O, class A1, class A2, class A3, class A4, class A5> _bi::bind_t bind(R (T::*f)(B1, B2, B3, B4, B5) const, O o, A1, A2, A3, A4, A5);
template<class R, class B1, class B2, class B3, class B4, class B5, class A1, class A2, class A3, class A4, class A5> _bi::bind_t bind(R (*f)(B1, B2, B3, B4, B5), A1, A2, A3, A4, A5);
template<class R, class T, class B1, class B2, class B3, class B4, class B5, class B6, class O, class A1, class A2, class A3, class A4, class A5, class A6> _bi::bind_t bind(R (T::*f)(B1, B2, B3, B4, B5, B6), O o, A1, A2, A3, A4, A5, A6);
template<class R, class T, class B1, class B2, class B3, class B4, class B5, class B6, class O, class A1, class A2, class A3, class A4, class A5, class A6> _bi::bind_t bind(R (T::*f)(B1, B2, B3, B4, B5, B6) const, O o, A1, A2, A3, A4, A5, A6);
template<class R, class B1, class B2, class B3, class B4, class B5, class B6, class A1, class A2, class A3, class A4, class A5, class A6> _bi::bind_t bind(R (*f)(B1, B2, B3, B4, B5, B6), A1, A2, A3, A4, A5, A6);
// anything else (a member function of seven or more parameters, a function object)
template<class F, class... A> _bi::bind_t bind(F f, A... a);
template<int I> struct arg {};
namespace placeholders {
static const arg<1> _1 = {};
static const arg<2> _2 = {};
static const arg<3> _3 = {};
static const arg<4> _4 = {};
// boost::bind's nine (rtabmap's message_filters callbacks of five to nine messages)
static const arg<5> _5 = {};
static const arg<6> _6 = {};
static const arg<7> _7 = {};
static const arg<8> _8 = {};
static const arg<9> _9 = {};
}
template<class T> struct reference_wrapper { reference_wrapper(T& t); operator T&() const; };
template<class T> reference_wrapper<T> ref(T& t);
template<class T> reference_wrapper<const T> cref(const T& t);
}  // namespace boost
#endif
