// haros_arch stand-in: boost archives
#include <boost/serialization/haros_serialization.hpp>
