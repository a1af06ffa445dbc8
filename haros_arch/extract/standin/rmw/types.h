// haros_arch stand-in
#include <rmw/qos_profiles.h>
