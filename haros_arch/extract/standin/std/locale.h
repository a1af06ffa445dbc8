// haros_arch stand-in for <locale.h>
#include "haros_std.h"
