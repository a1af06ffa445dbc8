"""A ROS 2 Python launch file's ``get_package_share_directory('nav_bringupp')`` looks
the package up when the call runs: ament_index_python raises PackageNotFoundError there,
whatever the condition of the action its value goes to (erasers_kachaka's xtion.launch.py
built rviz2's ``-d`` path with ``'erasers_kachaka__vision'`` for a node started only in
debug). A package that is neither here nor installed, a letter or two from one that is,
is said at the call as ``PACKAGE_NOT_FOUND`` (so ``launch-missing-reference``), once,
even when no action performs the value; one near no package stays unsaid there (installed
where the robot runs, perhaps), and one asked for in a ``try`` that catches its absence
is no error."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

PY = """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare

def generate_launch_description():
    try:
        optional = get_package_share_directory('nav_bringupx')
    except Exception:
        optional = ''
    far = get_package_share_directory('unknown_pkg')
    found = FindPackageShare('nav_bringupy').find('nav_bringupy')
    return LaunchDescription([
        Node(package='rviz2', executable='rviz2',
             condition=IfCondition(LaunchConfiguration('debug', default='false')),
             arguments=['-d', os.path.join(
                 get_package_share_directory('nav_bringupp'), 'rviz', 'x.rviz')]),
        Node(package='rviz2', executable='rviz2', name='always',
             arguments=['-d', os.path.join(
                 get_package_share_directory('nav_bringupz'), 'rviz', 'x.rviz')]),
    ])
"""

FILES = {
    "src/nav_bringup/package.xml": package_xml("nav_bringup"),
    "src/other/package.xml": package_xml("other"),
    "src/other/launch/main.launch.py": PY,
}


def test_a_misspelt_package_looked_up_by_a_call_is_said_at_the_call(write_tree):
    root = write_tree(FILES)
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/other/launch/main.launch.py"), ws, {}, {})
    missing = [(d.location.line, d.message) for d in model.diagnostics
               if d.code == "PACKAGE_NOT_FOUND"]
    assert missing == [
        (15, "package nav_bringupy is not in the workspace nor installed here "
             "(did you mean nav_bringup?)"),
        # under a condition that does not hold: the call runs all the same
        (20, "package nav_bringupp is not in the workspace nor installed here "
             "(did you mean nav_bringup?)"),
        # performed by a node that starts: said at the call, not again at the node
        (23, "package nav_bringupz is not in the workspace nor installed here "
             "(did you mean nav_bringup?)")]
    # near no package: installed where the robot runs, perhaps; no error
    assert not any("unknown_pkg" in d.message and d.severity == "error"
                   for d in model.diagnostics)
