// haros_arch stand-in: see ../autoware_utils/haros_node_utilities.h
#include "../autoware_utils/haros_node_utilities.h"
