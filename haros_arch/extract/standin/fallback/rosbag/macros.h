// haros_arch stand-in: ROS 1 rosbag's and rosbag_storage's export macros, for a
// workspace that has rosbag installed, not as sources (a fork of rosbag's recorder or
// player in the workspace declares ``class ROSBAG_DECL Recorder``). Linux builds
// define them empty or as a visibility attribute: empty here.
#ifndef HAROS_STANDIN_ROSBAG_MACROS_H
#define HAROS_STANDIN_ROSBAG_MACROS_H
#define ROSBAG_DECL
#define ROSBAG_STORAGE_DECL
#endif  // HAROS_STANDIN_ROSBAG_MACROS_H
