// haros_arch stand-in
#include <ros/service_server.h>
