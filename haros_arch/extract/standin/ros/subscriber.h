// haros_arch stand-in
#include <ros/publisher.h>
