// haros_arch stand-in: boost::bind and boost::placeholders (declarations only)
#ifndef HAROS_STANDIN_BOOST_BIND_BIND_HPP
#define HAROS_STANDIN_BOOST_BIND_BIND_HPP
namespace boost {
namespace _bi { struct bind_t { template<class... A> void operator()(A&&...) const; }; }
template<class F, class... A> _bi::bind_t bind(F f, A... args);
template<class R, class F, class... A> _bi::bind_t bind(F f, A... args);
template<int I> struct arg {};
namespace placeholders {
static const arg<1> _1 = {};
static const arg<2> _2 = {};
static const arg<3> _3 = {};
static const arg<4> _4 = {};
}
template<class T> struct reference_wrapper { reference_wrapper(T& t); operator T&() const; };
template<class T> reference_wrapper<T> ref(T& t);
template<class T> reference_wrapper<const T> cref(const T& t);
}  // namespace boost
#endif
