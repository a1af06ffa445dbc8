// haros_arch stand-in for <sys/ipc.h>
#include "../haros_std.h"
