// haros_arch stand-in for <linux/input.h> (declarations only)
#ifndef HAROS_STANDIN_LINUX_INPUT_H
#define HAROS_STANDIN_LINUX_INPUT_H
#include "../haros_std.h"
struct input_event { struct timeval time; unsigned short type; unsigned short code; int value; };
struct input_id { unsigned short bustype, vendor, product, version; };
struct ff_replay { unsigned short length; unsigned short delay; };
struct ff_trigger { unsigned short button; unsigned short interval; };
struct ff_envelope { unsigned short attack_length, attack_level, fade_length, fade_level; };
struct ff_constant_effect { short level; struct ff_envelope envelope; };
struct ff_rumble_effect { unsigned short strong_magnitude; unsigned short weak_magnitude; };
struct ff_periodic_effect { unsigned short waveform, period; short magnitude, offset;
  unsigned short phase; struct ff_envelope envelope; unsigned int custom_len;
  short* custom_data; };
struct ff_effect {
  unsigned short type; short id; unsigned short direction;
  struct ff_trigger trigger; struct ff_replay replay;
  union { struct ff_constant_effect constant; struct ff_periodic_effect periodic;
          struct ff_rumble_effect rumble; } u;
};
#define EV_SYN 0x00
#define EV_KEY 0x01
#define EV_REL 0x02
#define EV_ABS 0x03
#define EV_MSC 0x04
#define EV_LED 0x11
#define EV_SND 0x12
#define EV_FF 0x15
#define EV_MAX 0x1f
#define FF_RUMBLE 0x50
#define FF_PERIODIC 0x51
#define FF_CONSTANT 0x52
#define FF_GAIN 0x60
#define FF_AUTOCENTER 0x61
#define FF_MAX 0x7f
#define EVIOCGVERSION 0x80044501
#define EVIOCGID 0x80084502
#define EVIOCGNAME(len) (0x80004506 + ((len) << 16))
#define EVIOCGBIT(ev, len) (0x80004520 + (ev) + ((len) << 16))
#define EVIOCSFF 0x40304580
#define EVIOCRMFF 0x40044581
#define EVIOCGEFFECTS 0x80044584
#define EVIOCGRAB 0x40044590
#endif
