// haros_arch stand-in: ros2_control's hardware_interface/visibility_control.h (headers.FALLBACK):
// its symbol visibility macros, empty (a visibility attribute changes no call the code makes:
// a class declared `class HARDWARE_INTERFACE_PUBLIC Name` parses as `class Name`)
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_VISIBILITY_CONTROL_H
#define HAROS_STANDIN_HARDWARE_INTERFACE_VISIBILITY_CONTROL_H
#define HARDWARE_INTERFACE_EXPORT
#define HARDWARE_INTERFACE_IMPORT
#define HARDWARE_INTERFACE_PUBLIC
#define HARDWARE_INTERFACE_LOCAL
#define HARDWARE_INTERFACE_PUBLIC_TYPE
#endif
