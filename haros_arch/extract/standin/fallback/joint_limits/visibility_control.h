// haros_arch stand-in: ros2_control's joint_limits/visibility_control.h (headers.FALLBACK):
// its symbol visibility macros, empty (a visibility attribute changes no call the code makes:
// a class declared `class JOINT_LIMITS_PUBLIC Name` parses as `class Name`)
#ifndef HAROS_STANDIN_JOINT_LIMITS_VISIBILITY_CONTROL_H
#define HAROS_STANDIN_JOINT_LIMITS_VISIBILITY_CONTROL_H
#define JOINT_LIMITS_EXPORT
#define JOINT_LIMITS_IMPORT
#define JOINT_LIMITS_PUBLIC
#define JOINT_LIMITS_LOCAL
#define JOINT_LIMITS_PUBLIC_TYPE
#endif
