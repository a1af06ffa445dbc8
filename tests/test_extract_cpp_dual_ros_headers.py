"""Code kept for both ROS versions (open_vins' ov_msckf: a package.xml whose every
dependency is under ``condition="$ROS_VERSION == ..."``, so that a run naming no ROS
version cannot tell from it) includes each version's headers under a preprocessor
condition: its ROS1Visualizer.cpp includes ``ros/ros.h`` and a helper header that has
``#if ROS_AVAILABLE == 1`` roscpp's message headers, ``#elif ROS_AVAILABLE == 2``
rclcpp's. A ROS 2 header included only under a condition does not make ROS 2 code of a
unit that includes a ROS 1 header under none: the unit is read as ROS 1 (boost::bind's
``_1`` in the global namespace), and the subscriber bound with ``_1`` is found."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

PACKAGE = """\
<?xml version="1.0"?>
<package format="3">
  <name>dual</name>
  <version>0.0.1</version>
  <description>d</description>
  <maintainer email="a@b.c">a</maintainer>
  <license>MIT</license>
  <buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>
  <depend condition="$ROS_VERSION == 1">roscpp</depend>
  <depend condition="$ROS_VERSION == 1">sensor_msgs</depend>
  <buildtool_depend condition="$ROS_VERSION == 2">ament_cmake</buildtool_depend>
  <depend condition="$ROS_VERSION == 2">rclcpp</depend>
  <depend condition="$ROS_VERSION == 2">sensor_msgs</depend>
  <export>
    <build_type condition="$ROS_VERSION == 1">catkin</build_type>
    <build_type condition="$ROS_VERSION == 2">ament_cmake</build_type>
  </export>
</package>
"""

HELPER = """\
#ifndef DUAL_HELPER_H
#define DUAL_HELPER_H
#if ROS_AVAILABLE == 1
#include <sensor_msgs/Image.h>
#elif ROS_AVAILABLE == 2
#include <sensor_msgs/msg/image.hpp>
#include <rclcpp/rclcpp.hpp>
#endif
#endif
"""

SOURCE = """\
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include "helper.h"
class Viz {
 public:
  explicit Viz(ros::NodeHandle nh) : nh_(nh) {
    sub_ = nh_.subscribe<sensor_msgs::Image>("cam0", 10, boost::bind(&Viz::mono, this, _1, 0));
  }
  void mono(const sensor_msgs::ImageConstPtr & msg, int id);
  ros::NodeHandle nh_;
  ros::Subscriber sub_;
};
int main(int argc, char ** argv) {
  ros::init(argc, argv, "viz");
  Viz viz(ros::NodeHandle("~"));
  ros::spin();
}
"""


def test_ros2_headers_under_a_condition_do_not_make_ros1_code_ros2(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(PACKAGE)
    (tmp_path / "helper.h").write_text(HELPER)
    source = tmp_path / "viz.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "~cam0")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_ERROR_NEAR_CALL" not in codes


def test_ros2_code_with_ros2_headers_under_a_condition_stays_ros2(tmp_path) -> None:
    """Without a ROS 1 header outside conditions, a conditional rclcpp still tells."""
    (tmp_path / "package.xml").write_text(PACKAGE)
    (tmp_path / "helper.h").write_text(HELPER)
    source = tmp_path / "node.cpp"
    source.write_text("""\
#include "helper.h"
#include <std_msgs/msg/string.hpp>
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("talker");
  auto pub = node->create_publisher<std_msgs::msg::String>("chatter", 10);
  rclcpp::spin(node);
}
""")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "chatter")]


def test_conditional_spans_leave_out_the_include_guard() -> None:
    from haros_arch.extract.cpp.headers import _conditional_spans
    text = HELPER
    spans = _conditional_spans(text)
    inside = [text.index(h) for h in ("sensor_msgs/Image.h", "rclcpp/rclcpp.hpp")]
    assert all(any(a <= i < b for a, b in spans) for i in inside)
    assert not any(a <= text.index("#define DUAL_HELPER_H") < b for a, b in spans)
