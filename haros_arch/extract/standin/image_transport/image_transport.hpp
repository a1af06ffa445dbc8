// haros_arch stand-in
#include <image_transport/image_transport.h>
