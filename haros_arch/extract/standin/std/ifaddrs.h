// haros_arch stand-in for <ifaddrs.h>
#include "haros_std.h"
