// haros_arch stand-in: sensor_msgs' fillImage (declarations only; no ROS call): ROS 1's,
// and in a ROS 2 unit ROS 2's, whose deprecated fill_image.h includes fill_image.hpp
#if defined(HAROS_UNIT_ROS) && HAROS_UNIT_ROS == 2
#include <sensor_msgs/fill_image.hpp>
#else
#ifndef HAROS_STANDIN_SENSOR_MSGS_FILL_IMAGE_H
#define HAROS_STANDIN_SENSOR_MSGS_FILL_IMAGE_H
#include <cstdint>
#include <string>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/image_encodings.h>
namespace sensor_msgs {
bool fillImage(Image& image, const std::string& encoding_arg, uint32_t rows_arg,
               uint32_t cols_arg, uint32_t step_arg, const void* data_arg);
void clearImage(Image& image);
}  // namespace sensor_msgs
#endif
#endif  // HAROS_UNIT_ROS
