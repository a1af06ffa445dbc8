// haros_arch stand-in for <linux/spi/spidev.h>, the SPI user-space interface (declarations
// only; the values are not the kernel's): the mode bits, the ioctl requests and the
// transfer record a driver fills (Husarion Panther's APA102 lights, an SPI display)
#ifndef HAROS_STANDIN_LINUX_SPI_SPIDEV_H
#define HAROS_STANDIN_LINUX_SPI_SPIDEV_H
#include "../../haros_std.h"
#define SPI_CPHA 0x01
#define SPI_CPOL 0x02
#define SPI_MODE_0 (0 | 0)
#define SPI_MODE_1 (0 | SPI_CPHA)
#define SPI_MODE_2 (SPI_CPOL | 0)
#define SPI_MODE_3 (SPI_CPOL | SPI_CPHA)
#define SPI_MODE_X_MASK (SPI_CPOL | SPI_CPHA)
#define SPI_CS_HIGH 0x04
#define SPI_LSB_FIRST 0x08
#define SPI_3WIRE 0x10
#define SPI_LOOP 0x20
#define SPI_NO_CS 0x40
#define SPI_READY 0x80
#define SPI_TX_DUAL 0x100
#define SPI_TX_QUAD 0x200
#define SPI_RX_DUAL 0x400
#define SPI_RX_QUAD 0x800
#define SPI_CS_WORD 0x1000
#define SPI_TX_OCTAL 0x2000
#define SPI_RX_OCTAL 0x4000
#define SPI_3WIRE_HIZ 0x8000
#define SPI_IOC_MAGIC 'k'
struct spi_ioc_transfer {
  uint64_t tx_buf;
  uint64_t rx_buf;
  uint32_t len;
  uint32_t speed_hz;
  uint16_t delay_usecs;
  uint8_t bits_per_word;
  uint8_t cs_change;
  uint8_t tx_nbits;
  uint8_t rx_nbits;
  uint8_t word_delay_usecs;
  uint8_t pad;
};
#define SPI_MSGSIZE(N) ((N) * sizeof(struct spi_ioc_transfer))
#define SPI_IOC_MESSAGE(N) (0x40006b00UL | (SPI_MSGSIZE(N) << 16))
#define SPI_IOC_RD_MODE 0x80016b01UL
#define SPI_IOC_WR_MODE 0x40016b01UL
#define SPI_IOC_RD_LSB_FIRST 0x80016b02UL
#define SPI_IOC_WR_LSB_FIRST 0x40016b02UL
#define SPI_IOC_RD_BITS_PER_WORD 0x80016b03UL
#define SPI_IOC_WR_BITS_PER_WORD 0x40016b03UL
#define SPI_IOC_RD_MAX_SPEED_HZ 0x80046b04UL
#define SPI_IOC_WR_MAX_SPEED_HZ 0x40046b04UL
#define SPI_IOC_RD_MODE32 0x80046b05UL
#define SPI_IOC_WR_MODE32 0x40046b05UL
#endif
