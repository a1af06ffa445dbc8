// haros_arch stand-in
#include "class_list_macros.hpp"
