// haros_arch stand-in for <time.h>
#include "haros_std.h"
