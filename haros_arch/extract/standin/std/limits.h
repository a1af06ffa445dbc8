// haros_arch stand-in for <limits.h>
#include "haros_std.h"
