"""A substitution class a ROS 2 launch file defines on launch's ``Substitution``, with a
``perform`` of its own, is not interpreted, but launch performs its object where the
action using it runs, and its ``perform`` performs the substitutions its constructor
was given: a launch configuration among them that nothing has declared or set there is
LAUNCH_ARG_UNSET. turtlebot4_simulator decdf2b's ignition.launch.py passed
``OffsetParser(LaunchConfiguration('x'), 0.157)`` to the include of the dock's
description, which declares x only when it runs: launch raised SubstitutionFailure."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

PY = """
from launch import LaunchDescription, LaunchContext, Substitution
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


class OffsetParser(Substitution):
    def __init__(self, number, offset):
        self.__number = number
        self.__offset = offset

    def perform(self, context: LaunchContext = None) -> str:
        number = float(self.__number.perform(context))
        return f'{number + self.__offset}'


def generate_launch_description():
    x = LaunchConfiguration('x')
    y = LaunchConfiguration('y')
    return LaunchDescription([
        DECLARE
        Node(package='tf2_ros', executable='static_transform_publisher', name='dock_tf',
             arguments=['--x', OffsetParser(x, 0.157), '--y', OffsetParser(y, 0.0),
                        '--frame-id', 'map', '--child-frame-id', 'dock']),
    ])
"""


def _unset(tmp, declare: str) -> list[str]:
    root = tmp({"src/pkg/package.xml": package_xml("pkg", "ament_python"),
                "src/pkg/launch/dock.launch.py": PY.replace("DECLARE", declare)})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/pkg/launch/dock.launch.py"), ws, {}, {})
    return sorted(d.message.split()[2] for d in model.diagnostics
                  if d.code == "LAUNCH_ARG_UNSET")


def test_configuration_given_to_a_substitution_class_and_never_declared(write_tree) -> None:
    assert _unset(write_tree, "DeclareLaunchArgument('y', default_value='1.0'),") == ["x"]


def test_configurations_declared_are_not_said(write_tree) -> None:
    assert _unset(write_tree, "DeclareLaunchArgument('x', default_value='0.0'), "
                              "DeclareLaunchArgument('y', default_value='1.0'),") == []
