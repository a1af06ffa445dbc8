"""ROS calls chosen with a macro the package's CMake defines (livox_ros_driver2's
``add_definitions(-DBUILDING_ROS2)`` and ``#elif defined BUILDING_ROS2`` around its
declarations and publishers) under an if() the analysis cannot decide: the macro is not
applied, so the node was read empty and complete (9 false "set but never read"
warnings). It says so (CPP_BUILD_MACRO) and the node is partial; with a
compile_commands.json it is not said. (A macro defined unconditionally is applied:
test_extract_cpp_cmake_definitions.)"""

from __future__ import annotations

import json
import os

import pytest
from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_rule

NODE = """
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Driver : public rclcpp::Node {
public:
  Driver() : Node("driver") {
#ifdef BUILDING_ROS2
    this->declare_parameter("frame_id", std::string("lidar"));
    pub_ = create_publisher<std_msgs::msg::String>("points", 10);
#endif
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Driver>());
}
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='drv', executable='driver',
                                   parameters=[{'frame_id': 'lidar'}])])
"""


def _model(write_tree, commands: bool):
    files = {
        "src/drv/package.xml": package_xml("drv", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend></package>"),
        "src/drv/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(drv)\n"
                                  "if(ROS_EDITION STREQUAL \"ROS2\")\n"
                                  "  add_definitions(-DBUILDING_ROS2)\nendif()\n"
                                  "add_executable(driver src/driver.cpp)\n",
        "src/drv/src/driver.cpp": NODE,
        "src/drv/launch/drv.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [drv/launch/drv.launch.py]\n",
    }
    root = write_tree(files)
    if commands:
        source = root / "src/drv/src/driver.cpp"
        entry = {"directory": str(root / "src"), "file": str(source),
                 "command": f"c++ -DBUILDING_ROS2 -c {source}"}
        (root / "src/compile_commands.json").write_text(json.dumps([entry]))
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def test_calls_under_a_macro_the_cmake_defines_make_the_node_partial(write_tree) -> None:
    model = _model(write_tree, False)
    node = next(n for p in model.packages for n in p.nodes if n.executable == "driver")
    assert node.completeness == "partial"
    said = [d for d in model.diagnostics if d.code == "CPP_BUILD_MACRO"]
    assert [(d.location.line, d.severity) for d in said] == [(8, "warning")]
    assert "BUILDING_ROS2" in said[0].message and "CMakeLists.txt:4" in said[0].message
    # its parameter is not said set and never read (the node may read it): undecided
    rule = next(r for r in load_catalogue() if r.id == "parameter-set-not-read")
    assert [f.rule for f in run_rule(rule, model)] == ["parameter-set-not-read-undecided"]


def test_with_the_build_s_compile_commands_the_macro_is_applied(write_tree) -> None:
    model = _model(write_tree, True)
    node = next(n for p in model.packages for n in p.nodes if n.executable == "driver")
    assert node.completeness == "complete"
    assert ("publish", "points") in {(c.kind, c.name) for c in node.calls}
    assert not [d for d in model.diagnostics if d.code == "CPP_BUILD_MACRO"]


COMPAT = """
#pragma once
#include <memory>
#include <rclcpp/rclcpp.hpp>
extern rclcpp::Node::SharedPtr node;
#ifdef BUILDING_ROS1
#define DECLARE(name, value) private_nh.param(name, value, value)
#elif defined BUILDING_ROS2
template <typename T>
void declare_it(const std::string & name, const T & value) {
  node->declare_parameter(name, value);
}
#define DECLARE(name, value) declare_it(name, value)
#endif
"""

WRAPPED = """
#include "common.hpp"
rclcpp::Node::SharedPtr node;
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  node = std::make_shared<rclcpp::Node>("driver");
  DECLARE("frame_id", std::string("lidar"));
  rclcpp::spin(node);
}
"""


DUAL_MANIFEST = (
    '<buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>'
    '<buildtool_depend condition="$ROS_VERSION == 2">ament_cmake</buildtool_depend>'
    '<depend condition="$ROS_VERSION == 2">rclcpp</depend>'
    '<depend condition="$ROS_VERSION == 1">roscpp</depend><export>'
    '<build_type condition="$ROS_VERSION == 1">catkin</build_type>'
    '<build_type condition="$ROS_VERSION == 2">ament_cmake</build_type></export></package>')


def test_calls_under_a_macro_in_a_header_of_the_package_make_the_node_partial(
        write_tree) -> None:
    """ros_deep_learning: its nodes call macros (ROS_DECLARE_PARAMETER) that ros_compat.h
    defines under ``#ifdef ROS1`` / ``#elif ROS2``, the macro the CMake defines under
    ``if(catkin_FOUND)``: neither applied, the nodes were read with no call and complete
    (41 false warnings). The header, included through another one, is read for such
    blocks: said there, once, and the node is partial."""
    files = {
        # built by catkin or by ament as the ROS version chooses: catkin_FOUND follows
        # the run's ROS version, which names none (test_package_xml_s_build_tool_...)
        "src/drv/package.xml": package_xml("drv").replace("</package>", DUAL_MANIFEST),
        "src/drv/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(drv)\n"
                                  "find_package(catkin QUIET)\n"
                                  "if(catkin_FOUND)\n  add_definitions(-DBUILDING_ROS1)\n"
                                  "else()\n  add_definitions(-DBUILDING_ROS2)\nendif()\n"
                                  "add_executable(driver src/driver.cpp src/other.cpp)\n",
        "src/drv/src/driver.cpp": WRAPPED,
        "src/drv/src/other.cpp": '#include "drv/compat.hpp"\n',
        "src/drv/src/common.hpp": '#pragma once\n#include "drv/compat.hpp"\n',
        "src/drv/include/drv/compat.hpp": COMPAT,
        "src/drv/launch/drv.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [drv/launch/drv.launch.py]\n",
    }
    root = write_tree(files)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    node = next(n for p in model.packages for n in p.nodes if n.executable == "driver")
    assert node.completeness == "partial"
    said = [d for d in model.diagnostics if d.code == "CPP_BUILD_MACRO"]
    assert [(d.location.file, d.location.line) for d in said] == [
        ("drv/include/drv/compat.hpp", 10)]
    assert "declare_parameter" in said[0].message and "BUILDING_ROS2" in said[0].message
    rule = next(r for r in load_catalogue() if r.id == "parameter-set-not-read")
    assert [f.rule for f in run_rule(rule, model)] == ["parameter-set-not-read-undecided"]


BOTH_NODE = """
#ifdef BUILDING_ROS1
#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char ** argv) {
  ros::init(argc, argv, "driver");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::String>("points1", 10);
  ros::spin();
}
#else
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("driver");
  auto pub = node->create_publisher<std_msgs::msg::String>("points2", 10);
  rclcpp::spin(node);
}
#endif
"""


@pytest.mark.parametrize(("manifest", "topics"), [
    # ros_deep_learning: a catkin package.xml (format 1, buildtool catkin)
    ("<buildtool_depend>catkin</buildtool_depend><depend>roscpp</depend></package>",
     ["points1"]),
    ("<buildtool_depend>ament_cmake</buildtool_depend><depend>rclcpp</depend>"
     "<export><build_type>ament_cmake</build_type></export></package>", ["points2"]),
    (DUAL_MANIFEST, None),  # both, by $ROS_VERSION: the run's version decides
])
def test_package_xml_s_build_tool_decides_catkin_found(write_tree, manifest, topics) -> None:
    """ros_deep_learning's CMakeLists.txt picks ROS 1 or ROS 2 with ``find_package(catkin
    QUIET)`` / ``if(catkin_FOUND)`` and defines the macro its sources test there; its
    package.xml is the ROS 1 one, which colcon builds with catkin: with no ROS version
    given, catkin_FOUND was undecided and the nodes partial (CPP_BUILD_MACRO). The
    package.xml's build tool decides it when it names one only."""
    root = write_tree({
        "src/drv/package.xml": package_xml("drv").replace("</package>", manifest),
        "src/drv/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(drv)\n"
                                  "find_package(catkin QUIET)\n"
                                  "if(catkin_FOUND)\n  add_definitions(-DBUILDING_ROS1)\n"
                                  "else()\n  find_package(ament_cmake QUIET)\n"
                                  "  if(ament_cmake_FOUND)\n"
                                  "    add_definitions(-DBUILDING_ROS2)\n  endif()\n"
                                  "endif()\nadd_executable(driver src/driver.cpp)\n",
        "src/drv/src/driver.cpp": BOTH_NODE,
        "project.yaml": "project: p\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    node = next(n for p in model.packages for n in p.nodes if n.executable == "driver")
    said = [d for d in model.diagnostics if d.code == "CPP_BUILD_MACRO"]
    if topics is None:
        assert node.completeness == "partial" and said
        return
    assert node.completeness == "complete" and not said
    assert [c.name for c in node.calls if c.kind == "publish"] == topics
