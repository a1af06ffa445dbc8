// haros_arch stand-in: rosbag (see bag.h)
#include <rosbag/bag.h>
