// haros_arch stand-in
#include <ros/time.h>
