// haros_arch stand-in for <sched.h>
#include "haros_std.h"
