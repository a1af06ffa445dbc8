"""An rclpy node may keep the Parameter that ``declare_parameter`` gives and test its
``.value`` (``self.origin_param = self.declare_parameter('local_xy_origin', 'auto',
descriptor=ParameterDescriptor(..))``, then ``if self.origin_param.value == 'auto':``),
Python's quotes around the string. marti_common's initialize_origin subscribes its GPS
topics only then; its own launch file sets the origin to ``swri``, and the two
subscriptions were false subscriber-without-publisher warnings: the read's descriptor
(a call) kept the member from naming the parameter, and neither the ``.value`` nor the
single-quoted string was read by the condition grammar. A Parameter's other uses stay
undecided."""

from __future__ import annotations

import os

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import absorbed
from tests.conftest import package_xml

SCRIPT = """#!/usr/bin/env python3
import rclpy
from rclpy.node import Node
from rcl_interfaces.msg import ParameterDescriptor
from std_msgs.msg import String


class Origin(Node):
    def __init__(self):
        super().__init__('origin')
        self.origin_param = self.declare_parameter(
            'origin', 'auto', descriptor=ParameterDescriptor(name='origin'))
        self.topic_param = self.declare_parameter('topic', 'gps')
        if self.origin_param.value == 'auto':
            self.sub = self.create_subscription(String, self.topic_param.value, self.cb, 2)
        if self.origin_param.name == 'origin':
            self.named = self.create_publisher(String, 'named', 1)

    def cb(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Origin())
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='py', executable='origin', name='auto'),
        Node(package='py', executable='origin', name='fixed', parameters=[{'origin': 'swri'}]),
    ])
"""


def test_a_condition_over_a_parameter_objects_value_is_decided(write_tree) -> None:
    root = write_tree({
        "src/py/package.xml": package_xml("py", "ament_python"),
        "src/py/setup.py": "from setuptools import setup\n"
                           "setup(name='py', packages=['py'], entry_points={\n"
                           "    'console_scripts': ['origin = py.origin:main']})\n",
        "src/py/py/__init__.py": "",
        "src/py/py/origin.py": SCRIPT,
        "src/py/launch/all.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [py/launch/all.launch.py]\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configurations[0]
    links = {(i.name, link.kind, link.rosname.full if link.rosname else link.name,
              bool(link.conditions))
             for i in config.nodes for link in i.links if link.kind in ("subscribe", "publish")}
    # origin is 'auto' by default (the subscription is unconditional there) and 'swri'
    # where the launch sets it (dropped); ``.name`` is no value read: undecided
    assert {(n, k, t, c) for n, k, t, c in links if "rosout" not in t} == {
        ("/auto", "subscribe", "/gps", False), ("/auto", "publish", "/named", True),
        ("/fixed", "publish", "/named", True)}


def test_a_call_every_instance_drops_has_its_name_said_by_the_graph(write_tree) -> None:
    """The subscription's name is a parameter's (PY_DYNAMIC_NAME, said by the extractor
    and absorbed where the graph names it); where the only instance drops the call,
    CONDITION_FALSE says what became of it, and the info is not printed again."""
    root = write_tree({
        "src/py/package.xml": package_xml("py", "ament_python"),
        "src/py/setup.py": "from setuptools import setup\n"
                           "setup(name='py', packages=['py'], entry_points={\n"
                           "    'console_scripts': ['origin = py.origin:main']})\n",
        "src/py/py/__init__.py": "",
        "src/py/py/origin.py": SCRIPT,
        "src/py/launch/fixed.launch.py": LAUNCH.replace(
            "        Node(package='py', executable='origin', name='auto'),\n", ""),
        "project.yaml": "project: p\nconfigurations:\n  c: [py/launch/fixed.launch.py]\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    assert [d.code for d in model.configurations[0].diagnostics
            if d.code == "CONDITION_FALSE"] == ["CONDITION_FALSE"]
    dynamic = [d for d in model.diagnostics if d.code == "PY_DYNAMIC_NAME"]
    assert dynamic and all(d in absorbed(model) for d in dynamic), dynamic
