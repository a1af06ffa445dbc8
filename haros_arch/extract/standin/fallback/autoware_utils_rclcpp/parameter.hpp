// haros_arch stand-in: see ../autoware_utils/haros_parameter.h
#include "../autoware_utils/haros_parameter.h"
