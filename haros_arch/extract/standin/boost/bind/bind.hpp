// haros_arch stand-in
#include <boost/bind.hpp>
