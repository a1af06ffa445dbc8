// haros_arch stand-in for <sys/select.h>
#include "../haros_std.h"
