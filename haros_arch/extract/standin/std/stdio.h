// haros_arch stand-in for <stdio.h>
#include "haros_std.h"
