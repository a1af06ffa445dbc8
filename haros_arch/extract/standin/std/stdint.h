// haros_arch stand-in for <stdint.h>
#include "haros_std.h"
