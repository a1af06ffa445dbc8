// haros_arch stand-in for <linux/can.h>, SocketCAN's frames and address (declarations
// only; the values are the kernel's where a driver may print them): the records a CAN
// driver reads and writes (EduArt's edu_robot CAN gateway, robot base drivers)
#ifndef HAROS_STANDIN_LINUX_CAN_H
#define HAROS_STANDIN_LINUX_CAN_H
#include "../haros_std.h"
#define AF_CAN 29
#define PF_CAN AF_CAN
#define CAN_RAW 1
#define CAN_BCM 2
#define CAN_ISOTP 6
#define CAN_J1939 7
#define CAN_EFF_FLAG 0x80000000U
#define CAN_RTR_FLAG 0x40000000U
#define CAN_ERR_FLAG 0x20000000U
#define CAN_SFF_MASK 0x000007FFU
#define CAN_EFF_MASK 0x1FFFFFFFU
#define CAN_ERR_MASK 0x1FFFFFFFU
#define CAN_INV_FILTER 0x20000000U
#define CAN_SFF_ID_BITS 11
#define CAN_EFF_ID_BITS 29
#define CAN_MAX_DLC 8
#define CAN_MAX_DLEN 8
#define CANFD_MAX_DLC 15
#define CANFD_MAX_DLEN 64
#define CANFD_BRS 0x01
#define CANFD_ESI 0x02
#define CANFD_FDF 0x04
typedef uint32_t canid_t;
typedef uint32_t can_err_mask_t;
struct can_frame {
  canid_t can_id;
  uint8_t can_dlc;
  uint8_t len;
  uint8_t __pad;
  uint8_t __res0;
  uint8_t len8_dlc;
  uint8_t data[CAN_MAX_DLEN];
};
struct canfd_frame {
  canid_t can_id;
  uint8_t len;
  uint8_t flags;
  uint8_t __res0;
  uint8_t __res1;
  uint8_t data[CANFD_MAX_DLEN];
};
#define CAN_MTU (sizeof(struct can_frame))
#define CANFD_MTU (sizeof(struct canfd_frame))
struct sockaddr_can {
  sa_family_t can_family;
  int can_ifindex;
  union {
    struct { canid_t rx_id, tx_id; } tp;
    struct { uint64_t name; uint32_t pgn; uint8_t addr; } j1939;
  } can_addr;
};
struct can_filter { canid_t can_id; canid_t can_mask; };
#endif
