"""rclcpp and rclpy declare ``use_sim_time`` on every node they make (false by default),
so a ROS 2 node that reads its own ``use_sim_time`` with no default reads a parameter
that is set. ros2_control's controller manager (jazzy, controller_manager.cpp:719)
``this->get_parameter("use_sim_time").as_bool()`` was reported "read but never set" in
every ros2_control_demos configuration, and in xarm_ros2's (survey Z19), whose launch
files set none. A read of another parameter so is still reported."""

from __future__ import annotations

import os

import pytest

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue
from tests.conftest import package_xml

A_NODE_MADE_IN_MAIN = """
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

A_NODE_CLASS = """
#include <rclcpp/rclcpp.hpp>
class Manager : public rclcpp::Node
{
public:
  Manager() : rclcpp::Node("clock_user")
  {
    sim_ = this->get_parameter("use_sim_time").as_bool();
    rate_ = this->get_parameter("rate").as_int();
  }
  bool sim_ = false;
  int rate_ = 0;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Manager>());
}
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='ex', executable='user', name='clock_user')])
"""


@pytest.mark.parametrize("code", [A_NODE_MADE_IN_MAIN, A_NODE_CLASS], ids=["main", "class"])
def test_a_ros2_nodes_own_use_sim_time_is_set_by_its_client_library(write_tree, code) -> None:
    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n"
                                 "add_executable(user src/node.cpp)\n",
        "src/ex/src/node.cpp": code,
        "src/ex/launch/ex.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    unset = sorted(f.message.split(" ")[0] for f in run_catalogue(model)
                   if f.rule == "parameter-read-not-set")
    assert unset == ["/clock_user/rate"]
