// haros_arch stand-in for <sys/time.h>
#include "../haros_std.h"
