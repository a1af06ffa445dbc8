"""A ROS 2 launch condition that compares one launch argument with a string
(``LaunchConfigurationEquals('hardware_type', 'fake')``, its ``NotEquals``,
``$(equals $(var hw) fake)``) excludes the same comparison with another string, as an
``$(eval hw == 'fake')`` does in ROS 1. Interbotix's xsarm_moveit.launch.py starts the
robot's description (robot_state_publisher) under ``hardware_type`` equal to 'actual',
'fake' and 'gz_classic', an argument its own launch files cannot know: the three were
read as running together (a false multiple-publishers warning on /<robot>/robot_description
and three undecided duplicate names)."""

from __future__ import annotations

import json
import os

from conftest import package_xml

from haros_arch.launch.ros2 import load
from haros_arch.model.conditions import Condition, exclusive
from haros_arch.model.load import from_data
from haros_arch.model.serialise import to_data
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load as load_project
from haros_arch.query.catalogue import load_catalogue, run_rule
from haros_arch.workspace import scan

PYTHON = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.conditions import LaunchConfigurationEquals, LaunchConfigurationNotEquals
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('hw'), DeclareLaunchArgument('other'),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             name='rsp', condition=LaunchConfigurationEquals('hw', 'actual')),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             name='rsp', condition=LaunchConfigurationEquals(
            launch_configuration_name='hw', expected_value='fake')),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             name='rsp', condition=LaunchConfigurationNotEquals('hw', 'fake')),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             name='rsp', condition=LaunchConfigurationEquals('other', 'fake')),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             name='rsp', condition=IfCondition(PythonExpression(
                 ['"', LaunchConfiguration('hw'), '"', " in ('actual', 'fake')"]))),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             name='rsp', condition=UnlessCondition(PythonExpression(
                 ["'gz' == '", LaunchConfiguration('hw'), "'"]))),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             name='rsp', condition=IfCondition(PythonExpression(
                 ["'", LaunchConfiguration('hw'), "' == '", LaunchConfiguration('other'),
                  "'"]))),
    ])
"""

XML = """<launch>
  <arg name="hw"/>
  <node pkg="robot_state_publisher" exec="robot_state_publisher" name="rsp"
        if="$(equals $(var hw) actual)"/>
  <node pkg="robot_state_publisher" exec="robot_state_publisher" name="rsp"
        if="$(equals fake $(var hw))"/>
  <node pkg="robot_state_publisher" exec="robot_state_publisher" name="rsp"
        if="$(not-equals $(var hw) fake)"/>
  <node pkg="robot_state_publisher" exec="robot_state_publisher" name="rsp"
        unless="$(equals $(var hw) fake)"/>
</launch>
"""


def _nodes(write_tree, name: str, text: str):
    root = write_tree({"src/p/package.xml": package_xml("p", "ament_python"),
                       f"src/p/launch/{name}": text})
    workspace = scan([str(root / "src")], {})
    return load(str(root / "src/p/launch" / name), workspace, {}, {}).nodes


def test_python_equals_of_one_argument_and_other_strings_exclude(write_tree) -> None:
    actual, fake, not_fake, other, real, not_gz, two = _nodes(
        write_tree, "a.launch.py", PYTHON)
    assert actual.conditions[0].compares == ("hw", ("actual",), True)
    assert exclusive(actual.conditions, fake.conditions)
    assert exclusive(fake.conditions, not_fake.conditions)
    assert not exclusive(actual.conditions, not_fake.conditions)
    assert not exclusive(fake.conditions, other.conditions)  # another argument
    # Interbotix's ros2_control branch: hardware_type in ('actual', 'fake')
    assert real.conditions[0].compares == ("hw", ("actual", "fake"), True)
    gz = [c.compares for c in not_gz.conditions]
    assert gz == [("hw", ("gz",), False)]  # unless 'gz' == hw
    assert not exclusive(real.conditions, actual.conditions)
    assert exclusive(real.conditions, not_fake.conditions) is False
    assert not exclusive(real.conditions, not_gz.conditions)
    # ... and the Gazebo branch, hardware_type == 'gz_classic', never runs beside it
    gz_classic = (Condition("x", "launch", "if", compares=("hw", ("gz_classic",), True)),)
    assert exclusive(real.conditions, gz_classic) and exclusive(gz_classic, real.conditions)
    assert exclusive(not_gz.conditions, (Condition(
        "y", "launch", "if", compares=("hw", ("gz",), True)),))
    assert two.conditions[0].compares is None  # two arguments not known


def test_xml_equals_of_one_argument_and_other_strings_exclude(write_tree) -> None:
    actual, fake, not_fake, unless_fake = _nodes(write_tree, "a.launch.xml", XML)
    assert exclusive(actual.conditions, fake.conditions)
    assert exclusive(fake.conditions, not_fake.conditions)
    assert exclusive(fake.conditions, unless_fake.conditions)
    assert not exclusive(actual.conditions, not_fake.conditions)
    assert not exclusive(not_fake.conditions, unless_fake.conditions)


def test_no_warning_for_publishers_one_argument_keeps_apart(write_tree) -> None:
    nodes = "".join(
        "        Node(package='robot_state_publisher', executable='robot_state_publisher',\n"
        f"             name='rsp', condition=LaunchConfigurationEquals('hw', '{hw}')),\n"
        for hw in ("actual", "fake", "gz_classic"))
    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_python"),
        "src/p/launch/a.launch.py": PYTHON.split("        Node(")[0] + nodes + "    ])\n",
        "project.yaml": "project: p\nconfigurations:\n  c: [p/launch/a.launch.py]\n",
    })
    model = analyse(load_project(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    config = model.configuration("c")
    publishers = [link.node.name for link in config.links
                  if link.kind == "publish" and link.rosname.full == "/robot_description"]
    assert publishers == ["/rsp"] * 3  # the model's publisher, once per instance
    rules = {rule.id: rule for rule in load_catalogue()}
    # a model read back from its JSON (check of a saved model) keeps the comparison
    saved = from_data(json.loads(json.dumps(to_data(model))))
    for rule in ("multiple-publishers", "duplicate-node-names"):
        assert [f.message for f in run_rule(rules[rule], model)] == [], rule
        assert [f.message for f in run_rule(rules[rule], saved)] == [], rule
