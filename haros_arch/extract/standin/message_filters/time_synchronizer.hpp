// haros_arch stand-in
#include <message_filters/subscriber.h>
