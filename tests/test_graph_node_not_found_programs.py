"""A launch file that runs a program its package (in the workspace) does not build is
told which programs the package does build, the nearest to the name first: urg_node
369ee4d's urg_node_launch.py runs ``urg_node``, an executable its CMakeLists.txt renamed
``urg_node_driver`` (the component's EXECUTABLE) in 5bcd8b6. The message said only "not
in the workspace", though the package is there."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(urg)
find_package(rclcpp_components REQUIRED)
add_library(urg SHARED src/urg_node.cpp)
rclcpp_components_register_node(urg PLUGIN "urg::UrgNode" EXECUTABLE urg_node_driver)
add_executable(getID src/get_id.cpp)
install(TARGETS urg getID RUNTIME DESTINATION lib/${PROJECT_NAME})
install(PROGRAMS scripts/set_urg_ip.py DESTINATION lib/${PROJECT_NAME})
"""

NODE = """#include <rclcpp/rclcpp.hpp>
namespace urg {
class UrgNode : public rclcpp::Node {
public:
  explicit UrgNode(const rclcpp::NodeOptions & options) : rclcpp::Node("urg_node", options) {}
};
}
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='urg', executable='urg_node'),
        Node(package='urg', executable='urg_node_driver'),
        Node(package='gone', executable='urg_node'),
    ])
"""


def _tree(write_tree, cmake=CMAKE):
    return write_tree({
        "src/urg/package.xml": package_xml("urg", "ament_cmake"),
        "src/urg/CMakeLists.txt": cmake,
        "src/urg/src/urg_node.cpp": NODE,
        "src/urg/src/get_id.cpp": "int main() { return 0; }\n",
        "src/urg/scripts/set_urg_ip.py": "#!/usr/bin/env python3\nprint('ip')\n",
        "src/urg/launch/urg.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [urg/launch/urg.launch.py]\n"})


def test_the_programs_the_package_builds_are_named(write_tree):
    root = _tree(write_tree)
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (config,) = model.configurations
    said = [(d.location.line, d.message) for d in config.diagnostics
            if d.code == "NODE_NOT_FOUND"]
    assert said == [(7, "node type urg/urg_node is not in the workspace; its interface "
                        "is unknown; package urg is in the workspace and builds "
                        "urg_node_driver, getID, set_urg_ip.py")]
    missing = [f.message for f in run_catalogue(model)
               if f.rule == "launch-missing-reference"]
    assert missing == [said[0][1]]
    # a package not here is said by NODE_PACKAGE_UNKNOWN, with no list
    (gone,) = [d.message for d in config.diagnostics if d.code == "NODE_PACKAGE_UNKNOWN"]
    assert gone.startswith("package gone of node gone/urg_node is not in the workspace")
    assert "builds" not in gone


def test_a_package_with_no_program_says_so(write_tree):
    cmake = "cmake_minimum_required(VERSION 3.8)\nproject(urg)\n"
    root = _tree(write_tree, cmake)
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (config,) = model.configurations
    said = sorted(d.message for d in config.diagnostics if d.code == "NODE_NOT_FOUND")
    assert said == [
        "node type urg/urg_node is not in the workspace; its interface is unknown; "
        "package urg is in the workspace, with no program found in its build files",
        "node type urg/urg_node_driver is not in the workspace; its interface is "
        "unknown; package urg is in the workspace, with no program found in its build files"]
