"""A header-only library, ``add_library(name INTERFACE)``, gives the targets linking it
its INTERFACE include folders. mrover-ros2 c7572baf makes ``motor``, ``can_device``
and others with a macro (``add_library(${name} INTERFACE)``,
``target_include_directories(${name} INTERFACE ${includes})``) and its hardware
bridge nodes link them: the library was not made, so ``#include "brushless.hpp"`` was
not found, the motor controllers that declare the node's parameters were not read, and
drive_hw_bridge got 18 false parameter-set-not-read warnings."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(rov)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
find_package(std_msgs REQUIRED)
include_directories(other)
macro(header_only_library name includes)
  add_library(${name} INTERFACE)
  target_include_directories(${name} INTERFACE ${includes})
endmacro()
header_only_library(motor esw/motor)
add_executable(bridge src/bridge.cpp)
ament_target_dependencies(bridge rclcpp std_msgs)
target_link_libraries(bridge motor)
install(TARGETS bridge DESTINATION lib/${PROJECT_NAME})
ament_package()
"""

HEADER = """#pragma once
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>
class Motor {
public:
  explicit Motor(rclcpp::Node::SharedPtr const& node) {
    max_torque_ = node->declare_parameter<double>("max_torque", 1.0);
    pub_ = node->create_publisher<std_msgs::msg::Float64>("torque", 10);
  }
private:
  double max_torque_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
};
"""

NODE = """#include <rclcpp/rclcpp.hpp>
#include "motor.hpp"
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("bridge");
  Motor motor(node);
  rclcpp::spin(node);
}
"""


def test_interface_library_gives_its_include_folders(write_tree):
    root = write_tree({
        "src/rov/package.xml": package_xml("rov", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "src/rov/CMakeLists.txt": CMAKE,
        "src/rov/esw/motor/motor.hpp": HEADER,
        "src/rov/other/unrelated.hpp": "#pragma once\n",
        "src/rov/src/bridge.cpp": NODE,
        "project.yaml": "project: p\ndistro: humble\nworkspace: src\n"})
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (node,) = [n for n in model.nodes if n.package == "rov"]
    assert sorted((c.kind, c.name) for c in node.calls) == [("declare", "max_torque"),
                                                            ("publish", "torque")]
    assert node.completeness == "complete"
    assert not [d for d in model.diagnostics if d.code.startswith("CMAKE_SOURCE")]
