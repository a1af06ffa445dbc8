// haros_arch stand-in for <sys/shm.h>
#include "../haros_std.h"
