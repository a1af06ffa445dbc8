// haros_arch stand-in for <sys/wait.h>
#include "../haros_std.h"
