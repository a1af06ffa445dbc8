// haros_arch stand-in for <termios.h>
#include "haros_std.h"
