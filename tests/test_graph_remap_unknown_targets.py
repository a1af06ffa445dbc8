"""A remap whose target is not known statically is no use of another remap of the same
node: aerostack2's point_cloud2occ_grid-map_server.launch.py (5ce95b3e^) gives
pointcloud_to_laserscan_node ``('cloud', LaunchConfiguration('cloud_topic_in'))`` and
``('scan', LaunchConfiguration('scan_topic_out'))``, both arguments declared by an action
the launch stage does not interpret; the node subscribes ``cloud_in``, so the first remap
changes nothing. Both targets resolve to ``/drone0/?``, and the node's scan, remapped by
the second, was that name too: the first remap's target counted as a name the node
already uses, the remap as used, and remap-unused said nothing."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

NODE = """import rclpy
from sensor_msgs.msg import LaserScan, PointCloud2


def main():
    rclpy.init()
    node = rclpy.create_node('flatten')
    pub = node.create_publisher(LaserScan, 'scan', 10)
    node.create_subscription(PointCloud2, 'cloud_in', lambda msg: pub.publish(LaserScan()), 10)
    rclpy.spin(node)
"""

LAUNCH = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('cloud_topic_in'),
        DeclareLaunchArgument('scan_topic_out'),
        Node(package='flat', executable='flatten', namespace='drone0',
             remappings=[REMAPS]),
    ])
"""


def _remap_findings(write_tree, remaps: str) -> list[tuple[str, str]]:
    root = write_tree({
        "src/flat/package.xml": package_xml("flat", build_type="ament_python").replace(
            "</package>", "<depend>rclpy</depend><depend>sensor_msgs</depend></package>"),
        "src/flat/setup.py": ("from setuptools import setup\nsetup(name='flat', "
                              "entry_points={'console_scripts': "
                              "['flatten = flat.flatten:main']})\n"),
        "src/flat/flat/__init__.py": "",
        "src/flat/flat/flatten.py": NODE,
        "src/flat/launch/flat.launch.py": LAUNCH.replace("REMAPS", remaps),
        "project.yaml": "project: p\ndistro: jazzy\nconfigurations:\n"
                        "  c: [flat/launch/flat.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    return [(f.rule, f.message) for f in run_catalogue(model)
            if f.rule.startswith("remap-unused")]


CLOUD = "('cloud', LaunchConfiguration('cloud_topic_in'))"
SCAN = "('scan', LaunchConfiguration('scan_topic_out'))"


def test_an_unused_remap_beside_a_used_one_both_to_unknown_names(write_tree) -> None:
    found = _remap_findings(write_tree, f"{CLOUD}, {SCAN}")
    assert [rule for rule, _ in found] == ["remap-unused"]
    assert found[0][1].startswith("cloud:=? is given to /drone0/flatten")


def test_the_unused_remap_alone_and_the_used_one_alone(write_tree) -> None:
    assert [rule for rule, _ in _remap_findings(write_tree, CLOUD)] == ["remap-unused"]
    assert _remap_findings(write_tree, SCAN) == []
