// haros_arch stand-in for <ctype.h>
#include "haros_std.h"
