// haros_arch stand-in for <linux/joystick.h> (declarations only)
#ifndef HAROS_STANDIN_LINUX_JOYSTICK_H
#define HAROS_STANDIN_LINUX_JOYSTICK_H
#include "../haros_std.h"
struct js_event { unsigned int time; short value; unsigned char type; unsigned char number; };
#define JS_EVENT_BUTTON 0x01
#define JS_EVENT_AXIS 0x02
#define JS_EVENT_INIT 0x80
#define JSIOCGVERSION 0x80046a01
#define JSIOCGAXES 0x80016a11
#define JSIOCGBUTTONS 0x80016a12
#define JSIOCGNAME(len) (0x80006a13 + ((len) << 16))
#endif
