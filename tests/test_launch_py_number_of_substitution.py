"""``int()`` / ``float()`` of a launch substitution object: panther_ros 03ada6da's
manager_bt.launch.py computed ``float(EnvironmentVariable(name="PANTHER_ROBOT_VERSION",
default_value="1.2"))`` in generate_launch_description. No class of launch converts to a
number, so Python raises TypeError and the launch file does not load; said where the call
is (LAUNCH_PY_UNSUPPORTED, the Python error of the interpreted code). The value a
substitution gives when performed (``.perform(context)`` in an OpaqueFunction) and a
``str`` from ``os.environ`` are strings, converted as before, not said."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

LAUNCH = """import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import EnvironmentVariable, LaunchConfiguration
from launch_ros.actions import Node


def setup(context):
    count = int(LaunchConfiguration('count').perform(context))
    rate = float(context.launch_configurations['rate'])
    return [Node(package='pkg', executable='x', name=f'x{i}',
                 parameters=[{'rate': rate}]) for i in range(count)]


def generate_launch_description():
    version = float(EnvironmentVariable(name='ROBOT_VERSION', default_value='1.2'))
    size = int(LaunchConfiguration('count'))
    level = int(os.environ.get('LEVEL', '3')) + int('4') + int(float('2.5'))
    return LaunchDescription([
        DeclareLaunchArgument('count', default_value='2'),
        DeclareLaunchArgument('rate', default_value='2.5'),
        OpaqueFunction(function=setup),
    ])
"""


def test_a_number_of_a_substitution_fails(write_tree) -> None:
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_python"),
                       "src/pkg/launch/main.launch.py": LAUNCH})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/pkg/launch/main.launch.py"), ws, {}, {})
    said = sorted((d.location.line, d.message) for d in model.diagnostics
                  if d.code == "LAUNCH_PY_UNSUPPORTED")
    assert [line for line, _ in said] == [16, 17]
    assert "float()" in said[0][1] and "not EnvironmentVariable" in said[0][1]
    assert "int()" in said[1][1] and "not LaunchConfiguration" in said[1][1]
    assert all("TypeError" in message for _, message in said)
    # performed values are strings: converted, the nodes made
    assert sorted(str(node.name) for node in model.nodes) == ["/x0", "/x1"]
