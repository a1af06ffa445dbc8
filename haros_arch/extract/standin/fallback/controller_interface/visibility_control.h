// haros_arch stand-in: ros2_control's controller_interface/visibility_control.h (headers.FALLBACK):
// its symbol visibility macros, empty (a visibility attribute changes no call the code makes:
// a class declared `class CONTROLLER_INTERFACE_PUBLIC Name` parses as `class Name`)
#ifndef HAROS_STANDIN_CONTROLLER_INTERFACE_VISIBILITY_CONTROL_H
#define HAROS_STANDIN_CONTROLLER_INTERFACE_VISIBILITY_CONTROL_H
#define CONTROLLER_INTERFACE_EXPORT
#define CONTROLLER_INTERFACE_IMPORT
#define CONTROLLER_INTERFACE_PUBLIC
#define CONTROLLER_INTERFACE_LOCAL
#define CONTROLLER_INTERFACE_PUBLIC_TYPE
#endif
