"""A topic name built from several parameters' values (f1tenth_gym_ros' gym_bridge
publishes its odometry on ``self.ego_namespace + '/' + self.get_parameter(
'ego_odom_topic').value``, the namespace read into a member before) takes each value in
the place of its ``?``, as a name from one parameter does: ``/ego_racecar/odom`` with its
launch file's sim.yaml. Before, only a name with one parameter part was filled, and
gym_bridge's four odometry publishers were ``?/?``. A part no one sets, with no default,
stays ``?``; the node model keeps the parameters (``PrimitiveCall.name_more``) through
its JSON form."""

from __future__ import annotations

import os

from haros_arch.extract.python import extract_python
from haros_arch.model.load import call_from_data
from haros_arch.model.serialise import to_data
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Bridge(Node):
    def __init__(self):
        super().__init__('bridge')
        self.declare_parameter('ns', 'robot')
        self.declare_parameter('odom_topic')
        self.declare_parameter('scan_topic', 'scan')
        self.ns = self.get_parameter('ns').value
        odom = self.ns + '/' + self.get_parameter('odom_topic').value
        self.create_publisher(String, odom, 10)
        self.create_publisher(
            String, f"{self.ns}/sensors/{self.get_parameter('scan_topic').value}", 10)


def main():
    rclpy.init()
    rclpy.spin(Bridge())
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='py', executable='bridge', name='set',
             parameters=[{'ns': 'ego_racecar', 'odom_topic': 'odom', 'scan_topic': 'lidar'}]),
        Node(package='py', executable='bridge', name='defaults'),
    ])
"""

TREE = {
    "src/py/package.xml": package_xml("py", "ament_python"),
    "src/py/setup.py": "from setuptools import setup\n"
                       "setup(name='py', packages=['py'], entry_points={\n"
                       "    'console_scripts': ['bridge = py.bridge:main']})\n",
    "src/py/py/__init__.py": "",
    "src/py/py/bridge.py": NODE,
    "src/py/launch/all.launch.py": LAUNCH,
    "project.yaml": "project: p\nconfigurations:\n  c: [py/launch/all.launch.py]\n"}


def test_the_node_model_names_each_parameter(write_tree) -> None:
    root = write_tree(TREE)
    result = extract_python([str(root / "src/py/py/bridge.py")], scan([str(root / "src")]),
                            package="py")
    publishers = [c for c in result.calls if c.kind == "publish"]
    assert [(c.name, c.name_param, c.name_default, c.name_more) for c in publishers] == [
        ("?/?", "ns", "robot", [["odom_topic", None]]),
        ("?/sensors/?", "ns", "robot", [["scan_topic", "scan"]])]
    assert [call_from_data(to_data(c)).name_more for c in publishers] == [
        [["odom_topic", None]], [["scan_topic", "scan"]]]


def test_the_graph_fills_each_parameter(write_tree) -> None:
    root = write_tree(TREE)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    published = {(i.name, link.rosname.full) for i in model.configurations[0].nodes
                 for link in i.links if link.kind == "publish"
                 and "rosout" not in link.rosname.full
                 and "parameter_events" not in link.rosname.full}
    assert published == {
        ("/set", "/ego_racecar/odom"), ("/set", "/ego_racecar/sensors/lidar"),
        # the namespace's default; no odometry topic set nor given by default
        ("/defaults", "/robot/?"), ("/defaults", "/robot/sensors/scan")}
