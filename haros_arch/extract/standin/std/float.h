// haros_arch stand-in for <float.h>
#include "haros_std.h"
