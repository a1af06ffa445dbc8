// haros_arch stand-in for <signal.h>
#include "haros_std.h"
