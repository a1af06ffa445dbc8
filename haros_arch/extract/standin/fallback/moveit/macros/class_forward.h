// haros_arch stand-in: moveit_core's moveit/macros/class_forward.h (Humble and ROS 1 name)
#include "class_forward.hpp"
