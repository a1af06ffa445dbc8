// haros_arch stand-in for <malloc.h>
#include "haros_std.h"
