// haros_arch stand-in for <strings.h>
#include "haros_std.h"
