"""A ROS 2 launch argument declared that nothing of the whole launch reads by name is
said, LAUNCH_ARG_UNUSED (warning), where it is declared: raspimouse_slam_navigation_ros2
e71c388's pc_navigation.launch.py declared ``use_sim_tim`` (default True) and read
``LaunchConfiguration('use_sim_time', default='False')``, so nav2 and rviz2 ran on wall
time. An argument read by an included file, or only under a condition that does not
hold, is used; nothing is said when a part of the launch is not seen (an include of a
file not read), which may read it."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

TOP = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    use_sim_time = LaunchConfiguration('use_sim_time', default='False')
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_tim', default_value='True'),
        DeclareLaunchArgument('robot', default_value='mouse'),
        DeclareLaunchArgument('rviz', default_value='false'),
        DeclareLaunchArgument('rviz_file', default_value='view.rviz'),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(
            get_package_share_directory(INCLUDED), 'launch', 'inner.launch.py'))),
        Node(package='rviz2', executable='rviz2', condition=IfCondition(
             LaunchConfiguration('rviz')), arguments=['-d', LaunchConfiguration('rviz_file')],
             parameters=[{'use_sim_time': use_sim_time}]),
    ])
"""

INNER = """
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='talker', name=LaunchConfiguration('robot')),
    ])
"""


def _said(write_tree, included: str) -> list[tuple[str, int]]:
    root = write_tree({"src/demo/package.xml": package_xml("demo", "ament_python"),
                       "src/demo/launch/top.launch.py": TOP.replace("INCLUDED",
                                                                    repr(included)),
                       "src/demo/launch/inner.launch.py": INNER})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/demo/launch/top.launch.py"), ws, {}, {})
    return [(d.message, d.location.line) for d in model.diagnostics
            if d.code == "LAUNCH_ARG_UNUSED"]


def test_declared_argument_nothing_reads_is_said(write_tree) -> None:
    assert _said(write_tree, "demo") == [
        ("launch argument use_sim_tim is declared but nothing in the launch reads it: its "
         "value changes nothing; a configuration of a near name is read and never "
         "declared: use_sim_time", 14)]


def test_not_said_when_an_include_is_not_read(write_tree) -> None:
    assert _said(write_tree, "not_here") == []
