// haros_arch stand-in: ros2_control's controller_manager/visibility_control.h (headers.FALLBACK):
// its symbol visibility macros, empty (a visibility attribute changes no call the code makes:
// a class declared `class CONTROLLER_MANAGER_PUBLIC Name` parses as `class Name`)
#ifndef HAROS_STANDIN_CONTROLLER_MANAGER_VISIBILITY_CONTROL_H
#define HAROS_STANDIN_CONTROLLER_MANAGER_VISIBILITY_CONTROL_H
#define CONTROLLER_MANAGER_EXPORT
#define CONTROLLER_MANAGER_IMPORT
#define CONTROLLER_MANAGER_PUBLIC
#define CONTROLLER_MANAGER_LOCAL
#define CONTROLLER_MANAGER_PUBLIC_TYPE
#endif
