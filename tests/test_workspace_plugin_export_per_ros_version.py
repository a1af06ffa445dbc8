"""A package kept for both ROS versions exports its nodelet for ROS 1 only
(foxglove_bridge 4e801bb: ``<nodelet condition="$ROS_VERSION == 1" plugin=
"${prefix}/nodelets.xml"/>``, the library built under ``if("$ENV{ROS_VERSION}" STREQUAL
"1")``), and its ROS 1 launch file loads that nodelet into a manager. A run that names
no ROS version reads each version's build (PACKAGE_BUILD_BY_ROS_VERSION), but took the
export's condition as false (ROS_VERSION empty): the nodelet was "not in the workspace"
(launch-missing-reference, an error) and its interface unknown. The export is read now
when its condition holds for either version; a run for ROS 2 still leaves it out."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from haros_arch.cli import main

MANIFEST = """\
<?xml version="1.0"?>
<package format="3">
  <name>bridge</name>
  <version>0.1.0</version>
  <description>d</description>
  <maintainer email="a@b.c">m</maintainer>
  <license>MIT</license>
  <buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>
  <buildtool_depend condition="$ROS_VERSION == 2">ament_cmake</buildtool_depend>
  <depend condition="$ROS_VERSION == 1">nodelet</depend>
  <depend condition="$ROS_VERSION == 1">roscpp</depend>
  <depend condition="$ROS_VERSION == 2">rclcpp</depend>
  <depend>std_msgs</depend>
  <export>
    <build_type condition="$ROS_VERSION == 1">catkin</build_type>
    <build_type condition="$ROS_VERSION == 2">ament_cmake</build_type>
    <nodelet condition="$ROS_VERSION == 1" plugin="${prefix}/nodelets.xml"/>
  </export>
</package>
"""
CMAKE = """\
cmake_minimum_required(VERSION 3.10)
project(bridge)
if("$ENV{ROS_VERSION}" STREQUAL "1")
  find_package(catkin REQUIRED COMPONENTS nodelet roscpp std_msgs)
  catkin_package(LIBRARIES bridge_nodelet)
  add_library(bridge_nodelet src/bridge_nodelet.cpp)
elseif("$ENV{ROS_VERSION}" STREQUAL "2")
  find_package(ament_cmake REQUIRED)
  find_package(rclcpp REQUIRED)
  add_executable(bridge_node src/bridge_node.cpp)
  ament_package()
endif()
"""
NODELETS = """\
<library path="lib/libbridge_nodelet">
  <class name="bridge/bridge_nodelet" type="bridge::Bridge" base_class_type="nodelet::Nodelet">
    <description>d</description>
  </class>
</library>
"""
NODELET = """\
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

namespace bridge {
class Bridge : public nodelet::Nodelet {
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    pub_ = nh.advertise<std_msgs::String>("status", 1);
  }
  ros::Publisher pub_;
};
}  // namespace bridge

PLUGINLIB_EXPORT_CLASS(bridge::Bridge, nodelet::Nodelet)
"""
NODE = """\
#include <rclcpp/rclcpp.hpp>

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("bridge");
  rclcpp::spin(node);
}
"""
LAUNCH = """\
<launch>
  <node pkg="nodelet" type="nodelet" name="manager" args="manager"/>
  <node pkg="nodelet" type="nodelet" name="bridge" args="load bridge/bridge_nodelet manager"/>
</launch>
"""


def _run(tmp_path: Path) -> tuple[dict, dict]:
    """The extracted model and the check's report."""
    root = tmp_path / "ws"
    for rel, text in {"package.xml": MANIFEST, "CMakeLists.txt": CMAKE,
                      "nodelets.xml": NODELETS, "src/bridge_nodelet.cpp": NODELET,
                      "src/bridge_node.cpp": NODE, "launch/bridge.launch": LAUNCH}.items():
        path = root / "src" / "bridge" / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    model, report = tmp_path / "model.json", tmp_path / "check.json"
    assert main(["extract", str(root), "--no-cache", "-q", "-o", str(model)]) == 0
    main(["check", str(root), "--no-cache", "--format", "json", "-o", str(report),
          "--fail-on", "never"])
    return json.loads(model.read_text()), json.loads(report.read_text())


@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    for name in ("ROS_VERSION", "ROS_DISTRO", "ROS_PYTHON_VERSION"):
        monkeypatch.delenv(name, raising=False)


def test_a_nodelet_exported_for_ros1_is_read_with_no_version_given(tmp_path: Path) -> None:
    model, report = _run(tmp_path)
    assert [f for f in report["findings"] if f["rule"] == "launch-missing-reference"] == []
    (config,) = model["configurations"]
    assert ("publish", "/bridge", "/status") in [
        (link["kind"], link["node"], link["name"]) for link in config["links"]]


def test_a_run_for_ros2_leaves_the_ros1_export_out(tmp_path: Path,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ROS_VERSION", "2")
    monkeypatch.setenv("ROS_DISTRO", "jazzy")
    model, _ = _run(tmp_path)
    (package,) = model["packages"]
    assert [n["name"] for n in package["nodes"]] == ["bridge/bridge_node"]
