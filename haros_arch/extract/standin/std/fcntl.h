// haros_arch stand-in for <fcntl.h>
#include "haros_std.h"
