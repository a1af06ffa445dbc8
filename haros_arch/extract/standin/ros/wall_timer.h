// haros_arch stand-in
#include <ros/timer.h>
