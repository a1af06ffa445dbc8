// haros_arch stand-in for <unistd.h>
#include "haros_std.h"
