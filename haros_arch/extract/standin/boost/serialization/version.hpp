// haros_arch stand-in: boost serialization
#include <boost/serialization/haros_serialization.hpp>
