"""A ROS 2 node built with local arguments of its own (``rclcpp::NodeOptions::arguments``).

rcl reads a node's own remap rules before the process's (``_rcl_remap_name``: the local
arguments, then the global ones): ``NodeOptions().arguments({"--ros-args", "-r",
"__ns:=/fixed"})`` given to the node's constructor puts it in ``/fixed`` whatever
namespace the launch file gives the process (``-r __ns:=/robot1``), and ``-r
__node:=renamed`` names it whatever ``name=`` says. The node sat in the launch's
namespace, under the launch's name, in the graph."""

from __future__ import annotations

import os

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

PACKAGE = ('<?xml version="1.0"?>\n<package format="3"><name>demo</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<buildtool_depend>ament_cmake</buildtool_depend><depend>rclcpp</depend>"
           "<depend>std_msgs</depend>"
           "<export><build_type>ament_cmake</build_type></export></package>\n")

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(demo)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
find_package(std_msgs REQUIRED)
add_executable(talker src/talker.cpp)
add_executable(helper src/helper.cpp)
add_executable(plain src/plain.cpp)
ament_target_dependencies(talker rclcpp std_msgs)
ament_target_dependencies(helper rclcpp std_msgs)
ament_target_dependencies(plain rclcpp std_msgs)
install(TARGETS talker helper plain DESTINATION lib/${PROJECT_NAME})
ament_package()
"""

# a node class whose constructor passes on the options main builds
TALKER = """#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class Talker : public rclcpp::Node {
 public:
  explicit Talker(const rclcpp::NodeOptions & options) : rclcpp::Node("talker", options) {
    pub_ = create_publisher<std_msgs::msg::String>("chatter", 10);
  }
 private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::NodeOptions options;
  options.arguments({"--ros-args", "-r", "__ns:=/fixed"});
  rclcpp::spin(std::make_shared<Talker>(options));
  return 0;
}
"""

# the options written at the construction, renaming the node
HELPER = """#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared(
    "helper", rclcpp::NodeOptions().start_parameter_services(false).arguments(
      {"--ros-args", "-r", "__node:=renamed"}));
  auto pub = node->create_publisher<std_msgs::msg::String>("status", 10);
  rclcpp::spin(node);
  return 0;
}
"""

# default options: the launch's namespace and name, as before
PLAIN = """#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("plain", rclcpp::NodeOptions());
  auto pub = node->create_publisher<std_msgs::msg::String>("out", 10);
  rclcpp::spin(node);
  return 0;
}
"""

LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='talker', namespace='robot1'),
        Node(package='demo', executable='helper', namespace='robot1', name='launched'),
        Node(package='demo', executable='plain', namespace='robot1', name='given'),
    ])
"""


def test_own_arguments_beat_the_launch(write_tree) -> None:
    root = write_tree({
        "src/demo/package.xml": PACKAGE, "src/demo/CMakeLists.txt": CMAKE,
        "src/demo/src/talker.cpp": TALKER, "src/demo/src/helper.cpp": HELPER,
        "src/demo/src/plain.cpp": PLAIN, "src/demo/launch/all.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  all: [demo/launch/all.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    config = model.configuration("all")
    assert sorted(n.name for n in config.nodes) == [
        "/fixed/talker", "/robot1/given", "/robot1/renamed"]
    assert sorted((link.node.name, link.rosname.full) for link in config.links) == [
        ("/fixed/talker", "/fixed/chatter"), ("/robot1/given", "/robot1/out"),
        ("/robot1/renamed", "/robot1/status")]
    talker = next(n for n in model.nodes if n.executable == "talker")
    assert talker.local_rules == {"/fixed/talker": ["__ns:=/fixed"]}
