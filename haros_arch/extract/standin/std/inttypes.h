// haros_arch stand-in for <inttypes.h>
#include "haros_std.h"
