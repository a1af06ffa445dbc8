// haros_arch stand-in: see ../autoware_utils/haros_polling_subscriber.h
#include "../autoware_utils/haros_polling_subscriber.h"
