"""A ROS 2 node launched without ``name=`` whose code names it at run time around text
it writes: tf2_ros' static_transform_publisher (humble and jazzy,
static_transform_broadcaster_node.cpp) is ``static_transform_publisher_`` and 16 random
characters. The instance is ``<namespace>/static_transform_publisher_?``, as an
anonymous name (``$(anon x)``, ``x_?``) is: its node known, its name in part; earlier it
was ``/?``. A parameter file's section for a node stays a warning (the name is not
known)."""

from __future__ import annotations

import os
from textwrap import dedent

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

SETUP = """
    from setuptools import setup
    setup(name='talk', packages=['talk'],
          entry_points={'console_scripts': ['talker = talk.talker:main']})
    """

TALKER = """
    import os
    import rclpy
    from std_msgs.msg import String

    def main():
        rclpy.init()
        node = rclpy.create_node('talker_' + os.environ['SUFFIX'])
        node.declare_parameter('rate', 1.0)
        node.create_publisher(String, '~/status', 10)
        rclpy.spin(node)
    """

LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        return LaunchDescription([
            Node(package='talk', executable='talker', namespace='robot',
                 parameters=[{'rate': 5.0}]),
            Node(package='talk', executable='talker', namespace='robot',
                 parameters=['talk.yaml']),
        ])
    """


def test_a_node_named_in_part_by_its_code(write_tree) -> None:
    root = write_tree({
        "src/talk/package.xml": package_xml("talk", build_type="ament_python"),
        "src/talk/setup.py": SETUP,
        "src/talk/resource/talk": "",
        "src/talk/talk/__init__.py": "",
        "src/talk/talk/talker.py": TALKER,
        "src/talk/launch/talk.yaml": "talker_x:\n  ros__parameters:\n    rate: 7.0\n",
        "project.yaml": "project: p\nconfigurations:\n  c: [talk/launch/talk.launch.py]\n",
    })
    yaml = root / "src/talk/launch/talk.yaml"
    (root / "src/talk/launch/talk.launch.py").write_text(dedent(LAUNCH).replace(
        "'talk.yaml'", repr(str(yaml))))
    model = analyse(load(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    config = model.configuration("c")
    assert [n.name for n in config.nodes] == ["/robot/talker_?", "/robot/talker_?"]
    assert all(n.node is not None for n in config.nodes)
    assert sorted({(link.kind, link.rosname.full) for link in config.links}) == [
        ("publish", "/robot/talker_?/status"), ("read", "/robot/talker_?/rate")]
    # the section for talker_x: the name is not known, the warning stays
    assert [d.code for d in config.diagnostics if d.code == "LAUNCH_PARAM_FILE"] == [
        "LAUNCH_PARAM_FILE"]


STATIC = """<launch>
  <node pkg="tf2_ros" exec="static_transform_publisher" namespace="robot"
        args="--frame-id map --child-frame-id odom"/>
  <node pkg="tf2_ros" exec="static_transform_publisher" name="odom_to_base"
        args="--frame-id odom --child-frame-id base_link"/>
</launch>
"""


def test_static_transform_publisher_without_a_name(write_tree) -> None:
    """The shipped tf2_ros model (jazzy's, humble's too): the node is known, its name
    ``static_transform_publisher_?`` (the override read in geometry2's source), its
    parameters under that name; the one the launch names is named so."""
    root = write_tree({
        "src/bringup/package.xml": package_xml("bringup", build_type="ament_cmake"),
        "src/bringup/launch/tf.launch.xml": STATIC,
        "project.yaml": "project: p\ndistro: humble\n"
                        "configurations:\n  c: [bringup/launch/tf.launch.xml]\n",
    })
    model = analyse(load(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    config = model.configuration("c")
    assert sorted(n.name for n in config.nodes) == [
        "/odom_to_base", "/robot/static_transform_publisher_?"]
    assert all(n.node is not None and n.node.name == "tf2_ros/static_transform_publisher"
               for n in config.nodes)
    declared = {link.rosname.full for link in config.links if link.kind == "read"}
    assert "/robot/static_transform_publisher_?/frame_id" in declared
    assert "/odom_to_base/frame_id" in declared
