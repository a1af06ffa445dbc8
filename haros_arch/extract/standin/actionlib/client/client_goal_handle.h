// haros_arch stand-in
#include <actionlib/server/simple_action_server.h>
