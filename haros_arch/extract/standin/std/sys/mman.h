// haros_arch stand-in for <sys/mman.h>
#include "../haros_std.h"
