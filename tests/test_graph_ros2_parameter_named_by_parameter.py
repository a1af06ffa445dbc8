"""A ROS 2 parameter whose name holds another parameter's value: navigation2's route
server reads ``<value of graph_file_loader>.plugin`` (default ``GeoJsonGraphFileLoader``).
The graph fills the ``?`` with that value in the configuration (the launch's, else the
code's default), as it does for a topic; it left every such parameter ``?.plugin``, so
the parameters set under the chosen name were "maybe never read"."""

from __future__ import annotations

import json

from haros_arch.cli import main
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
class Server : public rclcpp::Node {
public:
  Server() : rclcpp::Node("server"), default_id_("Geo") {
    auto id = declare_parameter("loader", default_id_);
    declare_parameter(id + ".plugin", std::string("pkg::Geo"));
    auto other = declare_parameter("other", std::string("Other"));
    declare_parameter(other + ".rate", 1.0);
  }
  std::string default_id_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Server>());
}
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(srv)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
add_executable(server src/server.cpp)
ament_target_dependencies(server rclcpp)
install(TARGETS server DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
ament_package()
"""

LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(
        package='srv', executable='server', name='server',
        parameters=[{'other': 'Fast', 'Fast.rate': 2.0, 'Geo.plugin': 'pkg::Geo2',
                     'Other.rate': 3.0}])])
"""


def test_the_value_of_the_naming_parameter_names_the_parameter(write_tree) -> None:
    root = write_tree({"srv/package.xml": package_xml("srv", "ament_cmake"),
                       "srv/CMakeLists.txt": CMAKE, "srv/src/server.cpp": NODE,
                       "srv/launch/server.launch.py": LAUNCH})
    out = root / "check.json"
    main(["check", str(root), "--format", "json", "-o", str(out), "--fail-on", "never"])
    found = sorted((f["rule"], f["entities"]) for f in json.loads(out.read_text())["findings"])
    # Geo.plugin is read (loader keeps its default, the member's "Geo"), Fast.rate too
    # (other is set to "Fast"); Other.rate, the default's, is set and never read
    assert found == [("parameter-set-not-read", ["parameter:/server/Other.rate"])], found
