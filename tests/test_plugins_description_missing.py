"""A plugin description that package.xml exports and that is not there: an error for a
catkin package (ROS 1's pluginlib reads package.xml's exports, and fails on it); nothing
for an ament package, whose pluginlib reads only what its CMake files export with
``pluginlib_export_plugin_description_file`` (moveit2_tutorials 21a45aa keeps ROS 1's
``<moveit_core plugin="${prefix}/doc/controller_configuration/...xml"/>`` for a folder
its CMakeLists.txt no longer adds: two FILE_UNREADABLE errors before)."""

from __future__ import annotations

from haros_arch.cmake import parse_package
from haros_arch.workspace import scan

PACKAGE = """<?xml version="1.0"?>
<package format="3">
  <name>plug</name><version>0.1.0</version><description>x</description>
  <maintainer email="a@b.c">a</maintainer><license>BSD</license>
  <buildtool_depend>{tool}</buildtool_depend>
  <depend>{client}</depend>
  <depend>moveit_core</depend>
  <export>
    <build_type>{tool}</build_type>
    <moveit_core plugin="${{prefix}}/doc/gone/plugin_description.xml"/>
  </export>
</package>
"""


def _codes(write_tree, tool: str, client: str) -> list[str]:
    root = write_tree({
        "plug/package.xml": PACKAGE.format(tool=tool, client=client),
        "plug/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(plug)\n",
    })
    workspace = scan([str(root)])
    _, found = parse_package(workspace.packages["plug"], workspace)
    return [d.code for d in found]


def test_an_ament_package_xml_export_of_no_file_is_no_error(write_tree) -> None:
    assert "FILE_UNREADABLE" not in _codes(write_tree, "ament_cmake", "rclcpp")


def test_a_catkin_package_xml_export_of_no_file_is_an_error(write_tree) -> None:
    assert "FILE_UNREADABLE" in _codes(write_tree, "catkin", "roscpp")
