// haros_arch stand-in: ROS 1 controller_interface (see haros_ros1.h)
#include <controller_interface/haros_ros1.h>
