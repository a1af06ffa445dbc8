"""launch_pal's ``include_launch_py_description(pkg, paths, **kwargs)`` (PAL Robotics'
TIAGo, PMB2 launch files; tiago_simulation's tiago_gazebo.launch.py includes the robot's
spawn, bringup, navigation and MoveIt files so) is the include of the package's launch
file at that path: the file was a call not interpreted, its nodes unseen."""

from __future__ import annotations

from test_launch_ros2_python import run


def test_the_pal_include_is_an_include_of_the_package_s_file(write_tree) -> None:
    model, _ = run(write_tree, """
from launch_pal.include_utils import include_launch_py_description

def generate_launch_description():
    spawn = include_launch_py_description(
        'pkg', ['launch', 'part.launch.py'],
        launch_arguments={'robot': 'tiago'}.items())
    skipped = include_launch_py_description(
        'pkg', ['launch', 'part.launch.py'], condition=IfCondition('false'))
    return LaunchDescription([spawn, skipped])
""", extra={"src/pkg/launch/part.launch.py": HEADER_PART})
    assert [n.name for n in model.nodes] == ["/tiago_spawner"]
    assert "LAUNCH_PY_UNSUPPORTED" not in [d.code for d in model.diagnostics]


HEADER_PART = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='robot'),
        Node(package='spawner', executable='spawn',
             name=[LaunchConfiguration('robot'), '_spawner']),
    ])
"""
