// haros_arch stand-in for <sys/socket.h>
#include "../haros_std.h"
