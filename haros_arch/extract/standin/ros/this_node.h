// haros_arch stand-in
#include <ros/init.h>
