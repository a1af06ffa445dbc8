// haros_arch stand-in: PickNik's rosparam_shortcuts (declarations only; ROS 1's
// melodic/noetic API and ROS 2's ros2 branch side by side), for a workspace that has the
// package installed, not as sources. ``get(parent, nh, name, value)`` reads ``name`` on
// ``nh`` (ROS 1) and returns false when it is not set; ROS 2's ``get(node, name, value)``
// declares the parameter with the value's type and no default, then reads it (API rows:
// extract/cpp/api.py ROSPARAM_SHORTCUTS). ``shutdownIfError(..., count)`` shuts the
// process down when the count of failed gets is not zero, which makes each get it
// counts a required read (extract/cpp/tested.py). Every other header of the package
// stands in as this one.
#ifndef HAROS_STANDIN_ROSPARAM_SHORTCUTS_H
#define HAROS_STANDIN_ROSPARAM_SHORTCUTS_H
#include <cstddef>
#include <map>
#include <string>
#include <vector>
#include <Eigen/Geometry>
#include <ros/ros.h>

namespace rosparam_shortcuts {
bool get(const std::string& parent_name, const ros::NodeHandle& nh,
         const std::string& param_name, bool& value);
bool get(const std::string& parent_name, const ros::NodeHandle& nh,
         const std::string& params_name, std::map<std::string, bool>& parameters);
bool get(const std::string& parent_name, const ros::NodeHandle& nh,
         const std::string& param_name, double& value);
bool get(const std::string& parent_name, const ros::NodeHandle& nh,
         const std::string& param_name, std::vector<double>& values);
bool get(const std::string& parent_name, const ros::NodeHandle& nh,
         const std::string& param_name, int& value);
bool get(const std::string& parent_name, const ros::NodeHandle& nh,
         const std::string& param_name, std::size_t& value);
bool get(const std::string& parent_name, const ros::NodeHandle& nh,
         const std::string& param_name, std::string& value);
bool get(const std::string& parent_name, const ros::NodeHandle& nh,
         const std::string& param_name, std::vector<std::string>& values);
bool get(const std::string& parent_name, const ros::NodeHandle& nh,
         const std::string& param_name, ros::Duration& value);
bool get(const std::string& parent_name, const ros::NodeHandle& nh,
         const std::string& param_name, Eigen::Isometry3d& value);
// (geometry_msgs::Pose read from six or seven numbers: any type, so that no message
// header has to be there)
template <typename Pose>
bool get(const std::string& parent_name, const ros::NodeHandle& nh,
         const std::string& param_name, Pose& value);
std::string getDebugArrayString(std::vector<double> values);
std::string getDebugArrayString(std::vector<std::string> values);
bool convertDoublesToEigen(const std::string& parent_name, std::vector<double> values,
                           Eigen::Isometry3d& transform);
void shutdownIfError(const std::string& parent_name, std::size_t error_count);
#ifdef HAROS_STANDIN_RCLCPP_HPP
// ROS 2 (rclcpp is in the precompiled stand-ins; not included here)
template <typename T>
bool get(const rclcpp::Node::SharedPtr& node, const std::string& param_name, T& value);
void shutdownIfError(const std::size_t error_count);
#endif
}  // namespace rosparam_shortcuts
#endif
