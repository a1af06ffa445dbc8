// haros_arch stand-in for <dlfcn.h>
#include "haros_std.h"
