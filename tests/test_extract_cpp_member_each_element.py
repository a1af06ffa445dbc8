"""A member a class's constructor (in the same file) keeps from its parameter, where
every construction passes an element of a list parameter: the class's reads named with
the member are one per element (``PrimitiveCall.name_each``), as when the element is
used directly. navigation2's collision monitor builds a polygon per element of
``polygons`` and each reads ``polygon_name_ + ".points"`` and so on; in one file that
read was ``?.points``, undecided, so a misspelt key under a polygon went unreported."""

from __future__ import annotations

import json

from haros_arch.cli import main
from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
class Poly {
public:
  Poly(rclcpp::Node * node, const std::string & name) : node_(node), name_(name) {}
  void configure() {
    points_ = node_->declare_parameter<std::vector<double>>(name_ + ".points");
    fixed_ = node_->declare_parameter<double>(other_ + ".margin", 0.1);
  }
  rclcpp::Node * node_;
  std::string name_;
  std::string other_;
  std::vector<double> points_;
  double fixed_;
};
class Monitor : public rclcpp::Node {
public:
  Monitor() : rclcpp::Node("monitor") {
    auto names = declare_parameter<std::vector<std::string>>(
      "polygons", std::vector<std::string>());
    for (const auto & name : names) {
      auto p = std::make_shared<Poly>(this, name);
      p->configure();
      polys_.push_back(p);
    }
  }
  std::vector<std::shared_ptr<Poly>> polys_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Monitor>());
}
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(pm)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
add_executable(monitor src/monitor.cpp)
ament_target_dependencies(monitor rclcpp)
install(TARGETS monitor DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
ament_package()
"""

LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(
        package='pm', executable='monitor', name='monitor',
        parameters=[{'polygons': ['Stop', 'Slow'], 'Stop.points': [0.1, 0.1],
                     'Slow.pionts': [0.2, 0.2]}])])
"""


def _tree(write_tree):
    return write_tree({"pm/package.xml": package_xml("pm", "ament_cmake"),
                       "pm/CMakeLists.txt": CMAKE, "pm/src/monitor.cpp": NODE,
                       "pm/launch/monitor.launch.py": LAUNCH})


def test_a_member_kept_from_each_element_names_one_read_per_element(write_tree) -> None:
    root = _tree(write_tree)
    result = extract_cpp([str(root / "pm" / "src" / "monitor.cpp")], scan([str(root)]),
                         cache_dir=None, distro="jazzy")
    made = sorted((c.name, c.name_param, c.name_each) for c in result.calls
                  if c.kind == "declare" and c.name != "polygons")
    assert made == [("?.margin", None, None),  # a member no constructor sets
                    ("?.points", "polygons", ".")]


def test_the_misspelt_key_of_one_element_is_found(write_tree) -> None:
    root = _tree(write_tree)
    out = root / "check.json"
    main(["check", str(root), "--format", "json", "-o", str(out), "--fail-on", "never"])
    found = sorted((f["rule"], f["entities"])
                   for f in json.loads(out.read_text())["findings"]
                   if f["rule"].startswith("parameter-") and f["severity"] != "info")
    assert found == [
        ("parameter-read-not-set", ["parameter:/monitor/Slow.points"]),
        ("parameter-set-not-read", ["parameter:/monitor/Slow.pionts"]),
    ], found
