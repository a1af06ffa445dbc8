"""Two ROS 2 nodes launched under one name (a duplicate, said once by
duplicate-node-names) each read the parameters their own launch action gives them:
launch_ros hands each process its own. The graph keeps one parameter per full name, set
to the last node's value, and named both nodes' topics from it: Nautilus-One's
cameras_launch.py starts two ``publish_camera`` nodes with ``camera_name``
``auv_camera_front`` and ``auv_camera_down``, and both were taken to publish
``/auv_camera_down/image_raw/compressed`` (two false multiple-publishers)."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_rule

NODE = """
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Camera(Node):
    def __init__(self):
        super().__init__('camera')
        self.declare_parameter('camera_name', 'cam')
        name = self.get_parameter('camera_name').get_parameter_value().string_value
        self.pub = self.create_publisher(String, f'{name}/image_raw', 10)


def main():
    rclpy.init()
    rclpy.spin(Camera())
"""

LAUNCH = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('second', default_value='down'),
        Node(package='cams', executable='camera', name='camera',
             parameters=[{'camera_name': 'front'}]),
        Node(package='cams', executable='camera', name='camera',
             parameters=[{'camera_name': LaunchConfiguration('second')}]),
        Node(package='cams', executable='camera', name='other',
             parameters=[{'camera_name': 'down'}]),
    ])
"""


def test_two_nodes_of_one_name_keep_their_own_parameters(write_tree) -> None:
    root = write_tree({
        "src/cams/package.xml": package_xml("cams", build_type="ament_python"),
        "src/cams/setup.py": "from setuptools import setup\n"
                             "setup(name='cams', packages=['cams'], entry_points="
                             "{'console_scripts': ['camera = cams.camera:main']})\n",
        "src/cams/resource/cams": "",
        "src/cams/cams/__init__.py": "",
        "src/cams/cams/camera.py": NODE,
        "src/cams/launch/cams.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [cams/launch/cams.launch.py]\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configuration("c")
    publishers = sorted((link.node.id, link.resource.name) for link in config.links
                        if link.kind == "publish" and link.resource.name.endswith("image_raw"))
    assert publishers == [("node:/camera", "/front/image_raw"),
                          ("node:/camera#2", "/down/image_raw"),
                          ("node:/other", "/down/image_raw")]
    found = {rule.id: [list(f.entities) for f in run_rule(rule, model)]
             for rule in load_catalogue()
             if rule.id in ("duplicate-node-names", "multiple-publishers")}
    assert len(found["duplicate-node-names"]) == 1
    # the down camera's topic has two publishers truly (/camera#2 and /other); the front
    # one has one
    assert [e for e in found["multiple-publishers"] if "topic:/front/image_raw" in e] == []
    assert [e for e in found["multiple-publishers"] if "topic:/down/image_raw" in e]
