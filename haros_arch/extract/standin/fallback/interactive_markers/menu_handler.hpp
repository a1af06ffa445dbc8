// haros_arch stand-in: ROS 2 interactive_markers' MenuHandler (see menu_handler.h)
#include <interactive_markers/interactive_marker_server.hpp>
#include <interactive_markers/menu_handler.h>
