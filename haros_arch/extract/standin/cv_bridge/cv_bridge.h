// haros_arch stand-in: cv_bridge for ROS 1 (declarations only); in a ROS 2 unit the
// header of ROS 2's cv_bridge, which includes cv_bridge.hpp (Foxy's only header; Humble's
// deprecated one): ROS 2 code including <cv_bridge/cv_bridge.h> gets the ROS 2 API
#if defined(HAROS_UNIT_ROS) && HAROS_UNIT_ROS == 2
#include <cv_bridge/cv_bridge.hpp>
#else
#ifndef HAROS_STANDIN_CV_BRIDGE_H
#define HAROS_STANDIN_CV_BRIDGE_H
#include <string>
#include <boost/shared_ptr.hpp>
#include <opencv2/opencv.hpp>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/image_encodings.h>
namespace cv_bridge {
class Exception {
public:
  Exception(const std::string& error);
  const char* what() const;
};
class CvImage {
public:
  CvImage();
  CvImage(const std_msgs::Header& header, const std::string& encoding, const cv::Mat& image = cv::Mat());
  sensor_msgs::ImagePtr toImageMsg() const;
  void toImageMsg(sensor_msgs::Image& ros_image) const;
  sensor_msgs::CompressedImagePtr toCompressedImageMsg(int format = 0) const;
  std_msgs::Header header;
  std::string encoding;
  cv::Mat image;
};
typedef boost::shared_ptr<CvImage> CvImagePtr;
typedef boost::shared_ptr<CvImage const> CvImageConstPtr;
CvImagePtr toCvCopy(const sensor_msgs::ImageConstPtr& source, const std::string& encoding = std::string());
CvImagePtr toCvCopy(const sensor_msgs::Image& source, const std::string& encoding = std::string());
CvImagePtr toCvCopy(const sensor_msgs::CompressedImageConstPtr& source, const std::string& encoding = std::string());
CvImageConstPtr toCvShare(const sensor_msgs::ImageConstPtr& source, const std::string& encoding = std::string());
CvImageConstPtr toCvShare(const sensor_msgs::Image& source, const boost::shared_ptr<void const>& tracked_object, const std::string& encoding = std::string());
CvImagePtr cvtColor(const CvImageConstPtr& source, const std::string& encoding);
int getCvType(const std::string& encoding);
}  // namespace cv_bridge
#endif
#endif  // HAROS_UNIT_ROS
