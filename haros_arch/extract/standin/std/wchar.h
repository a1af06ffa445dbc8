// haros_arch stand-in for <wchar.h>
#include "haros_std.h"
