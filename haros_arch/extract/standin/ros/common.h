// haros_arch stand-in: roscpp's ros/common.h, its version macros. The version is the
// analysed distribution's, given as -D flags (extract/cpp/versions.py); without them
// Noetic's, whose API the stand-ins follow
#ifndef HAROS_STANDIN_ROS_COMMON_H
#define HAROS_STANDIN_ROS_COMMON_H
#ifdef ROS_VERSION_MAJOR
// the analysed distribution's roscpp (tf2_ros/buffer.h: a ROS 1 unit's tf2::Stamped)
#define HAROS_ROSCPP_VERSION_GIVEN
#endif
#ifndef ROS_VERSION_MAJOR
#define ROS_VERSION_MAJOR 1
#define ROS_VERSION_MINOR 16
#define ROS_VERSION_PATCH 0
#endif
#define ROS_VERSION_COMBINED(major, minor, patch) \
  (((major) << 20) | ((minor) << 10) | (patch))
#define ROS_VERSION ROS_VERSION_COMBINED(ROS_VERSION_MAJOR, ROS_VERSION_MINOR, \
                                         ROS_VERSION_PATCH)
#define ROS_VERSION_GE(major1, minor1, patch1, major2, minor2, patch2) \
  (ROS_VERSION_COMBINED(major1, minor1, patch1) >= ROS_VERSION_COMBINED(major2, minor2, patch2))
#define ROS_VERSION_MINIMUM(major, minor, patch) \
  ROS_VERSION_GE(ROS_VERSION_MAJOR, ROS_VERSION_MINOR, ROS_VERSION_PATCH, major, minor, patch)
#endif
