"""ROS_PACKAGE_NAME: defined in each unit as its package's build defines it (catkin
through rosconsole, ament_cmake_ros), part of what keys the unit's cached result."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

# hector_slam's hector_imu_attitude_to_tf
ROS1 = """
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
void cb(const sensor_msgs::Imu::ConstPtr& m) {}
int main(int argc, char** argv) {
  ros::init(argc, argv, ROS_PACKAGE_NAME);
  ros::NodeHandle nh;
  ros::Subscriber s = nh.subscribe("imu_topic", 10, cb);
  ros::spin();
}
"""

ROS2 = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>(ROS_PACKAGE_NAME);
  auto p = node->create_publisher<std_msgs::msg::String>("out", 10);
}
"""


def manifest(name: str, tool: str, *depends: str) -> str:
    deps = "".join(f"<depend>{d}</depend>" for d in depends)
    return (f'<?xml version="1.0"?>\n<package format="2"><name>{name}</name>'
            '<version>0.1.0</version><description>d</description>'
            '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
            f"<buildtool_depend>{tool}</buildtool_depend>{deps}</package>\n")


def extract(root: Path, package: str, cache: Path | None = None):
    source = root / "src" / package / "src" / "main.cpp"
    return extract_cpp([str(source)], scan([str(root / "src")]), cache_dir=cache)


def test_a_catkin_package_defines_it_and_names_the_node(write_tree, tmp_path):
    root = write_tree({"src/imu/package.xml": manifest("imu_to_tf", "catkin", "roscpp"),
                       "src/imu/src/main.cpp": ROS1})
    cache = tmp_path / "cache"
    for name in ("imu_to_tf", "imu_attitude_to_tf", "imu_to_tf"):
        # the package renamed, its file unchanged: another key, not the cached result
        (root / "src/imu/package.xml").write_text(manifest(name, "catkin", "roscpp"))
        result = extract(root, "imu", cache)
        assert result.rosname == name
        assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "imu_topic")]
        assert result.diagnostics == []


def test_ament_cmake_ros_defines_it_plain_ament_cmake_does_not(write_tree):
    root = write_tree({
        "src/with_ros/package.xml": manifest(
            "with_ros", "ament_cmake_ros", "rclcpp", "std_msgs"),
        "src/with_ros/src/main.cpp": ROS2,
        "src/plain/package.xml": manifest("plain", "ament_cmake", "rclcpp", "std_msgs"),
        "src/plain/src/main.cpp": ROS2})
    result = extract(root, "with_ros")
    assert result.rosname == "with_ros" and result.diagnostics == []
    plain = extract(root, "plain")
    assert plain.rosname != "plain"
    assert any("ROS_PACKAGE_NAME" in d.message for d in plain.diagnostics)
