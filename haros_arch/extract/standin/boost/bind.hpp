// haros_arch stand-in: boost::bind (declarations only)
#ifndef HAROS_STANDIN_BOOST_BIND_HPP
#define HAROS_STANDIN_BOOST_BIND_HPP
namespace boost {
namespace _bi { struct bind_t { template<class... A> void operator()(A&&...) const; }; }
template<class F, class... A> _bi::bind_t bind(F f, A... args);
}  // namespace boost
namespace haros_standin { template<int I> struct arg {}; }
static const haros_standin::arg<1> _1 = {};
static const haros_standin::arg<2> _2 = {};
static const haros_standin::arg<3> _3 = {};
#endif
