// haros_arch stand-in: boost::system::system_error (see error_code.hpp)
#include <boost/system/error_code.hpp>
