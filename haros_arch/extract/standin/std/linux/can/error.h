// haros_arch stand-in for <linux/can/error.h>, the error frame's classes (declarations
// only)
#ifndef HAROS_STANDIN_LINUX_CAN_ERROR_H
#define HAROS_STANDIN_LINUX_CAN_ERROR_H
#include <linux/can.h>
#define CAN_ERR_DLC 8
#define CAN_ERR_TX_TIMEOUT 0x00000001U
#define CAN_ERR_LOSTARB 0x00000002U
#define CAN_ERR_CRTL 0x00000004U
#define CAN_ERR_PROT 0x00000008U
#define CAN_ERR_TRX 0x00000010U
#define CAN_ERR_ACK 0x00000020U
#define CAN_ERR_BUSOFF 0x00000040U
#define CAN_ERR_BUSERROR 0x00000080U
#define CAN_ERR_RESTARTED 0x00000100U
#endif
