// haros_arch stand-in for <dirent.h>
#include "haros_std.h"
