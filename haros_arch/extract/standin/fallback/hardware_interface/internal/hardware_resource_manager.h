// haros_arch stand-in: ROS 1 hardware_interface (see ../haros_ros1.h)
#include <hardware_interface/haros_ros1.h>
