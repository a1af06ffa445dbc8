// haros_arch stand-in: sensor_msgs image encodings, ROS 1 and ROS 2 (declarations only)
#ifndef HAROS_STANDIN_SENSOR_MSGS_IMAGE_ENCODINGS_H
#define HAROS_STANDIN_SENSOR_MSGS_IMAGE_ENCODINGS_H
#include <string>
namespace sensor_msgs {
namespace image_encodings {
extern const std::string RGB8, RGBA8, RGB16, RGBA16, BGR8, BGRA8, BGR16, BGRA16, MONO8,
    MONO16,
    TYPE_8UC1, TYPE_8UC2, TYPE_8UC3, TYPE_8UC4, TYPE_8SC1, TYPE_8SC2, TYPE_8SC3, TYPE_8SC4,
    TYPE_16UC1, TYPE_16UC2, TYPE_16UC3, TYPE_16UC4, TYPE_16SC1, TYPE_16SC2, TYPE_16SC3,
    TYPE_16SC4, TYPE_32SC1, TYPE_32SC2, TYPE_32SC3, TYPE_32SC4, TYPE_32FC1, TYPE_32FC2,
    TYPE_32FC3, TYPE_32FC4, TYPE_64FC1, TYPE_64FC2, TYPE_64FC3, TYPE_64FC4,
    BAYER_RGGB8, BAYER_BGGR8, BAYER_GBRG8, BAYER_GRBG8,
    BAYER_RGGB16, BAYER_BGGR16, BAYER_GBRG16, BAYER_GRBG16,
    YUV422, YUV422_YUY2, UYVY, YUYV, NV21, NV24;
bool isColor(const std::string& encoding);
bool isMono(const std::string& encoding);
bool isBayer(const std::string& encoding);
bool hasAlpha(const std::string& encoding);
int numChannels(const std::string& encoding);
int bitDepth(const std::string& encoding);
}  // namespace image_encodings
}  // namespace sensor_msgs
#endif
