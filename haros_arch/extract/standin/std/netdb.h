// haros_arch stand-in for <netdb.h>
#include "haros_std.h"
