// haros_arch stand-in: see distortion_models.h
#include <sensor_msgs/distortion_models.h>
