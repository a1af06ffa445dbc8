// haros_arch stand-in: see image_encodings.h
#include <sensor_msgs/image_encodings.h>
