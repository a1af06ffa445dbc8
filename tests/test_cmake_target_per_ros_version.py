"""A package CMake builds under both ROS versions (catkin for ROS 1, ament_cmake for ROS 2,
chosen in package.xml by ``$ROS_VERSION``), whose CMakeLists.txt makes one executable in
each branch of ``if(ament_cmake_FOUND) ... else() ...`` from its own source, in a run that
names no ROS version (depthai-ros 22a7282: depthai_examples' ``stereo_inertial_node``).
The reading that decides no version kept one target, with the last make's sources: the
ROS 2 launch file's node ran the ROS 1 code. Each launch file's node now runs the code
its ROS version's build compiles, with the macros that build defines (depthai_bridge's
library gives its users ``PUBLIC IS_ROS2`` in its ament branch only)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from haros_arch.cli import main


def _manifest(name: str, depends: str = "") -> str:
    return f"""\
<?xml version="1.0"?>
<package format="3">
  <name>{name}</name>
  <version>0.1.0</version>
  <description>d</description>
  <maintainer email="a@b.c">m</maintainer>
  <license>MIT</license>
  <buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>
  <buildtool_depend condition="$ROS_VERSION == 2">ament_cmake</buildtool_depend>
  <depend condition="$ROS_VERSION == 1">roscpp</depend>
  <depend condition="$ROS_VERSION == 2">rclcpp</depend>
  <depend>std_msgs</depend>
  {depends}
  <export>
    <build_type condition="$ROS_VERSION == 1">catkin</build_type>
    <build_type condition="$ROS_VERSION == 2">ament_cmake</build_type>
  </export>
</package>
"""


BRIDGE_CMAKE = """\
cmake_minimum_required(VERSION 3.10)
project(bridge)
find_package(ament_cmake QUIET)
if(ament_cmake_FOUND)
  find_package(rclcpp REQUIRED)
  add_library(bridge SHARED src/bridge.cpp)
  target_compile_definitions(bridge PUBLIC USE_ROS2)
  ament_target_dependencies(bridge rclcpp)
  ament_package()
else()
  find_package(catkin REQUIRED COMPONENTS roscpp)
  catkin_package(LIBRARIES bridge)
  add_library(bridge src/bridge.cpp)
  target_link_libraries(bridge ${catkin_LIBRARIES})
endif()
"""
BRIDGE_HEADER = """\
#pragma once
#ifdef USE_ROS2
#include <rclcpp/rclcpp.hpp>
namespace bridge { using Handle = rclcpp::Node::SharedPtr; }
#else
#include <ros/ros.h>
namespace bridge { using Handle = ros::NodeHandle; }
#endif
"""
EXAMPLES_CMAKE = """\
cmake_minimum_required(VERSION 3.10)
project(examples)
find_package(ament_cmake QUIET)
if(ament_cmake_FOUND)
  find_package(rclcpp REQUIRED)
  find_package(std_msgs REQUIRED)
  find_package(bridge REQUIRED)
  include_directories(../bridge/include)
  add_executable(talker ros2_src/talker.cpp)
  ament_target_dependencies(talker rclcpp std_msgs bridge)
  install(TARGETS talker DESTINATION lib/${PROJECT_NAME})
  install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
  ament_package()
elseif(CATKIN_DEVEL_PREFIX OR CATKIN_BUILD_BINARY_PACKAGE)
  find_package(catkin REQUIRED COMPONENTS roscpp std_msgs bridge)
  catkin_package()
  include_directories(../bridge/include ${catkin_INCLUDE_DIRS})
  add_executable(talker ros1_src/talker.cpp)
  target_link_libraries(talker ${catkin_LIBRARIES})
endif()
"""
ROS1_TALKER = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <bridge/bridge.hpp>

int main(int argc, char** argv) {
  ros::init(argc, argv, "talker");
  bridge::Handle nh("~");
  ros::Publisher pub = nh.advertise<std_msgs::String>("ros1_chatter", 1);
  ros::spin();
  return 0;
}
"""
ROS2_TALKER = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <bridge/bridge.hpp>

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  bridge::Handle node = rclcpp::Node::make_shared("talker");
  auto pub = node->create_publisher<std_msgs::msg::String>("ros2_chatter", 1);
  rclcpp::spin(node);
  return 0;
}
"""
ROS1_LAUNCH = """\
<launch>
  <node pkg="examples" type="talker" name="talker"/>
</launch>
"""
ROS2_LAUNCH = """\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='examples', executable='talker', name='talker')])
"""


def _workspace(root: Path) -> Path:
    files = {
        "bridge/package.xml": _manifest("bridge"),
        "bridge/CMakeLists.txt": BRIDGE_CMAKE,
        "bridge/include/bridge/bridge.hpp": BRIDGE_HEADER,
        "bridge/src/bridge.cpp": "#include <bridge/bridge.hpp>\n",
        "examples/package.xml": _manifest("examples", "<depend>bridge</depend>"),
        "examples/CMakeLists.txt": EXAMPLES_CMAKE,
        "examples/ros1_src/talker.cpp": ROS1_TALKER,
        "examples/ros2_src/talker.cpp": ROS2_TALKER,
        "examples/launch/talker.launch": ROS1_LAUNCH,
        "examples/launch/talker.launch.py": ROS2_LAUNCH,
    }
    for rel, text in files.items():
        path = root / "src" / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


@pytest.fixture
def checked(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> dict:
    for name in ("ROS_VERSION", "ROS_DISTRO", "ROS_PYTHON_VERSION"):
        monkeypatch.delenv(name, raising=False)
    root = _workspace(tmp_path / "ws")
    out = tmp_path / "model.json"
    assert main(["extract", str(root), "-o", str(out), "--no-cache", "-q"]) == 0
    return json.loads(out.read_text())


def _links(model: dict, launch: str) -> list[tuple[str, str, str]]:
    (found,) = [c for c in model["configurations"] if c["launch"] == [launch]]
    return sorted((link["kind"], link["node"], link["name"]) for link in found["links"])


def test_each_launch_file_runs_its_ros_version_s_build_of_the_target(checked: dict) -> None:
    assert _links(checked, "examples/launch/talker.launch") == [
        ("publish", "/talker", "/talker/ros1_chatter")]
    # the ament build's source, with the macro the linked library's ament build gives
    assert _links(checked, "examples/launch/talker.launch.py") == [
        ("publish", "/talker", "/ros2_chatter")]


def test_the_ros_2_node_is_read_whole(checked: dict) -> None:
    partial = [d["message"] for d in checked["diagnostics"]
               if d["code"] in ("CPP_NODE_PARTIAL", "CPP_ERROR_NEAR_CALL")]
    assert partial == []
