// haros_arch stand-in for <stdlib.h>
#include "haros_std.h"
