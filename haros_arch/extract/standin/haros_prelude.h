// haros_arch: the stand-in headers precompiled once per process (a PCH) so that each
// translation unit parses in milliseconds. Headers included again later are skipped by
// their include guards.
#include "std/haros_std.h"
#include <boost/shared_ptr.hpp>
#include <boost/function.hpp>
// code that names boost::lexical_cast through a header we stand in for empty (gazebo's:
// gazebo_plugins' gazebo_ros_utils.h includes no boost header of its own for it)
#include <boost/lexical_cast.hpp>
#include <ros/ros.h>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <rclcpp_action/rclcpp_action.hpp>
#include <rclcpp_components/register_node_macro.hpp>
#include <tf2_ros/buffer.h>
#include <image_transport/image_transport.h>
#include <message_filters/subscriber.h>
#include <actionlib/server/simple_action_server.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
