// haros_arch stand-in: sensor_msgs' camera distortion model names, ROS 1 and ROS 2
#ifndef HAROS_STANDIN_SENSOR_MSGS_DISTORTION_MODELS_H
#define HAROS_STANDIN_SENSOR_MSGS_DISTORTION_MODELS_H
#include <string>
namespace sensor_msgs {
namespace distortion_models {
extern const std::string PLUMB_BOB, RATIONAL_POLYNOMIAL, EQUIDISTANT;
}  // namespace distortion_models
}  // namespace sensor_msgs
#endif
