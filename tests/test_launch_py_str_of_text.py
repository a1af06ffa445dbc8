"""``str()`` of a text a Python launch file makes that is known only when launch runs (a
share folder ``get_package_share_directory`` gives, a path ``os.path.join`` joins of
one): Python's ``str`` of a ``str`` is that string. tractobots' nav2.launch.py:15
includes ``str(get_package_share_directory('nav2_bringup') +
'/launch/navigation_launch.py')``, nav2_bringup not in the workspace: "str() of values
not known statically" and "included file ? is not known statically" (two warnings),
where the same path without ``str()`` is an include of a package not here, said once as
an info. Now the ``str()`` is the text it is given; the same for a launch file of the
workspace (read) and a parameter file of a node."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

MAIN = '''import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node


def generate_launch_description():
    nav2 = IncludeLaunchDescription(PythonLaunchDescriptionSource(
        [str(get_package_share_directory('nav2_bringup') + '/launch/navigation_launch.py')]))
    own = IncludeLaunchDescription(PythonLaunchDescriptionSource(
        str(os.path.join(get_package_share_directory('pkg'), 'launch', 'b.launch.py'))))
    params = str(os.path.join(get_package_share_directory('pkg'), 'config', 'p.yaml'))
    return LaunchDescription([nav2, own, Node(package='pkg', executable='a', name='a',
                                              parameters=[params])])
'''

INCLUDED = '''from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='pkg', executable='b', name='b')])
'''


def test_str_of_a_text_known_when_launch_runs_is_that_text(write_tree):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "src/pkg/launch/a.launch.py": MAIN,
                       "src/pkg/launch/b.launch.py": INCLUDED,
                       "src/pkg/config/p.yaml": "a:\n  ros__parameters:\n    rate: 5\n"})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/pkg/launch/a.launch.py"), ws, {}, {})
    assert [(d.code, d.severity) for d in model.diagnostics] == [
        ("LAUNCH_UNKNOWN_VALUE", "info")], model.diagnostics
    assert "nav2_bringup" in model.diagnostics[0].message
    assert sorted(n.name for n in model.nodes) == ["/a", "/b"]
    assert [(p.name, p.value) for p in model.params] == [("/a/rate", 5)]
