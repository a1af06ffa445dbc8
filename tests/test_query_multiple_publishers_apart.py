"""multiple-publishers claims that two publishers run together. Interbotix's
xsarm_moveit.launch.py spawns arm_controller through ros2_control (under
``IfCondition(PythonExpression(['"', hw, '"', " in ('actual', 'fake')"]))``) or through
Gazebo (``LaunchConfigurationEquals('hardware_type', 'gz_classic')``), an argument none
of its launch files sets: two instances of /wx250s/arm_controller under conditions not
known and not the same, of which one may run without the other. They were a warning
(/wx250s/arm_controller/controller_state "published by /wx250s/arm_controller (2
instances)"); duplicate-node-names already counts such a pair as undecided. (Those two
conditions are now read as excluding each other, test_launch_ros2_equals_exclusive; two
arguments not known, here, stay undecided.) Publishers under the same condition still
run together: a warning."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load as load_project
from haros_arch.query.catalogue import load_catalogue, run_rule

LAUNCH = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, LaunchConfigurationEquals
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node

def generate_launch_description():
    hw = LaunchConfiguration('hw')
    return LaunchDescription([
        DeclareLaunchArgument('hw'), DeclareLaunchArgument('gazebo'),
        DeclareLaunchArgument('sim'),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             name='rsp', condition=IfCondition(
                 PythonExpression(["'", hw, "' in ('actual', 'fake')"]))),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             name='rsp', condition=LaunchConfigurationEquals('gazebo', 'classic')),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             name='sim_a', namespace='sim', condition=IfCondition(LaunchConfiguration('sim'))),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             name='sim_b', namespace='sim', condition=IfCondition(LaunchConfiguration('sim'))),
    ])
"""


def test_publishers_under_different_unknown_conditions_are_undecided(write_tree) -> None:
    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_python"),
        "src/p/launch/a.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [p/launch/a.launch.py]\n",
    })
    model = analyse(load_project(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    rule = next(r for r in load_catalogue() if r.id == "multiple-publishers")
    found = {f.rule: f for f in run_rule(rule, model)}
    assert set(found) == {"multiple-publishers", "multiple-publishers-undecided"}
    # the two instances of /rsp: one may run without the other
    assert "/robot_description" in found["multiple-publishers-undecided"].message
    assert found["multiple-publishers-undecided"].message.endswith(": /rsp (1)")
    # two publishers under one condition run together whenever either does
    assert found["multiple-publishers"].message.startswith("/sim/robot_description is ")
