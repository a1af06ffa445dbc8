"""A ROS 2 node's own ``use_sim_time`` is declared by rclcpp / rclpy on every node (false
by default): a read of it is never a read of a parameter nothing sets (survey Z19:
controller_manager's ros2_control_node reads it, xarm_ros2's launch files set none)."""

from __future__ import annotations

import os

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("clock_user");
  bool sim = node->get_parameter("use_sim_time").as_bool();
  int rate = node->get_parameter("rate").as_int();
  rclcpp::spin(node);
}
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='ex', executable='user', name='clock_user')])
"""


def test_a_ros2_nodes_use_sim_time_is_always_set(write_tree) -> None:
    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n"
                                 "add_executable(user src/node.cpp)\n",
        "src/ex/src/node.cpp": NODE,
        "src/ex/launch/ex.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    unset = sorted(f.message.split(" ")[0] for f in run_catalogue(model)
                   if f.rule == "parameter-read-not-set")
    assert unset == ["/clock_user/rate"]
