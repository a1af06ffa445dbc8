// haros_arch stand-in for <pthread.h>
#include "haros_std.h"
