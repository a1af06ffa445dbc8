// haros_arch stand-in: boost::enable_shared_from_this (declarations only)
#ifndef HAROS_STANDIN_BOOST_ENABLE_SHARED_FROM_THIS_HPP
#define HAROS_STANDIN_BOOST_ENABLE_SHARED_FROM_THIS_HPP
#include <boost/shared_ptr.hpp>
namespace boost {
template<class T> class enable_shared_from_this {
public:
  shared_ptr<T> shared_from_this();
  shared_ptr<const T> shared_from_this() const;
};
}  // namespace boost
#endif
