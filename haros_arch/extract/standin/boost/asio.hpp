// haros_arch stand-in: Boost.Asio's umbrella header. Declared: boost::system's error
// codes, which its handlers take, and the option classes of serial_port_base (a serial
// driver's `port.set_option(serial_port_base::parity(serial_port_base::parity::none))`,
// and its overloads on each option, are only valid with their nested enums). The other
// asio classes a unit names (io_service, timers, serial ports, sockets) are declared
// permissively, as for any missing library.
#ifndef HAROS_STANDIN_BOOST_ASIO_HPP
#define HAROS_STANDIN_BOOST_ASIO_HPP
#include <cstddef>
#include <boost/system/error_code.hpp>
namespace boost {
namespace asio {
class serial_port_base {
 public:
  class baud_rate {
   public:
    explicit baud_rate(unsigned int rate = 0);
    unsigned int value() const;
  };
  class flow_control {
   public:
    enum type { none, software, hardware };
    explicit flow_control(type t = none);
    type value() const;
  };
  class parity {
   public:
    enum type { none, odd, even };
    explicit parity(type t = none);
    type value() const;
  };
  class stop_bits {
   public:
    enum type { one, onepointfive, two };
    explicit stop_bits(type t = one);
    type value() const;
  };
  class character_size {
   public:
    explicit character_size(unsigned int t = 8);
    unsigned int value() const;
  };
};
}  // namespace asio
}  // namespace boost
#endif
