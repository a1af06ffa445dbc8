"""A ROS 2 parameter whose name a node writes with a leading slash, as code ported from
ROS 1 does: szenergy's formula_student_packages, cone_detector.py:103-113, declares
``/cone_detector/lidar_input_topic`` and reads it back, and its launch file
launch_cone_detector.py:12 gives ``{"/cone_detector/lidar_input_topic": '/points'}``.
rcl and rclpy keep the name as written, so the launch file's value is the one the node
reads. The launch file's setting was ``/cone_detector_node//cone_detector/
lidar_input_topic`` (node and key joined by a slash) and the node's read
``/cone_detector_node/cone_detector/lidar_input_topic`` (the name folded as a private
one): a parameter set and never read, beside the same one read and never set. The read
now keeps the name as written, as the setting does; ``/x`` and ``x`` stay two parameters
(tests/test_query_launch_params_unknown.py, moveit2_tutorials' ``/child_frame_id``)."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

SETUP = """
    from setuptools import setup
    setup(name='det', packages=['det'],
          entry_points={'console_scripts': ['detector = det.detector:main']})
    """

DETECTOR = """
    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import PointCloud2

    class Detector(Node):
        def __init__(self):
            super().__init__('detector')
            self.declare_parameters(namespace='', parameters=[
                ('/detector/input_topic', '/points'), ('/detector/dataset', 'cone')])
            topic = self.get_parameter('/detector/input_topic').value
            self.create_subscription(PointCloud2, topic, self.on_cloud, 10)
            self.dataset = self.get_parameter('/detector/dataset').value

        def on_cloud(self, msg):
            pass

    def main():
        rclpy.init()
        rclpy.spin(Detector())
    """

LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        return LaunchDescription([
            Node(package='det', executable='detector', name='cone_detector_node',
                 parameters=[{'/detector/input_topic': '/lidar/points'},
                             {'/detector/unused': 1}]),
        ])
    """


def _config(write_tree):
    root = write_tree({
        "src/det/package.xml": package_xml("det", build_type="ament_python"),
        "src/det/setup.py": SETUP,
        "src/det/resource/det": "",
        "src/det/det/__init__.py": "",
        "src/det/det/detector.py": DETECTOR,
        "src/det/launch/det.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [det/launch/det.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    return model.configuration("c")


def _findings(write_tree) -> tuple[list[tuple[str, str]], set[tuple[str, str]]]:
    config = _config(write_tree)
    params = sorted((p.rosname.full, "set") for p in config.parameters if p.set_by_launch)
    links = {(link.kind, link.rosname.full) for link in config.links}
    return params, links


def test_a_leading_slash_parameter_set_is_the_one_read(write_tree) -> None:
    params, links = _findings(write_tree)
    assert ("/cone_detector_node//detector/input_topic", "set") in params
    assert ("read", "/cone_detector_node//detector/input_topic") in links
    # the value the launch file gives names the topic subscribed to
    assert ("subscribe", "/lidar/points") in links


def test_a_leading_slash_parameter_is_no_global_name(write_tree) -> None:
    # (guard) a ROS 2 parameter is its node's alone, whatever its first character
    reads = [link.rosname for link in _config(write_tree).links if link.kind == "read"]
    assert reads and not [name for name in reads if name.is_global]


def test_a_parameter_no_node_reads_stays_unread(write_tree) -> None:
    # (guard) a setting the node never reads is no read's
    params, links = _findings(write_tree)
    assert ("/cone_detector_node//detector/unused", "set") in params
    assert not [name for kind, name in links if kind == "read" and "unused" in name]
