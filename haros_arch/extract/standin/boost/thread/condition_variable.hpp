// haros_arch stand-in
#include <boost/thread.hpp>
