"""rclpy's ``declare_parameter(name, Parameter.Type.X)`` (and the deprecated
``declare_parameter(name)``) with no value and no override declares the parameter
uninitialised and goes on: only a later ``get_parameter(name)`` raises. So such a
declaration alone is no "read but never set"; a get of the parameter still is.
rclcpp's ``declare_parameter<T>(name)`` throws when no override sets it, so it stays a
finding. ros2_controllers_test_nodes' trajectory publisher declares each goal name as a
DOUBLE_ARRAY and reads only ``<goal>.positions`` and the like
(publisher_joint_trajectory_controller.py:69-75)."""

from __future__ import annotations

import os

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue
from tests.conftest import package_xml

SCRIPT = """#!/usr/bin/env python3
import rclpy
from rclpy.node import Node


class Goals(Node):
    def __init__(self):
        super().__init__('goals')
        self.declare_parameter('pos1', rclpy.Parameter.Type.DOUBLE_ARRAY)
        self.declare_parameter('speed', rclpy.Parameter.Type.DOUBLE)
        self.speed = self.get_parameter('speed').value
        self.declare_parameter('topic', 'cmd')


def main():
    rclpy.init()
    rclpy.spin(Goals())
"""

NODE = """
#include <rclcpp/rclcpp.hpp>
class Limits : public rclcpp::Node
{
public:
  Limits() : rclcpp::Node("limits")
  {
    min_ = declare_parameter<double>("min");
  }
  double min_ = 0;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Limits>());
}
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='py', executable='goals', name='goals'),
                              Node(package='cc', executable='limits', name='limits')])
"""


def test_an_rclpy_typed_declaration_alone_is_no_read_not_set(write_tree) -> None:
    root = write_tree({
        "src/py/package.xml": package_xml("py", "ament_python"),
        "src/py/setup.py": "from setuptools import setup\n"
                           "setup(name='py', packages=['py'], entry_points={\n"
                           "    'console_scripts': ['goals = py.goals:main']})\n",
        "src/py/py/__init__.py": "",
        "src/py/py/goals.py": SCRIPT,
        "src/cc/package.xml": package_xml("cc", "ament_cmake"),
        "src/cc/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(cc)\n"
                                 "add_executable(limits src/node.cpp)\n",
        "src/cc/src/node.cpp": NODE,
        "src/py/launch/all.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [py/launch/all.launch.py]\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    unset = sorted(f.message.split(" ")[0] for f in run_catalogue(model)
                   if f.rule == "parameter-read-not-set")
    assert unset == ["/goals/speed", "/limits/min"]
