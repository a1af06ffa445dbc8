"""ROS 2 remapping order: rcl applies the FIRST rule that matches a name (rcl/remap.c,
``rcl_remap_first_match``; a node's local rules before the process's global ones),
where ROS 1 (roscpp, rospy) keeps the LAST. launch_ros writes a Node's command line as
``arguments``, ``--ros-args`` + ``ros_arguments``, then its own ``-r __node``/``__ns``,
then ``SetRemap`` rules of the scope, then its ``remappings`` (launch_ros
actions/node.py); a ComposableNode's request holds the scope's ``SetRemap`` rules, then
its own (load_composable_nodes.py), and the component takes no rule of its container's
process (rclcpp_components: ``use_global_arguments(false)``). A rule written
``node:from`` applies to the node of that name alone."""

from __future__ import annotations

import os

import pytest
from conftest import package_xml

from haros_arch.model.rosname import resolve_remaps
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

SETUP = """
from setuptools import setup
setup(name='talk', packages=['talk'],
      entry_points={'console_scripts': ['talker = talk.talker:main']})
"""

TALKER = """
import rclpy
from std_msgs.msg import String

def main():
    rclpy.init()
    node = rclpy.create_node('talker')
    node.create_publisher(String, 'chatter', 10)
    rclpy.spin(node)
"""

PY = """
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, SetRemap

def generate_launch_description():
    return LaunchDescription([
        GroupAction([
            SetRemap(src='chatter', dst='from_group'),
            SetRemap(src='chatter', dst='from_group_later'),
            Node(package='talk', executable='talker', name='grouped',
                 remappings=[('chatter', 'own')]),
        ]),
        Node(package='talk', executable='talker', name='own',
             remappings=[('chatter', 'own_first'), ('/chatter', 'own_second')]),
        Node(package='talk', executable='talker', name='args',
             arguments=['--ros-args', '-r', 'chatter:=from_args'],
             ros_arguments=['-r', 'chatter:=from_ros_args'],
             remappings=[('chatter', 'own')]),
        Node(package='talk', executable='talker', name='ros_args',
             ros_arguments=['-r', 'chatter:=from_ros_args', '-r', 'chatter:=later'],
             remappings=[('chatter', 'own')]),
        Node(package='talk', executable='talker', name='launch_name',
             ros_arguments=['-r', '__node:=renamed', '-r', '__node:=renamed_later']),
        GroupAction([
            SetRemap(src='pa:chatter', dst='only_pa'),
            Node(package='talk', executable='talker', name='pa'),
            Node(package='talk', executable='talker', name='pb'),
        ]),
    ])
"""

XML = """
<launch>
  <group>
    <set_remap from="chatter" to="from_group"/>
    <set_remap from="chatter" to="from_group_later"/>
    <node pkg="talk" exec="talker" name="grouped">
      <remap from="chatter" to="own"/>
    </node>
  </group>
  <node pkg="talk" exec="talker" name="own">
    <remap from="chatter" to="own_first"/>
    <remap from="/chatter" to="own_second"/>
  </node>
  <node pkg="talk" exec="talker" name="args" args="--ros-args -r chatter:=from_args"
        ros_args="-r chatter:=from_ros_args">
    <remap from="chatter" to="own"/>
  </node>
  <node pkg="talk" exec="talker" name="ros_args"
        ros_args="-r chatter:=from_ros_args -r chatter:=later">
    <remap from="chatter" to="own"/>
  </node>
  <node pkg="talk" exec="talker" name="launch_name"
        ros_args="-r __node:=renamed -r __node:=renamed_later"/>
  <group>
    <set_remap from="pa:chatter" to="only_pa"/>
    <node pkg="talk" exec="talker" name="pa"/>
    <node pkg="talk" exec="talker" name="pb"/>
  </group>
</launch>
"""


def build(write_tree, name: str, text: str):
    root = write_tree({
        "src/talk/package.xml": package_xml("talk", build_type="ament_python"),
        "src/talk/setup.py": SETUP,
        "src/talk/resource/talk": "",
        "src/talk/talk/__init__.py": "",
        "src/talk/talk/talker.py": TALKER,
        f"src/talk/launch/{name}": text,
        "project.yaml": f"project: p\nconfigurations:\n  c: [talk/launch/{name}]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    return model.configuration("c")


@pytest.mark.parametrize(("name", "text"), [("t.launch.py", PY), ("t.launch.xml", XML)])
def test_a_name_two_rules_remap_takes_the_rule_rcl_matches_first(write_tree, name, text):
    config = build(write_tree, name, text)
    published = {link.node.name: link.resource.name for link in config.links
                 if link.kind == "publish"}
    assert published == {
        "/grouped": "/from_group",      # SetRemap before the node's own remappings
        "/own": "/own_first",           # its own list: the first rule for /chatter
        "/args": "/from_args",          # arguments' --ros-args come first on the line
        "/ros_args": "/from_ros_args",  # ros_arguments before remappings, first of them
        "/renamed": "/chatter",         # a __node rule in ros_arguments before name=
        "/pa": "/only_pa",              # a rule for the node called pa (rcl's prefix)
        "/pb": "/chatter",              # ... and for no other
    }
    grouped = next(n for n in config.nodes if n.name == "/grouped")
    assert grouped.remapped == [["chatter", "/chatter", "/from_group"]]


def test_resolve_remaps_keeps_the_first_rule_in_ros2_and_the_last_in_ros1():
    pairs = [("a", "first"), ("/ns/a", "second")]
    assert resolve_remaps(pairs, "/ns", "/ns/n", first_wins=True) == {"/ns/a": "/ns/first"}
    assert resolve_remaps(pairs, "/ns", "/ns/n") == {"/ns/a": "/ns/second"}
