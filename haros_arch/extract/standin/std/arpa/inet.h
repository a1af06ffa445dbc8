// haros_arch stand-in for <arpa/inet.h>
#include "../haros_std.h"
