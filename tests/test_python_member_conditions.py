"""A Python node's parameter read stored in a member (``self.check =
self.get_parameter("check").value``, rospy's ``self.rate = rospy.get_param("~rate", 1)``)
names the member (``variable``), as C++ reads do, so a condition over ``self.check`` is
decided per node instance from the parameter: the launch value, else the declared
default (only when the member holds the read's result as it is, not a value computed
from it). ros2_controllers_test_nodes' trajectory publisher subscribes ``joint_states``
only ``if self.check_starting_point`` (publisher_joint_trajectory_controller.py:41-58),
which every surveyed configuration leaves false: its subscription was a false
"subscriber without publisher". A member assigned twice in its file stays undecided."""

from __future__ import annotations

import os

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from tests.conftest import package_xml

SCRIPT = """#!/usr/bin/env python3
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import JointState
from std_msgs.msg import String


class Goals(Node):
    def __init__(self):
        super().__init__('goals')
        self.declare_parameter('check', False)
        self.declare_parameter('verbose', False)
        self.check = self.get_parameter('check').value
        self.verbose = self.get_parameter('verbose').value
        self.declare_parameter('limit', 1)
        self.limit = self.get_parameter('limit').value * 10  # not the parameter's value
        if self.limit > 5:
            self.big = self.create_publisher(String, 'big', 1)
        if self.check:
            self.sub = self.create_subscription(JointState, 'joint_states', self.cb, 10)
        if not self.verbose:
            self.quiet = self.create_publisher(String, 'quiet', 1)
        if self.verbose:
            self.loud = self.create_publisher(String, 'loud', 1)

    def cb(self, msg):
        self.verbose = True


def main():
    rclpy.init()
    rclpy.spin(Goals())
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='py', executable='goals', name='unset'),
        Node(package='py', executable='goals', name='on', parameters=[{'check': True}]),
    ])
"""


def test_a_condition_over_a_member_holding_a_parameter_is_decided(write_tree) -> None:
    root = write_tree({
        "src/py/package.xml": package_xml("py", "ament_python"),
        "src/py/setup.py": "from setuptools import setup\n"
                           "setup(name='py', packages=['py'], entry_points={\n"
                           "    'console_scripts': ['goals = py.goals:main']})\n",
        "src/py/py/__init__.py": "",
        "src/py/py/goals.py": SCRIPT,
        "src/py/launch/all.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [py/launch/all.launch.py]\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configurations[0]
    links = {(i.name, link.kind, link.rosname.full if link.rosname else link.name,
              bool(link.conditions))
             for i in config.nodes for link in i.links if link.kind in ("subscribe", "publish")}
    # check: false by default (dropped), true where the launch sets it (unconditional);
    # verbose is assigned twice (the callback too), limit is computed from it: their
    # conditions stay
    assert {(n, k, t, c) for n, k, t, c in links if "rosout" not in t} == {
        ("/unset", "publish", "/quiet", True), ("/unset", "publish", "/loud", True),
        ("/unset", "publish", "/big", True), ("/on", "publish", "/big", True),
        ("/on", "subscribe", "/joint_states", False),
        ("/on", "publish", "/quiet", True), ("/on", "publish", "/loud", True)}
