// haros_arch stand-in for <sys/ioctl.h>
#include "../haros_std.h"
