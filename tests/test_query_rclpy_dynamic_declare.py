"""rclpy's ``get_parameter(name)`` of a parameter declared with no value raises only for a
statically typed one: declared ``descriptor=ParameterDescriptor(dynamic_typing=True)``,
it returns a NOT_SET parameter whose value is None (rclpy node.py, ``get_parameter``).
ros2_controllers_test_nodes' trajectory publisher (humble) declares each goal name so,
gets it, and takes the ``<goal>.positions`` form when it is no list: every goal was
reported read but never set (Elite's CS driver examples, 8 warnings). A value of None
given with another descriptor is no default: the parameter is statically typed and
uninitialised, and its get raises. The name alone (``declare_parameter(name)``, a
one-element tuple of ``declare_parameters``) is dynamically typed; ``(name, None)`` in
``declare_parameters`` statically."""

from __future__ import annotations

import os

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue
from tests.conftest import package_xml

SCRIPT = """#!/usr/bin/env python3
import rclpy
from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node


class Goals(Node):
    def __init__(self):
        super().__init__('goals')
        for name in ['pos1']:
            self.declare_parameter(name, descriptor=ParameterDescriptor(dynamic_typing=True))
            goal = self.get_parameter(name).value
        self.declare_parameter('speed', descriptor=ParameterDescriptor(description='m/s'))
        self.speed = self.get_parameter('speed').value
        self.declare_parameter('gain', None, ParameterDescriptor(dynamic_typing=False))
        self.gain = self.get_parameter('gain').value
        self.declare_parameter('ratio', None, ParameterDescriptor(dynamic_typing=True))
        self.ratio = self.get_parameter('ratio').value
        # the name alone: rclpy declares it dynamically typed (deprecated), get returns it
        self.declare_parameter('bare')
        self.bare = self.get_parameter('bare').value
        self.declare_parameters('', [('one',), ('two', None),
                                     ('three', None, ParameterDescriptor(dynamic_typing=True))])
        self.one = self.get_parameter('one').value
        self.two = self.get_parameter('two').value
        self.three = self.get_parameter('three').value


def main():
    rclpy.init()
    rclpy.spin(Goals())
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='py', executable='goals', name='goals')])
"""


def test_a_dynamically_typed_declaration_is_read_unset_without_failing(write_tree) -> None:
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
    reads = {link.resource.name for link in model.configurations[0].links
             if link.kind == "read"}
    assert "/goals/pos1" in reads
    unset = sorted(f.message.split(" ")[0] for f in run_catalogue(model)
                   if f.rule == "parameter-read-not-set")
    # a value of None without dynamic typing declares it statically typed, uninitialised
    assert unset == ["/goals/gain", "/goals/speed", "/goals/two"]

