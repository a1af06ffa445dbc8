// haros_arch stand-in: boost::bind with the placeholders in the global namespace
#ifndef HAROS_STANDIN_BOOST_BIND_HPP
#define HAROS_STANDIN_BOOST_BIND_HPP
#include <boost/bind/bind.hpp>
#ifndef BOOST_BIND_NO_PLACEHOLDERS
using namespace boost::placeholders;
#endif
#endif
