// haros_arch stand-in for <assert.h>
#include "haros_std.h"
