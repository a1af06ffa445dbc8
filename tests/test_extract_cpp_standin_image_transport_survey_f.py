"""Stand-in gaps of image_transport seen on real code (bench/README, survey F): the ZED
examples' components log ``CameraSubscriber::getTopic()`` after subscribing
(zed_rgb_convert_component.cpp, zed_aruco_localization_component.cpp). The stand-in's
CameraSubscriber had no ``getTopic``, ``getInfoTopic`` nor ``getNumPublishers``, and its
Subscriber no ``getNumPublishers`` nor ``getTransport``: each was a C++ error in a function
that calls the ROS API, and the node was partial for it."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <image_transport/image_transport.hpp>
#include <sensor_msgs/msg/image.hpp>
#include <sensor_msgs/msg/camera_info.hpp>

class Convert : public rclcpp::Node {
public:
  Convert() : Node("convert") {
    pub_ = image_transport::create_camera_publisher(this, "~/out");
    RCLCPP_INFO_STREAM(get_logger(), "Advertised on " << pub_.getTopic());
    sub_ = image_transport::create_camera_subscription(
      this, "in", std::bind(&Convert::on_image, this, std::placeholders::_1,
                            std::placeholders::_2), "raw");
    RCLCPP_INFO_STREAM(get_logger(), "Subscribed on " << sub_.getTopic() << " and "
                       << sub_.getInfoTopic() << " from " << sub_.getNumPublishers());
    raw_ = image_transport::create_subscription(
      this, "raw_in", std::bind(&Convert::on_raw, this, std::placeholders::_1), "raw");
    RCLCPP_INFO_STREAM(get_logger(), raw_.getTransport() << raw_.getNumPublishers());
  }
  void on_image(const sensor_msgs::msg::Image::ConstSharedPtr & image,
                const sensor_msgs::msg::CameraInfo::ConstSharedPtr & info) {
    pub_.publish(*image, *info);
  }
  void on_raw(const sensor_msgs::msg::Image::ConstSharedPtr &) {}
  image_transport::CameraPublisher pub_;
  image_transport::CameraSubscriber sub_;
  image_transport::Subscriber raw_;
};

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Convert>());
}
"""


def test_camera_subscriber_topic_and_subscriber_transport(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("convert", "ament_cmake"))
    source = tmp_path / "convert.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED")
            ] == []
    found = {(c.kind, c.name) for c in result.calls}
    assert {("publish", "~out"), ("subscribe", "in"), ("subscribe", "raw_in")} <= found
