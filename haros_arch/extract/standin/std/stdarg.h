// haros_arch stand-in for <stdarg.h>
#include "haros_std.h"
