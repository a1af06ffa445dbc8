// haros_arch stand-in for <poll.h>
#include "haros_std.h"
