// haros_arch stand-in for <linux/gpio.h>, the GPIO character device interface (version 2
// and the older line handles; declarations only, the values are not the kernel's): the
// records and ioctl requests a driver opens lines and sets their values with
// (hexapod-ros2-control's SH1122 display driver)
#ifndef HAROS_STANDIN_LINUX_GPIO_H
#define HAROS_STANDIN_LINUX_GPIO_H
#include "../haros_std.h"
#define GPIO_MAX_NAME_SIZE 32
#define GPIO_V2_LINES_MAX 64
#define GPIO_V2_LINE_NUM_ATTRS_MAX 10
struct gpiochip_info { char name[GPIO_MAX_NAME_SIZE]; char label[GPIO_MAX_NAME_SIZE]; uint32_t lines; };
enum gpio_v2_line_flag {
  GPIO_V2_LINE_FLAG_USED = 1, GPIO_V2_LINE_FLAG_ACTIVE_LOW = 2, GPIO_V2_LINE_FLAG_INPUT = 4,
  GPIO_V2_LINE_FLAG_OUTPUT = 8, GPIO_V2_LINE_FLAG_EDGE_RISING = 16,
  GPIO_V2_LINE_FLAG_EDGE_FALLING = 32, GPIO_V2_LINE_FLAG_OPEN_DRAIN = 64,
  GPIO_V2_LINE_FLAG_OPEN_SOURCE = 128, GPIO_V2_LINE_FLAG_BIAS_PULL_UP = 256,
  GPIO_V2_LINE_FLAG_BIAS_PULL_DOWN = 512, GPIO_V2_LINE_FLAG_BIAS_DISABLED = 1024,
  GPIO_V2_LINE_FLAG_EVENT_CLOCK_REALTIME = 2048, GPIO_V2_LINE_FLAG_EVENT_CLOCK_HTE = 4096
};
struct gpio_v2_line_values { uint64_t bits; uint64_t mask; };
enum gpio_v2_line_attr_id {
  GPIO_V2_LINE_ATTR_ID_FLAGS = 1, GPIO_V2_LINE_ATTR_ID_OUTPUT_VALUES = 2,
  GPIO_V2_LINE_ATTR_ID_DEBOUNCE = 3
};
struct gpio_v2_line_attribute {
  uint32_t id;
  uint32_t padding;
  union { uint64_t flags; uint64_t values; uint32_t debounce_period_us; };
};
struct gpio_v2_line_config_attribute { struct gpio_v2_line_attribute attr; uint64_t mask; };
struct gpio_v2_line_config {
  uint64_t flags;
  uint32_t num_attrs;
  uint32_t padding[5];
  struct gpio_v2_line_config_attribute attrs[GPIO_V2_LINE_NUM_ATTRS_MAX];
};
struct gpio_v2_line_request {
  uint32_t offsets[GPIO_V2_LINES_MAX];
  char consumer[GPIO_MAX_NAME_SIZE];
  struct gpio_v2_line_config config;
  uint32_t num_lines;
  uint32_t event_buffer_size;
  uint32_t padding[5];
  int32_t fd;
};
struct gpio_v2_line_info {
  char name[GPIO_MAX_NAME_SIZE];
  char consumer[GPIO_MAX_NAME_SIZE];
  uint32_t offset;
  uint32_t num_attrs;
  uint64_t flags;
  struct gpio_v2_line_attribute attrs[GPIO_V2_LINE_NUM_ATTRS_MAX];
  uint32_t padding[4];
};
enum gpio_v2_line_changed_type {
  GPIO_V2_LINE_CHANGED_REQUESTED = 1, GPIO_V2_LINE_CHANGED_RELEASED = 2,
  GPIO_V2_LINE_CHANGED_CONFIG = 3
};
struct gpio_v2_line_info_changed {
  struct gpio_v2_line_info info;
  uint64_t timestamp_ns;
  uint32_t event_type;
  uint32_t padding[5];
};
enum gpio_v2_line_event_id {
  GPIO_V2_LINE_EVENT_RISING_EDGE = 1, GPIO_V2_LINE_EVENT_FALLING_EDGE = 2
};
struct gpio_v2_line_event {
  uint64_t timestamp_ns;
  uint32_t id;
  uint32_t offset;
  uint32_t seqno;
  uint32_t line_seqno;
  uint32_t padding[6];
};
// version 1: line handles and events
#define GPIOLINE_FLAG_KERNEL (1UL << 0)
#define GPIOLINE_FLAG_IS_OUT (1UL << 1)
#define GPIOLINE_FLAG_ACTIVE_LOW (1UL << 2)
#define GPIOLINE_FLAG_OPEN_DRAIN (1UL << 3)
#define GPIOLINE_FLAG_OPEN_SOURCE (1UL << 4)
struct gpioline_info {
  uint32_t line_offset;
  uint32_t flags;
  char name[GPIO_MAX_NAME_SIZE];
  char consumer[GPIO_MAX_NAME_SIZE];
};
#define GPIOHANDLES_MAX 64
#define GPIOHANDLE_REQUEST_INPUT (1UL << 0)
#define GPIOHANDLE_REQUEST_OUTPUT (1UL << 1)
#define GPIOHANDLE_REQUEST_ACTIVE_LOW (1UL << 2)
#define GPIOHANDLE_REQUEST_OPEN_DRAIN (1UL << 3)
#define GPIOHANDLE_REQUEST_OPEN_SOURCE (1UL << 4)
#define GPIOHANDLE_REQUEST_BIAS_PULL_UP (1UL << 5)
#define GPIOHANDLE_REQUEST_BIAS_PULL_DOWN (1UL << 6)
#define GPIOHANDLE_REQUEST_BIAS_DISABLE (1UL << 7)
struct gpiohandle_request {
  uint32_t lineoffsets[GPIOHANDLES_MAX];
  uint32_t flags;
  uint8_t default_values[GPIOHANDLES_MAX];
  char consumer_label[GPIO_MAX_NAME_SIZE];
  uint32_t lines;
  int fd;
};
struct gpiohandle_config {
  uint32_t flags;
  uint8_t default_values[GPIOHANDLES_MAX];
  uint32_t padding[4];
};
struct gpiohandle_data { uint8_t values[GPIOHANDLES_MAX]; };
#define GPIOEVENT_REQUEST_RISING_EDGE (1UL << 0)
#define GPIOEVENT_REQUEST_FALLING_EDGE (1UL << 1)
#define GPIOEVENT_REQUEST_BOTH_EDGES ((1UL << 0) | (1UL << 1))
struct gpioevent_request {
  uint32_t lineoffset;
  uint32_t handleflags;
  uint32_t eventflags;
  char consumer_label[GPIO_MAX_NAME_SIZE];
  int fd;
};
#define GPIOEVENT_EVENT_RISING_EDGE 0x01
#define GPIOEVENT_EVENT_FALLING_EDGE 0x02
struct gpioevent_data { uint64_t timestamp; uint32_t id; };
#define GPIO_GET_CHIPINFO_IOCTL 0x8044b401UL
#define GPIO_GET_LINEINFO_UNWATCH_IOCTL 0xc004b40cUL
#define GPIO_V2_GET_LINEINFO_IOCTL 0xc100b405UL
#define GPIO_V2_GET_LINEINFO_WATCH_IOCTL 0xc100b406UL
#define GPIO_V2_GET_LINE_IOCTL 0xc250b407UL
#define GPIO_V2_LINE_SET_CONFIG_IOCTL 0xc110b40dUL
#define GPIO_V2_LINE_GET_VALUES_IOCTL 0xc010b40eUL
#define GPIO_V2_LINE_SET_VALUES_IOCTL 0xc010b40fUL
#define GPIO_GET_LINEINFO_IOCTL 0xc048b402UL
#define GPIO_GET_LINEHANDLE_IOCTL 0xc16cb403UL
#define GPIO_GET_LINEEVENT_IOCTL 0xc030b404UL
#define GPIOHANDLE_GET_LINE_VALUES_IOCTL 0xc040b408UL
#define GPIOHANDLE_SET_LINE_VALUES_IOCTL 0xc040b409UL
#define GPIOHANDLE_SET_CONFIG_IOCTL 0xc054b40aUL
#define GPIO_GET_LINEINFO_WATCH_IOCTL 0xc048b40bUL
#endif
