// haros_arch stand-in for <netinet/in.h>
#include "../haros_std.h"
