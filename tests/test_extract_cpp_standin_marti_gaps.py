"""Stand-in gaps that made marti_common's image and transform nodes ``partial`` for
errors in functions that make ROS calls: OpenCV's ``cv::Scalar`` compared with ``!=``
(blend_images_node), ``cv::Mat::ones(Size, type)``, ``cv::MORPH_ELLIPSE`` and
``getStructuringElement``'s anchor (contrast_stretch_node), and tf2's ``TimePointZero``
as the ``TimePoint`` it is (gps_transform_publisher passes it to its own
``GetTransform(target, source, const tf2::TimePoint&, ...)``)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <opencv2/opencv.hpp>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <tf2/time.h>
bool GetTransform(const std::string& target, const std::string& source,
                  const tf2::TimePoint& time, int& out);
class Images : public rclcpp::Node {
public:
  Images() : rclcpp::Node("images") {
    cv::Scalar mask_color(1, 2, 3);
    cv::Mat image = cv::Mat::zeros(4, 4, CV_8U);
    if (mask_color != cv::Scalar(0, 0, 0)) {
      cv::Mat mask = cv::Mat::ones(image.size(), CV_8U);
      cv::Mat element = cv::getStructuringElement(
          cv::MORPH_ELLIPSE, cv::Size(3, 3), cv::Point(1, 1));
    }
    int transform = 0;
    if (GetTransform("map", "wgs84", tf2::TimePointZero, transform)) {
      pub_ = create_publisher<std_msgs::msg::String>("status", 1);
    }
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
"""


def test_the_standins_have_what_marti_common_uses(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("images", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend>"
                      "<depend>tf2</depend></package>"))
    source = tmp_path / "images.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]
    assert errors == [], errors
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "status")]
