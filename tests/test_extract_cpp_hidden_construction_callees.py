"""A class template a function template builds with ``std::make_shared<Server<T>>(...)``
(its arguments depend on the template's parameters: the parse cannot choose its
constructor, and the class's name counts as a construction it cannot see) runs its
constructor, and so the free functions that constructor calls: navigation2's
``nav2::interfaces::create_service`` builds ``nav2::ServiceServer<SrvT>``, whose
constructor calls ``nav2::setIntrospectionMode``, which reads ``introspection_mode``. The
function's reads were dropped as code the executable never runs (map_server's
``/map_server/introspection_mode`` was "set but never read")."""

from __future__ import annotations

import os
from typing import Any

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from tests.conftest import package_xml

HEADER = """
#pragma once
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
namespace demo {
inline void configure(
    rclcpp::node_interfaces::NodeParametersInterface::SharedPtr params) {
  if (!params->has_parameter("introspection_mode")) {
    params->declare_parameter("introspection_mode", rclcpp::ParameterValue("disabled"));
  }
}
template<typename T>
class Server {
 public:
  template<typename NodeT>
  Server(const std::string & name, const NodeT & node) : name_(name) {
    configure(node->get_node_parameters_interface());
  }
 private:
  std::string name_;
};
template<typename T, typename NodeT>
std::shared_ptr<Server<T>> make_server(const NodeT & node, const std::string & name) {
  return std::make_shared<Server<T>>(name, node);
}
}  // namespace demo
"""

NODE = """
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include "demo/server.hpp"
class Mapper : public rclcpp::Node {
 public:
  Mapper() : Node("mapper") {
    %s
    declare_parameter("rate", 1.0);
  }
 private:
  std::shared_ptr<demo::Server<int>> server_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Mapper>());
  return 0;
}
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node
def generate_launch_description():
    return LaunchDescription([Node(package="demo", executable="mapper", name="mapper",
                                   parameters=[{"introspection_mode": "metadata"}])])
"""


def _declared(write_tree: Any, make: str, header: str = HEADER) -> list[str]:
    xml = package_xml("demo", None).replace("</package>", "<depend>rclcpp</depend>"
                                            "<export><build_type>ament_cmake</build_type>"
                                            "</export></package>")
    root = write_tree({
        "src/demo/package.xml": xml,
        "src/demo/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(demo)\n"
            "find_package(ament_cmake REQUIRED)\nfind_package(rclcpp REQUIRED)\n"
            "include_directories(include)\nadd_executable(mapper src/mapper.cpp)\n"
            "ament_target_dependencies(mapper rclcpp)\n"
            "install(TARGETS mapper DESTINATION lib/${PROJECT_NAME})\n"
            "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})\nament_package()\n"),
        "src/demo/include/demo/server.hpp": header,
        "src/demo/src/mapper.cpp": NODE % make,
        "src/demo/launch/mapper.launch.py": LAUNCH,
        "project.yaml": ("project: p\nworkspace: [src]\ndistro: jazzy\nconfigurations:\n"
                         "  c: {launch: [demo/launch/mapper.launch.py]}\n")})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    return sorted({link.resource.name for link in model.configurations[0].links
                   if link.kind in ("read", "write") and link.node.name == "/mapper"})


def test_a_free_function_a_hidden_construction_runs_makes_its_calls(write_tree: Any) -> None:
    declared = _declared(write_tree, 'server_ = demo::make_server<int>(this, "srv");')
    assert "/mapper/introspection_mode" in declared and "/mapper/rate" in declared


def test_a_free_function_no_code_calls_runs_nothing(write_tree: Any) -> None:
    """A guard: the same function, called by no constructor of the class the template
    builds (nor by anything else), makes no call of the node."""
    header = HEADER.replace("    configure(node->get_node_parameters_interface());\n", "")
    declared = _declared(write_tree, 'server_ = demo::make_server<int>(this, "srv");', header)
    assert "/mapper/introspection_mode" not in declared and "/mapper/rate" in declared
