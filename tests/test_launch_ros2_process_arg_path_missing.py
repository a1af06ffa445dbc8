"""A ROS 2 ``ExecuteProcess`` (``<executable cmd=...>``) that starts no node the reader
can name, given among its arguments an absolute path into a workspace package's share
folder that the build does not install and no source holds, is said,
LAUNCH_PROCESS_ARG_PATH_MISSING (warning), as a node's arguments are
(LAUNCH_NODE_ARG_PATH_MISSING): ``rviz2 -d <share>/rviz/gone.rviz`` run as a process
opens no configuration, ``python3 <share>/scripts/gone.py`` fails. Its paths were not
judged at all. A path that is there, one with a part not known, one given to an option
of output, a shell redirection's file and the arguments of a program that makes the
files it is given (``cp``, ``mkdir``) are not said; ``ros2 run`` / ``ros2 launch`` are
judged as before (the node's package and executable, the launch file)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

PY = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import ExecuteProcess
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    share = get_package_share_directory('demo')
    return LaunchDescription([
        ExecuteProcess(cmd=['rviz2', '-d', os.path.join(share, 'rviz', 'gone.rviz')]),
        ExecuteProcess(cmd=['rviz2', '-d', PathJoinSubstitution(
            [FindPackageShare('demo'), 'rviz', 'lost.rviz'])]),
        ExecuteProcess(cmd=['python3', os.path.join(share, 'scripts', 'gone.py')]),
        ExecuteProcess(cmd=['rviz2', '-d', os.path.join(share, 'rviz', 'here.rviz')]),
        ExecuteProcess(cmd=['rviz2', '-d', PathJoinSubstitution(
            [FindPackageShare('demo'), 'rviz', LaunchConfiguration('cfg')])]),
        ExecuteProcess(cmd=['recorder', '-o', os.path.join(share, 'rviz', 'out.bag')]),
        ExecuteProcess(cmd=['cp', os.path.join(share, 'rviz', 'here.rviz'),
                            os.path.join(share, 'rviz', 'copy.rviz')]),
        ExecuteProcess(cmd=['echo hi > ' + os.path.join(share, 'rviz', 'log.txt')],
                       shell=True),
    ])
"""

XML = """<launch>
  <executable cmd="rviz2 -d $(find-pkg-share demo)/rviz/xml_gone.rviz"/>
  <executable cmd="rviz2 -d $(find-pkg-share demo)/rviz/here.rviz"/>
</launch>
"""


def test_a_process_given_a_path_that_is_not_there(write_tree) -> None:
    root = write_tree({"src/demo/package.xml": package_xml("demo", "ament_python"),
                       "src/demo/setup.py": "from setuptools import setup\n"
                                            "setup(name='demo', data_files=[('share/demo/"
                                            "rviz', ['rviz/here.rviz'])])\n",
                       "src/demo/rviz/here.rviz": "",
                       "src/demo/scripts/other.py": "",
                       "src/demo/launch/run.launch.py": PY,
                       "src/demo/launch/run.launch.xml": XML})
    ws = scan([str(root / "src")], {})
    for name, expected in (
            ("run.launch.py", [
                (12, "process rviz2 is given the path demo/rviz/gone.rviz on its command "
                     "line, which is not there"),
                (13, "process rviz2 is given the path demo/rviz/lost.rviz on its command "
                     "line, which is not there"),
                (15, "process python3 is given the path demo/scripts/gone.py on its "
                     "command line, which is not there")]),
            ("run.launch.xml", [
                (2, "process rviz2 is given the path demo/rviz/xml_gone.rviz on its "
                    "command line, which is not there")])):
        model = load(str(root / "src/demo/launch" / name), ws, {}, {})
        said = sorted((d.location.line, d.message) for d in model.diagnostics
                      if d.code == "LAUNCH_PROCESS_ARG_PATH_MISSING")
        assert said == expected, name
