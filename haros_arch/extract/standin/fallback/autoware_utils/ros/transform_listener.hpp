// haros_arch stand-in: see ../haros_node_utilities.h
#include "../haros_node_utilities.h"
