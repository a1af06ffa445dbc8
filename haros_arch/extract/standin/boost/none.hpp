// haros_arch stand-in: boost::none (with boost::optional)
#include <boost/optional.hpp>
