// haros_arch stand-in: roscpp's version macros (noetic's roscpp, 1.15.15 as Debian
// ships it), which code tests in #if (ROS_VERSION_MINIMUM(1, 13, 0)); an undefined
// function-like macro there is an error that drops the branch it guards
#ifndef HAROS_STANDIN_ROS_COMMON_H
#define HAROS_STANDIN_ROS_COMMON_H
#define ROS_VERSION_MAJOR 1
#define ROS_VERSION_MINOR 15
#define ROS_VERSION_PATCH 15
#define ROS_VERSION_COMBINED(major, minor, patch) \
  (((major) << 20) | ((minor) << 10) | (patch))
#ifndef ROS_VERSION
#define ROS_VERSION \
  ROS_VERSION_COMBINED(ROS_VERSION_MAJOR, ROS_VERSION_MINOR, ROS_VERSION_PATCH)
#endif
#define ROS_VERSION_GE(major1, minor1, patch1, major2, minor2, patch2) \
  (ROS_VERSION_COMBINED(major1, minor1, patch1) >= \
   ROS_VERSION_COMBINED(major2, minor2, patch2))
#define ROS_VERSION_MINIMUM(major, minor, patch) \
  ROS_VERSION_GE(ROS_VERSION_MAJOR, ROS_VERSION_MINOR, ROS_VERSION_PATCH, major, minor, patch)
#endif
