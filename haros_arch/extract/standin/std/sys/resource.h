// haros_arch stand-in for <sys/resource.h>
#include "../haros_std.h"
