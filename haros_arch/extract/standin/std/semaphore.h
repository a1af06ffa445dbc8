// haros_arch stand-in for <semaphore.h>
#include "haros_std.h"
