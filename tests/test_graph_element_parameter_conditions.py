"""A condition on a local that holds the parameter each element of a list parameter
names: navigation2's collision monitor walks ``polygons`` and reads, for each
``polygon_name``, ``const std::string polygon_type = declare_or_get_parameter<
std::string>(polygon_name + ".type")``, then builds a circle, a polygon or a velocity
polygon by ``polygon_type``, each reading its own parameters. The condition names the
parameter by its element (``Condition.elements``, ``ELEMENT_PARAMETER``), and the graph,
making the calls of each element, decides it by the parameter that element names: the
value the configuration gives it, else the code's default. Without it every
``polygon_type`` test stayed undecided, so a misspelt ``raduis`` went unreported and
``Stop.radius`` was "maybe never read" though the code reads it."""

from __future__ import annotations

import json

from haros_arch.cli import main
from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
class Monitor : public rclcpp::Node {
public:
  Monitor() : rclcpp::Node("monitor") {
    std::vector<std::string> names = declare_parameter<std::vector<std::string>>(
      "polygons", std::vector<std::string>());
    for (const std::string & polygon_name : names) {
      const std::string polygon_type =
        declare_parameter<std::string>(polygon_name + ".type", "polygon");
      if (polygon_type == "circle") {
        declare_parameter<double>(polygon_name + ".radius");
      } else if (polygon_type == "polygon") {
        declare_parameter<std::vector<double>>(polygon_name + ".points");
      }
    }
  }
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Monitor>());
}
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(cm)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
add_executable(monitor src/monitor.cpp)
ament_target_dependencies(monitor rclcpp)
install(TARGETS monitor DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})
ament_package()
"""

LAUNCH = """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    params = os.path.join(get_package_share_directory('cm'), 'config', 'monitor.yaml')
    return LaunchDescription([
        Node(package='cm', executable='monitor', name='monitor', parameters=[params])])
"""

PARAMS = """monitor:
  ros__parameters:
    polygons: ["Stop", "Slow", "Third"]
    Stop:
      type: circle
      raduis: 0.3
    Slow:
      type: polygon
      points: [0.1, 0.1, -0.1, 0.1]
    Third:
      points: [0.2, 0.2, -0.2, 0.2]
"""


def _tree(write_tree):
    return write_tree({"cm/package.xml": package_xml("cm", "ament_cmake"),
                       "cm/CMakeLists.txt": CMAKE, "cm/src/monitor.cpp": NODE,
                       "cm/launch/monitor.launch.py": LAUNCH,
                       "cm/config/monitor.yaml": PARAMS})


def test_the_condition_names_the_parameter_its_element_names(write_tree) -> None:
    root = _tree(write_tree)
    result = extract_cpp([str(root / "cm" / "src" / "monitor.cpp")], scan([str(root)]),
                         cache_dir=None, distro="jazzy")
    held = {c.name: [(k.text, k.elements) for k in c.conditions if k.statement != "for each"]
            for c in result.calls if c.name in ("?.radius", "?.points")}
    assert held == {
        "?.radius": [('polygon_type == "circle"',
                      (("polygon_type", "polygons", "parameter:?.type"),))],
        "?.points": [('polygon_type == "circle"',
                      (("polygon_type", "polygons", "parameter:?.type"),)),
                     ('polygon_type == "polygon"',
                      (("polygon_type", "polygons", "parameter:?.type"),))]}


def test_the_graph_decides_each_element_by_its_own_parameter(write_tree) -> None:
    root = _tree(write_tree)
    out = root / "check.json"
    main(["check", str(root), "--format", "json", "-o", str(out), "--fail-on", "never"])
    found = sorted((f["rule"], f["entities"])
                   for f in json.loads(out.read_text())["findings"]
                   if f["rule"].startswith("parameter-"))
    # Stop is a circle: its radius is read (and not set: "raduis" is set, never read);
    # Slow a polygon; Third's type is not set, the code's default "polygon": its points
    # are read. Nothing is left undecided.
    assert found == [
        ("parameter-read-not-set", ["parameter:/monitor/Stop.radius"]),
        ("parameter-set-not-read", ["parameter:/monitor/Stop.raduis"]),
    ], found


WRAPPED = """
#include <rclcpp/rclcpp.hpp>
template<typename ParameterT, typename NodeT>
inline ParameterT declare_or_get(NodeT node, const std::string & parameter_name)
{
  if (node->has_parameter(parameter_name)) {
    return node->get_parameter(parameter_name).template get_value<ParameterT>();
  }
  auto param_type = rclcpp::ParameterValue{ParameterT{}}.get_type();
  auto parameter = node->declare_parameter(parameter_name, param_type);
  return parameter.template get<ParameterT>();
}
class Monitor : public rclcpp::Node {
public:
  Monitor() : rclcpp::Node("monitor") {
    std::vector<std::string> names = declare_parameter<std::vector<std::string>>(
      "polygons", std::vector<std::string>());
    for (const std::string & polygon_name : names) {
      const std::string polygon_type =
        declare_or_get<std::string>(this, polygon_name + ".type");
      if (polygon_type == "circle") {
        declare_parameter<double>(polygon_name + ".radius");
      } else if (polygon_type == "polygon") {
        declare_parameter<std::vector<double>>(polygon_name + ".points");
      }
    }
  }
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Monitor>());
}
"""


def test_a_wrapper_returning_the_value_types_the_read(write_tree) -> None:
    """navigation2 reads the type through its ``declare_or_get_parameter<std::string>``,
    which declares by ``rclcpp::ParameterValue{ParameterT{}}.get_type()``: the read is
    of the type the call returns, so the configured string decides the tests."""
    root = write_tree({"cm/package.xml": package_xml("cm", "ament_cmake"),
                       "cm/CMakeLists.txt": CMAKE, "cm/src/monitor.cpp": WRAPPED,
                       "cm/launch/monitor.launch.py": LAUNCH,
                       "cm/config/monitor.yaml": PARAMS.replace(
                           "    Third:\n      points", "    Third:\n      type: polygon\n"
                           "      points")})
    result = extract_cpp([str(root / "cm" / "src" / "monitor.cpp")], scan([str(root)]),
                         cache_dir=None, distro="jazzy")
    assert {(c.kind, c.type) for c in result.calls if c.name == "?.type"} == {
        ("read", "str"), ("declare", "str")}
    out = root / "check.json"
    main(["check", str(root), "--format", "json", "-o", str(out), "--fail-on", "never"])
    found = sorted((f["rule"], f["entities"])
                   for f in json.loads(out.read_text())["findings"]
                   if f["rule"].startswith("parameter-"))
    assert found == [
        ("parameter-read-not-set", ["parameter:/monitor/Stop.radius"]),
        ("parameter-set-not-read", ["parameter:/monitor/Stop.raduis"]),
    ], found
