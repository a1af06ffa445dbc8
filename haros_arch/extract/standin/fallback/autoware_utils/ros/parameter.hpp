// haros_arch stand-in: see ../haros_parameter.h
#include "../haros_parameter.h"
