// haros_arch stand-in for <stddef.h>
#include "haros_std.h"
