// haros_arch stand-in for <linux/can/raw.h>, the raw CAN socket's options (declarations
// only)
#ifndef HAROS_STANDIN_LINUX_CAN_RAW_H
#define HAROS_STANDIN_LINUX_CAN_RAW_H
#include <linux/can.h>
#define SOL_CAN_BASE 100
#define SOL_CAN_RAW (SOL_CAN_BASE + CAN_RAW)
enum {
  CAN_RAW_FILTER = 1, CAN_RAW_ERR_FILTER, CAN_RAW_LOOPBACK, CAN_RAW_RECV_OWN_MSGS,
  CAN_RAW_FD_FRAMES, CAN_RAW_JOIN_FILTERS, CAN_RAW_XL_FRAMES
};
#endif
