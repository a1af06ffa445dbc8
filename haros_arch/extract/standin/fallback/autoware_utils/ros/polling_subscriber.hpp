// haros_arch stand-in: see ../haros_polling_subscriber.h
#include "../haros_polling_subscriber.h"
