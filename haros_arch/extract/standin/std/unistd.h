// haros_arch stand-in for <unistd.h>
#include "haros_std.h"
#include "haros_getopt.h"
