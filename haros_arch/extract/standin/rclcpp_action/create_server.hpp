// haros_arch stand-in
#include <rclcpp_action/rclcpp_action.hpp>
