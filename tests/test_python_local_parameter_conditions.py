"""A Python condition over a local that holds a parameter's value (f1tenth_gym_ros'
gym_bridge: ``num_agents = self.get_parameter('num_agent').value``, then ``if
num_agents == 2:`` makes the opponent's topics), or over a read written in the test
itself (``if self.get_parameter('kb_teleop').value:``, ``if rospy.get_param('~x',
False):``), is decided per instance from the value the configuration gives the
parameter, as C++ conditions over such locals are (``Condition.parameters``). A read
with no default has no type: it takes the launch value as it is (rclpy's
``declare_parameter('num_agent')``, rospy's ``get_param('~mode')``). Before, every such
call stayed conditional: gym_bridge's launch sets ``num_agent: 1``, and its opponent's
four publishers and two subscriptions were listed as possible."""

from __future__ import annotations

import os

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from tests.conftest import package_xml

RCLPY = """import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Bridge(Node):
    def __init__(self):
        super().__init__('bridge')
        self.declare_parameter('num_agent')
        self.declare_parameter('kb_teleop')
        num_agents = self.get_parameter('num_agent').value
        self.create_publisher(String, 'ego', 10)
        if num_agents == 2:
            self.create_publisher(String, 'opp', 10)
        else:
            self.create_publisher(String, 'alone', 10)
        if self.get_parameter('kb_teleop').value:
            self.create_subscription(String, 'cmd_vel', self.cb, 10)
        mode = self.get_parameter('num_agent').value
        mode = 7
        if mode == 1:
            self.create_publisher(String, 'overwritten', 10)

    def cb(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Bridge())
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='py', executable='bridge', name='one',
             parameters=[{'num_agent': 1, 'kb_teleop': True}]),
        Node(package='py', executable='bridge', name='two',
             parameters=[{'num_agent': 2, 'kb_teleop': False}]),
        Node(package='py', executable='bridge', name='unset'),
    ])
"""

ROSPY = """#!/usr/bin/env python
import rospy
from std_msgs.msg import String
rospy.init_node('legacy')
mode = rospy.get_param('~mode')
if mode == 'fast':
    rospy.Publisher('fast', String, queue_size=1)
if rospy.get_param('~debug', False):
    rospy.Publisher('debug', String, queue_size=1)
"""


def _links(root) -> set[tuple[str, str, bool]]:
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configurations[0]
    return {(i.name, link.rosname.full, bool(link.conditions))
            for i in config.nodes for link in i.links
            if link.kind in ("subscribe", "publish") and "rosout" not in link.rosname.full
            and "parameter_events" not in link.rosname.full}


def test_rclpy_conditions_over_parameter_values_are_decided(write_tree) -> None:
    root = write_tree({
        "src/py/package.xml": package_xml("py", "ament_python"),
        "src/py/setup.py": "from setuptools import setup\n"
                           "setup(name='py', packages=['py'], entry_points={\n"
                           "    'console_scripts': ['bridge = py.bridge:main']})\n",
        "src/py/py/__init__.py": "",
        "src/py/py/bridge.py": RCLPY,
        "src/py/launch/all.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [py/launch/all.launch.py]\n"})
    assert _links(root) == {
        ("/one", "/ego", False), ("/one", "/alone", False), ("/one", "/cmd_vel", False),
        ("/two", "/ego", False), ("/two", "/opp", False),
        # nothing sets them: undecided (a local written again is no parameter's value)
        ("/unset", "/ego", False), ("/unset", "/opp", True), ("/unset", "/alone", True),
        ("/unset", "/cmd_vel", True),
        ("/one", "/overwritten", True), ("/two", "/overwritten", True),
        ("/unset", "/overwritten", True)}


def test_rospy_conditions_over_parameter_values_are_decided(write_tree) -> None:
    root = write_tree({
        "src/legacy/package.xml": package_xml("legacy"),
        "src/legacy/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0)\nproject(legacy)\n"
                                     "find_package(catkin REQUIRED)\ncatkin_package()\n"
                                     "catkin_install_python(PROGRAMS scripts/legacy.py\n"
                                     "  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n",
        "src/legacy/scripts/legacy.py": ROSPY,
        "src/legacy/launch/all.launch": (
            "<launch>\n"
            "  <node pkg='legacy' type='legacy.py' name='a'>\n"
            "    <param name='mode' value='fast'/><param name='debug' value='true'/>\n"
            "  </node>\n"
            "  <node pkg='legacy' type='legacy.py' name='b'>\n"
            "    <param name='mode' value='slow'/>\n"
            "  </node>\n"
            "</launch>\n"),
        "project.yaml": "project: p\ndistro: noetic\n"
                        "configurations:\n  c: [legacy/launch/all.launch]\n"})
    assert _links(root) == {("/a", "/fast", False), ("/a", "/debug", False)}
