// haros_arch stand-in: Boost.Asio's umbrella header. Only boost::system's error codes,
// which its handlers take, are declared; the asio classes a unit names (io_service,
// timers, serial ports, sockets) are declared permissively, as for any missing library.
#include <boost/system/error_code.hpp>
