// haros_arch stand-in for <math.h>
#include "haros_std.h"
