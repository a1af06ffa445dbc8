// haros_arch stand-in: cv_bridge for ROS 2 (declarations only)
#ifndef HAROS_STANDIN_CV_BRIDGE_HPP
#define HAROS_STANDIN_CV_BRIDGE_HPP
#include <memory>
#include <string>
#include <opencv2/opencv.hpp>
#include <sensor_msgs/msg/image.hpp>
#include <sensor_msgs/msg/compressed_image.hpp>
#include <std_msgs/msg/header.hpp>
#include <sensor_msgs/image_encodings.hpp>
namespace cv_bridge {
class Exception {
public:
  Exception(const std::string& error);
  const char* what() const;
};
class CvImage {
public:
  CvImage();
  CvImage(const std_msgs::msg::Header& header, const std::string& encoding, const cv::Mat& image = cv::Mat());
  sensor_msgs::msg::Image::SharedPtr toImageMsg() const;
  void toImageMsg(sensor_msgs::msg::Image& ros_image) const;
  sensor_msgs::msg::CompressedImage::SharedPtr toCompressedImageMsg(int format = 0) const;
  std_msgs::msg::Header header;
  std::string encoding;
  cv::Mat image;
};
typedef std::shared_ptr<CvImage> CvImagePtr;
typedef std::shared_ptr<CvImage const> CvImageConstPtr;
CvImagePtr toCvCopy(const sensor_msgs::msg::Image::ConstSharedPtr& source, const std::string& encoding = std::string());
CvImagePtr toCvCopy(const sensor_msgs::msg::Image& source, const std::string& encoding = std::string());
// a compressed image decoded (kachaka's hand recognition)
CvImagePtr toCvCopy(const sensor_msgs::msg::CompressedImage::ConstSharedPtr& source, const std::string& encoding = std::string());
CvImagePtr toCvCopy(const sensor_msgs::msg::CompressedImage& source, const std::string& encoding = std::string());
CvImageConstPtr toCvShare(const sensor_msgs::msg::Image::ConstSharedPtr& source, const std::string& encoding = std::string());
int getCvType(const std::string& encoding);
}  // namespace cv_bridge
#endif
