// haros_arch stand-in for <errno.h>
#include "haros_std.h"
