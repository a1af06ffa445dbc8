// haros_arch stand-in: sensor_msgs' fillImage for ROS 2 (declarations only; no ROS call)
#ifndef HAROS_STANDIN_SENSOR_MSGS_FILL_IMAGE_HPP
#define HAROS_STANDIN_SENSOR_MSGS_FILL_IMAGE_HPP
#include <cstdint>
#include <string>
#include <sensor_msgs/msg/image.hpp>
#include <sensor_msgs/image_encodings.hpp>
namespace sensor_msgs {
bool fillImage(msg::Image& image, const std::string& encoding_arg, uint32_t rows_arg,
               uint32_t cols_arg, uint32_t step_arg, const void* data_arg);
void clearImage(msg::Image& image);
}  // namespace sensor_msgs
#endif
