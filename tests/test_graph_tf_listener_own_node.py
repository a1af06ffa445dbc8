"""ROS 2 tf2_ros ``TransformListener`` built without a node.

``TransformListener(buffer)`` and ``TransformListener(buffer, spin_thread)`` make an
rclcpp node of their own (``transform_listener_impl_`` and an address) with default
NodeOptions, which subscribes ``/tf`` and ``/tf_static``: that node takes the process's
global arguments (the launch's namespace, its remaps) and not the namespace the code
gives the node it builds the listener in. Given a node (``TransformListener(buffer,
node, spin_thread)``), the listener subscribes on that node. With the launch's remap
``/tf:=tf`` and no launch namespace, the listener without a node of a node the code puts
in ``ns_a`` subscribes ``/tf``, not ``/ns_a/tf``; the one given the node, ``/ns_a/tf``.
Under the launch namespace ``robot1`` both are ``/robot1/tf``."""

from __future__ import annotations

import os

from haros_arch.extract.cpp import extract_cpp
from haros_arch.model.source import PROCESS_HANDLE
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

PACKAGE = ('<?xml version="1.0"?>\n<package format="3"><name>watch</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<buildtool_depend>ament_cmake</buildtool_depend><depend>rclcpp</depend>"
           "<depend>tf2_ros</depend>"
           "<export><build_type>ament_cmake</build_type></export></package>\n")

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(watch)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
find_package(tf2_ros REQUIRED)
add_executable(watcher src/watcher.cpp)
ament_target_dependencies(watcher rclcpp tf2_ros)
install(TARGETS watcher DESTINATION lib/${PROJECT_NAME})
ament_package()
"""

SOURCE = """#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

class Watcher : public rclcpp::Node {
 public:
  Watcher() : rclcpp::Node("watcher", "ns_a") {
    buffer_ = std::make_shared<tf2_ros::Buffer>(get_clock());
    own_ = std::make_shared<tf2_ros::TransformListener>(*buffer_);
    spinning_ = std::make_shared<tf2_ros::TransformListener>(*buffer_, true);
    given_ = std::make_shared<tf2_ros::TransformListener>(*buffer_, this, false);
  }
 private:
  std::shared_ptr<tf2_ros::Buffer> buffer_;
  std::shared_ptr<tf2_ros::TransformListener> own_, spinning_, given_;
};

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Watcher>());
  return 0;
}
"""

LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='watch', executable='watcher',{namespace}
             remappings=[('/tf', 'tf'), ('/tf_static', 'tf_static')]),
    ])
"""


def _tree(write_tree):
    return write_tree({
        "src/watch/package.xml": PACKAGE, "src/watch/CMakeLists.txt": CMAKE,
        "src/watch/src/watcher.cpp": SOURCE,
        "src/watch/launch/plain.launch.py": LAUNCH.format(namespace=""),
        "src/watch/launch/robot.launch.py": LAUNCH.format(namespace=" namespace='robot1',"),
        "project.yaml": "project: p\nconfigurations:\n"
                        "  plain: [watch/launch/plain.launch.py]\n"
                        "  robot: [watch/launch/robot.launch.py]\n",
    })


def test_a_listener_without_a_node_is_on_a_node_of_its_own(write_tree) -> None:
    root = _tree(write_tree)
    result = extract_cpp([str(root / "src/watch/src/watcher.cpp")], scan([str(root)]),
                         cache_dir=None)
    lines = {(c.name, c.location.line, c.handle_origin) for c in result.calls}
    # one subscription of each per node: the listener of line 11 (``spin_thread``, no
    # node) is on a node of its own as the first is, found once; the one given the node
    # is the node's
    assert lines == {
        ("/tf", 10, PROCESS_HANDLE), ("/tf_static", 10, PROCESS_HANDLE),
        ("/tf", 12, None), ("/tf_static", 12, None)}


def test_its_names_resolve_in_the_process_not_in_the_code_namespace(write_tree) -> None:
    root = _tree(write_tree)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    plain = model.configuration("plain")
    assert [n.name for n in plain.nodes] == ["/ns_a/watcher"]
    # the listener's own node is in the launch's namespace (none) with its remaps; the
    # listener given the node subscribes on it, in the namespace the code gives it
    assert sorted((link.rosname.full, link.location.line) for link in plain.links) == [
        ("/ns_a/tf", 12), ("/ns_a/tf_static", 12), ("/tf", 10), ("/tf_static", 10)]
    assert all(link.node.name == "/ns_a/watcher" for link in plain.links)
    robot = model.configuration("robot")
    assert [n.name for n in robot.nodes] == ["/robot1/watcher"]
    assert sorted((link.rosname.full, link.location.line) for link in robot.links) == [
        ("/robot1/tf", 10), ("/robot1/tf", 12), ("/robot1/tf_static", 10),
        ("/robot1/tf_static", 12)]
