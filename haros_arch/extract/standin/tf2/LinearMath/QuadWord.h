// haros_arch stand-in
#include <tf2_ros/buffer.h>
