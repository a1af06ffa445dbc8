// haros_arch stand-in for <pwd.h>
#include "haros_std.h"
