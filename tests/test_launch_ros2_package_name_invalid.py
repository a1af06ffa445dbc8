"""A ROS 2 launch file that looks up a package by a text no package can be named
(empty, blanks, a `/`: catkin_pkg refuses such a name, so no workspace or install holds
it) fails there: ament_index_python raises PackageNotFoundError at
``get_package_share_directory`` when the call runs, and launch at a
``FindPackageShare`` when it performs it (ASV_Loyola_US's zed2i_with_costmap.launch.py
called ``get_package_share_directory('   ')`` for nav2_bringup in its OpaqueFunction).
It was left as a package installed on the robot, perhaps, not said; it is
``PACKAGE_NOT_FOUND`` now, as a misspelt package is. A valid name near no package stays
unsaid."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

PY = """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare

def setup(context, *args, **kwargs):
    unused = os.path.join(get_package_share_directory('   '), 'launch')
    other = get_package_share_directory('some_robot_driver')
    return [Node(package='rviz2', executable='rviz2',
                 arguments=['-d', FindPackageShare('my/pkg')])]

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
"""


def test_a_text_no_package_can_be_named_is_not_found(write_tree):
    root = write_tree({"src/other/package.xml": package_xml("other"),
                       "src/other/launch/main.launch.py": PY})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/other/launch/main.launch.py"), ws, {}, {})
    missing = [(d.location.line, d.message) for d in model.diagnostics
               if d.code == "PACKAGE_NOT_FOUND"]
    assert [line for line, _ in missing] == [9, 11], missing
    assert "'   '" in missing[0][1] and "catkin_pkg refuses" in missing[0][1], missing
    assert "'my/pkg'" in missing[1][1], missing
    # a valid name near no package: installed where the robot runs, perhaps
    assert not any("some_robot_driver" in d.message and d.severity == "error"
                   for d in model.diagnostics)
