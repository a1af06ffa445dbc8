// haros_arch stand-in for <sys/types.h>
#include "../haros_std.h"
