// haros_arch stand-in: roslib's ros/package.h (declarations only).
#ifndef HAROS_STANDIN_ROS_PACKAGE_H
#define HAROS_STANDIN_ROS_PACKAGE_H
#include <string>
#include <vector>
namespace ros {
namespace package {
typedef std::vector<std::string> V_string;
std::string command(const std::string& cmd);
std::string getPath(const std::string& package_name);
bool getAll(V_string& packages);
}  // namespace package
}  // namespace ros
#endif
