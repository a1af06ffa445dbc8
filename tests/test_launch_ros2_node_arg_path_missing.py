"""A ROS 2 node given, among its ``arguments``, an absolute path into a workspace
package's share folder that its build does not install and no source holds is said,
LAUNCH_NODE_ARG_PATH_MISSING (warning), at the node, as a ROS 1 node's ``args`` are:
mycobot_ros2 83acce0's detect_marker.launch.py gave rviz2 ``-d`` its package's
``config/mypal_260.rviz`` (the folder holds ``mypalletizer.rviz``) and rviz opened
without it; waveshare's ugv_ws 5a6618a, Python's ``os.path.join`` of
``get_package_share_directory``, and the XML front end's ``$(find-pkg-share)`` the same.
A file that is there, one with a part not known, one the build makes
(``configure_file``), one in a folder that is not there (the launch file may make it and
write the file: bitbots_main's domain bridge configurations) and one given to an option of
output (map_saver_cli's ``-f``) are not said."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(viz)
find_package(ament_cmake REQUIRED)
configure_file(templates/made.rviz.in ${CMAKE_CURRENT_BINARY_DIR}/made.rviz)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/made.rviz DESTINATION share/${PROJECT_NAME}/config)
install(DIRECTORY config launch DESTINATION share/${PROJECT_NAME})
ament_package()
"""

PY = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    share = get_package_share_directory('viz')
    return LaunchDescription([
        DeclareLaunchArgument('rvizconfig', default_value=os.path.join(
            share, 'config', 'RVIZ_FILE')),
        Node(package='rviz2', executable='rviz2', name='rviz2',
             arguments=['-d', LaunchConfiguration('rvizconfig')]),
        Node(package='rviz2', executable='rviz2', name='rviz_made',
             arguments=['-d', os.path.join(share, 'config', 'made.rviz')]),
        Node(package='rviz2', executable='rviz2', name='rviz_unknown',
             arguments=['-d', PathJoinSubstitution([FindPackageShare('viz'), 'config',
                                                    LaunchConfiguration('other')])]),
        Node(package='domain_bridge', executable='domain_bridge', name='bridge',
             arguments=[os.path.join(share, 'config', 'made_at_launch', 'bridge.yaml')]),
        Node(package='nav2_map_server', executable='map_saver_cli', name='saver',
             arguments=['-f', os.path.join(share, 'maps', 'new_map')]),
    ])
"""

XML = """<launch>
  <node pkg="rviz2" exec="rviz2" name="rviz_xml"
        args="-d $(find-pkg-share viz)/config/RVIZ_FILE"/>
</launch>
"""


def _said(write_tree, rviz_file: str) -> list[tuple[str, str, int]]:
    root = write_tree({"src/viz/package.xml": package_xml("viz", "ament_cmake"),
                       "src/viz/CMakeLists.txt": CMAKE,
                       "src/viz/templates/made.rviz.in": "Panels: []\n",
                       "src/viz/config/view.rviz": "Panels: []\n",
                       "src/viz/launch/view.launch.py": PY.replace("RVIZ_FILE", rviz_file),
                       "src/viz/launch/view.launch.xml": XML.replace("RVIZ_FILE",
                                                                     rviz_file)})
    ws = scan([str(root / "src")], {})
    found = []
    for name in ("view.launch.py", "view.launch.xml"):
        model = load(str(root / "src/viz/launch" / name), ws, {}, {})
        found += [(d.location.file.rsplit("/", 1)[-1], d.message, d.location.line)
                  for d in model.diagnostics if d.code == "LAUNCH_NODE_ARG_PATH_MISSING"]
    return sorted(found)


def test_rviz_config_not_in_the_share_folder_is_said(write_tree) -> None:
    assert _said(write_tree, "missing.rviz") == [
        ("view.launch.py", "node /rviz2 is given the path viz/config/missing.rviz on its "
         "command line, which is not there", 15),
        ("view.launch.xml", "node /rviz_xml is given the path viz/config/missing.rviz on "
         "its command line, which is not there", 2)]


def test_rviz_config_that_is_there_is_not_said(write_tree) -> None:
    assert _said(write_tree, "view.rviz") == []
