"""A method's calls exist where objects of its class are built: navigation2's collision
monitor builds a ``VelocityPolygon`` only ``if (polygon_type == "velocity_polygon")``,
and ``VelocityPolygon::getParameters`` (velocity_polygon.cpp, called through the base
class's virtual ``configure()``) reads ``<name>.velocity_polygons`` without a default.
Without the construction's condition the read was made for every polygon, a false
"read but never set" for each polygon of another type. A method of a class whose file
builds it nowhere carries what every construction of the class in the node's files
shares (``links.CLASS_BUILT``), loops and ``try`` blocks aside; a class the node builds
unconditionally, or one a plugin export names, carries none."""

from __future__ import annotations

import json

from haros_arch.cli import main
from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SHAPES = """
#include <memory>
#include <rclcpp/rclcpp.hpp>
class Shape {
public:
  virtual ~Shape() {}
  virtual void configure() = 0;
};
class Circle : public Shape {
public:
  explicit Circle(rclcpp::Node * node);
  void configure() override;
private:
  rclcpp::Node * node_;
};
class Box : public Shape {
public:
  explicit Box(rclcpp::Node * node);
  void configure() override;
private:
  rclcpp::Node * node_;
};
class Logger {
public:
  explicit Logger(rclcpp::Node * node);
  void start();
private:
  rclcpp::Node * node_;
};
"""

CIRCLE = """
#include "shapes.hpp"
Circle::Circle(rclcpp::Node * node) : node_(node) {}
void Circle::configure() { node_->declare_parameter<double>("radius"); }
"""

BOX = """
#include "shapes.hpp"
Box::Box(rclcpp::Node * node) : node_(node) {}
void Box::configure() { node_->declare_parameter<double>("width"); }
Logger::Logger(rclcpp::Node * node) : node_(node) {}
void Logger::start() { node_->declare_parameter<double>("period"); }
"""

NODE = """
#include "shapes.hpp"
class Monitor : public rclcpp::Node {
public:
  Monitor() : rclcpp::Node("monitor") {
    const std::string kind = declare_parameter<std::string>("kind", "box");
    if (kind == "circle") {
      shape_ = std::make_shared<Circle>(this);
    } else {
      shape_ = std::make_shared<Box>(this);
    }
    shape_->configure();
    logger_ = std::make_shared<Logger>(this);
    logger_->start();
  }
  std::shared_ptr<Shape> shape_;
  std::shared_ptr<Logger> logger_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Monitor>());
}
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(sh)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
add_executable(monitor src/node.cpp src/circle.cpp src/box.cpp)
ament_target_dependencies(monitor rclcpp)
install(TARGETS monitor DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
ament_package()
"""

LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(
        package='sh', executable='monitor', name='monitor',
        parameters=[{'kind': 'box', 'width': 1.0, 'period': 0.5}])])
"""


def _tree(write_tree):
    return write_tree({"sh/package.xml": package_xml("sh", "ament_cmake"),
                       "sh/CMakeLists.txt": CMAKE, "sh/src/shapes.hpp": SHAPES,
                       "sh/src/circle.cpp": CIRCLE, "sh/src/box.cpp": BOX,
                       "sh/src/node.cpp": NODE, "sh/launch/monitor.launch.py": LAUNCH})


def test_a_method_carries_its_class_construction_conditions(write_tree) -> None:
    root = _tree(write_tree)
    result = extract_cpp([str(root / "sh" / "src" / name)
                          for name in ("node.cpp", "circle.cpp", "box.cpp")],
                         scan([str(root)]), cache_dir=None, distro="jazzy")
    under = {c.name: [(k.statement, k.text) for k in c.conditions]
             for c in result.calls if c.name in ("radius", "width", "period")}
    assert under == {"radius": [("if", 'kind == "circle"')],
                     "width": [("else", 'kind == "circle"')],
                     "period": []}


def test_the_graph_drops_the_reads_of_a_class_not_built(write_tree) -> None:
    root = _tree(write_tree)
    out = root / "check.json"
    main(["check", str(root), "--format", "json", "-o", str(out), "--fail-on", "never"])
    found = sorted((f["rule"], f["entities"])
                   for f in json.loads(out.read_text())["findings"]
                   if f["rule"].startswith("parameter-"))
    assert found == [], found  # radius, read by a Circle, which kind "box" never builds
