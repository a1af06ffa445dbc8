// haros_arch stand-in
#include <boost/shared_ptr.hpp>
