// haros_arch stand-in for <net/if.h>, network interfaces by name (declarations only; the
// request's union members are plain fields here): the interface index a SocketCAN or
// raw-socket driver asks with ``ioctl(fd, SIOCGIFINDEX, &ifr)``
#ifndef HAROS_STANDIN_NET_IF_H
#define HAROS_STANDIN_NET_IF_H
#include "../haros_std.h"
#define IFNAMSIZ 16
#define IF_NAMESIZE 16
#define IFF_UP 0x1
#define IFF_BROADCAST 0x2
#define IFF_LOOPBACK 0x8
#define IFF_RUNNING 0x40
#define IFF_PROMISC 0x100
#define IFF_MULTICAST 0x1000
#define SIOCGIFNAME 0x8910
#define SIOCGIFFLAGS 0x8913
#define SIOCSIFFLAGS 0x8914
#define SIOCGIFADDR 0x8915
#define SIOCGIFMTU 0x8921
#define SIOCSIFMTU 0x8922
#define SIOCGIFHWADDR 0x8927
#define SIOCGIFINDEX 0x8933
struct ifmap { unsigned long mem_start; unsigned long mem_end; unsigned short base_addr;
               unsigned char irq; unsigned char dma; unsigned char port; };
struct ifreq {
  char ifr_name[IFNAMSIZ];
  struct sockaddr ifr_addr;
  struct sockaddr ifr_dstaddr;
  struct sockaddr ifr_broadaddr;
  struct sockaddr ifr_netmask;
  struct sockaddr ifr_hwaddr;
  short ifr_flags;
  int ifr_ifindex;
  int ifr_metric;
  int ifr_mtu;
  struct ifmap ifr_map;
  char ifr_slave[IFNAMSIZ];
  char ifr_newname[IFNAMSIZ];
  char* ifr_data;
};
struct if_nameindex { unsigned int if_index; char* if_name; };
unsigned int if_nametoindex(const char* name);
char* if_indextoname(unsigned int index, char* name);
struct if_nameindex* if_nameindex(void);
void if_freenameindex(struct if_nameindex* ptr);
#endif
