// haros_arch stand-in
#include <nodelet/nodelet.h>
