// haros_arch stand-in for <stdbool.h>
#include "haros_std.h"
