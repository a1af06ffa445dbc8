// haros_arch stand-in: tf2_ros::MessageFilter is the same class in ROS 2
#pragma once
#include <tf2_ros/message_filter.h>
