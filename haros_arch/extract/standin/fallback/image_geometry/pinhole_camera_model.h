// haros_arch stand-in: image_geometry's camera models (declarations only, ROS 1 and 2),
// for a workspace that has image_geometry installed, not as sources. A model is geometry
// over a CameraInfo message: it makes no ROS call (turtlebot_actions' fiducial finder,
// depth and stereo nodes).
#ifndef HAROS_STANDIN_IMAGE_GEOMETRY_H
#define HAROS_STANDIN_IMAGE_GEOMETRY_H
#include <string>
#include <opencv2/opencv.hpp>

namespace image_geometry {
class Exception : public std::runtime_error {
 public:
  explicit Exception(const std::string& what);
};

class PinholeCameraModel {
 public:
  PinholeCameraModel();
  PinholeCameraModel(const PinholeCameraModel& other);
  PinholeCameraModel& operator=(const PinholeCameraModel& other);
  // a sensor_msgs CameraInfo (ROS 1 or 2), or a pointer to one
  template<class M> bool fromCameraInfo(const M& msg);
  std::string tfFrame() const;
  bool initialized() const;
  cv::Size fullResolution() const;
  cv::Size reducedResolution() const;
  cv::Point2d toFullResolution(const cv::Point2d& uv_reduced) const;
  cv::Point2d toReducedResolution(const cv::Point2d& uv_full) const;
  cv::Point2d project3dToPixel(const cv::Point3d& xyz) const;
  cv::Point3d projectPixelTo3dRay(const cv::Point2d& uv_rect) const;
  void rectifyImage(const cv::Mat& raw, cv::Mat& rectified,
                    int interpolation = cv::INTER_LINEAR) const;
  void unrectifyImage(const cv::Mat& rectified, cv::Mat& raw,
                      int interpolation = cv::INTER_LINEAR) const;
  cv::Point2d rectifyPoint(const cv::Point2d& uv_raw) const;
  cv::Point2d unrectifyPoint(const cv::Point2d& uv_rect) const;
  cv::Rect rectifyRoi(const cv::Rect& roi_raw) const;
  cv::Rect unrectifyRoi(const cv::Rect& roi_rect) const;
  const cv::Matx33d& intrinsicMatrix() const;
  const cv::Mat_<double>& distortionCoeffs() const;
  const cv::Matx33d& rotationMatrix() const;
  const cv::Matx34d& projectionMatrix() const;
  const cv::Matx33d& fullIntrinsicMatrix() const;
  const cv::Matx34d& fullProjectionMatrix() const;
  double fx() const; double fy() const; double cx() const; double cy() const;
  double Tx() const; double Ty() const;
  unsigned int binningX() const; unsigned int binningY() const;
  double getDeltaU(double deltaX, double Z) const;
  double getDeltaV(double deltaY, double Z) const;
  double getDeltaX(double deltaU, double Z) const;
  double getDeltaY(double deltaV, double Z) const;
};

class StereoCameraModel {
 public:
  StereoCameraModel();
  template<class M> bool fromCameraInfo(const M& left, const M& right);
  const PinholeCameraModel& left() const;
  const PinholeCameraModel& right() const;
  std::string tfFrame() const;
  void projectDisparityTo3d(const cv::Point2d& left_uv_rect, float disparity,
                            cv::Point3d& xyz) const;
  void projectDisparityImageTo3d(const cv::Mat& disparity, cv::Mat& point_cloud,
                                 bool handleMissingValues = false) const;
  static const double MISSING_Z;
  const cv::Matx44d& reprojectionMatrix() const;
  double baseline() const;
  double getZ(double disparity) const;
  double getDisparity(double Z) const;
  bool initialized() const;
};
}  // namespace image_geometry
#endif
