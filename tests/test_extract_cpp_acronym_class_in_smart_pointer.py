"""A class named in capitals (an acronym: ``CLAHE``) given to a smart pointer template
(``cv::Ptr``, ``boost::shared_ptr``, ``std::shared_ptr``), its header missing, is a type,
not a constant. ORB_SLAM3_ROS2 (00c5433) declares ``cv::Ptr<cv::CLAHE> clahe_`` in
StereoInertialNode (stereo-inertial-node.hpp:53; OpenCV's imgproc not among the
stand-ins): ``CLAHE`` was read as a template's non-type argument, the member was an
error, the class invalid, and the three subscriptions of its constructor unresolved
(``no matching member function for call to 'create_subscription'``). The rule that
names std's templates whose first argument is a type also missed a qualified name
(``std::shared_ptr<vendor::MODE>``): it looked at the text up to the name's scope."""

from __future__ import annotations

import pytest

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/imu.hpp"
#include <opencv2/core/core.hpp>
#include <vendor/filters.h>
class InertialNode : public rclcpp::Node {
 public:
  InertialNode() : Node("inertial") {
    sub_ = create_subscription<sensor_msgs::msg::Imu>(
        "imu", 1000, std::bind(&InertialNode::grab, this, std::placeholders::_1));
  }
  void grab(const sensor_msgs::msg::Imu::SharedPtr msg) { (void)msg; }
  POINTER<SCOPE::CLAHE> clahe_;
  rclcpp::Subscription<sensor_msgs::msg::Imu>::SharedPtr sub_;
};
int main(int argc, char **argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<InertialNode>());
}
"""


@pytest.mark.parametrize("pointer,scope", [
    ("cv::Ptr", "cv"), ("boost::shared_ptr", "vendor"), ("std::shared_ptr", "vendor"),
    ("std::shared_ptr", "cv")])
def test_an_acronym_class_in_a_smart_pointer(write_tree, pointer, scope) -> None:
    source = NODE.replace("POINTER", pointer).replace("SCOPE", scope)
    root = write_tree({"p/package.xml": package_xml("p", build_type="ament_cmake"),
                       "p/src/node.cpp": source})
    result = extract_cpp([str(root / "p" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls if c.kind == "subscribe"] == [
        ("subscribe", "imu")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" not in codes and "CPP_CALL_UNRESOLVED" not in codes
