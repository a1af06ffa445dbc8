// haros_arch stand-in for <sys/stat.h>
#include "../haros_std.h"
