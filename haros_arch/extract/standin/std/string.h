// haros_arch stand-in for <string.h>
#include "haros_std.h"
