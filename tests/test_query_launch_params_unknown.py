"""A launch file that gives a node parameters we cannot see (a parameter file not named
statically or not readable, a Python entry the reader cannot follow) may set any of that
node's parameters: a read of one of them is not called 'never set', it is counted in the
undecided info, which names the launch parameter ``<node>/?``. What the launch is seen
to set is still checked ('set but never read')."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import pytest
from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.query.catalogue import UNDECIDED

ROS2_NODE = """
    import rclpy

    def main():
        rclpy.init()
        node = rclpy.create_node('talker')
        node.declare_parameter('port', rclpy.Parameter.Type.STRING)
        port = node.get_parameter('port').value
        node.declare_parameter('gain', 1.0)
        gain = node.get_parameter('gain').value
    """

ROS2_LAUNCH = """
    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument
    from launch.substitutions import LaunchConfiguration
    from launch_ros.actions import Node
    from talk_tools import robot_parameters

    def generate_launch_description():
        return LaunchDescription([
            DeclareLaunchArgument('params_file'),
            Node(package='talk', executable='talker',
                 parameters=[{'gian': 2.0}, PARAMS]),
        ])
    """


def _ros2(write_tree: Any, params: str) -> dict[str, list[tuple[str, ...]]]:
    root = write_tree({
        "src/talk/package.xml": package_xml("talk", build_type="ament_python"),
        "src/talk/setup.py": "from setuptools import setup\n"
                             "setup(name='talk', packages=['talk'], entry_points="
                             "{'console_scripts': ['talker = talk.talker:main']})\n",
        "src/talk/resource/talk": "",
        "src/talk/talk/__init__.py": "",
        "src/talk/talk/talker.py": ROS2_NODE,
        "src/talk/launch/talk.launch.py": ROS2_LAUNCH.replace("PARAMS", params),
        "project.yaml": "project: p\nconfigurations:\n  c: [talk/launch/talk.launch.py]\n",
    })
    return _findings(root)


def _findings(root: Path) -> dict[str, list[tuple[str, ...]]]:
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    found: dict[str, list[tuple[str, ...]]] = {}
    for finding in run_catalogue(model, project):
        found.setdefault(finding.rule, []).append(finding.entities)
    return found


def test_ros2_all_parameters_known_decides(write_tree: Any) -> None:
    # the control case: every entry is known, so the read of port is decided
    found = _ros2(write_tree, "{'other': 1}")
    assert found.get("parameter-read-not-set") == [("parameter:/talker/port",)]
    assert "parameter-read-not-set" + UNDECIDED not in found
    assert sorted(found["parameter-set-not-read"]) == [("parameter:/talker/gian",),
                                                        ("parameter:/talker/other",)]


@pytest.mark.parametrize("params", [
    "robot_parameters()",  # a function of another module: not followed
    "LaunchConfiguration('params_file')",  # a file named by an argument never given
    "'/outside/the/workspace/params.yaml'",  # a file that cannot be read
], ids=["python-entry", "unnamed-file", "unreadable-file"])
def test_ros2_parameters_not_seen_leave_reads_undecided(write_tree: Any, params: str) -> None:
    found = _ros2(write_tree, params)
    assert "parameter-read-not-set" not in found
    assert found["parameter-read-not-set" + UNDECIDED] == [("parameter:/talker/?",)]
    # what the launch file is seen to set is still checked
    assert found.get("parameter-set-not-read") == [("parameter:/talker/gian",)]


ROS1_NODE = """#!/usr/bin/env python3
import rospy

rospy.init_node("talker")
port = rospy.get_param("~port")
frame = rospy.get_param("/shared/frame")
"""

ROS1_LAUNCH = """
<launch>
  <arg name="config" />
  <node name="talker" pkg="pkg" type="talker.py">
    ROSPARAM
  </node>
</launch>
"""


def _ros1(write_tree: Any, rosparam: str) -> dict[str, list[tuple[str, ...]]]:
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/CMakeLists.txt": "project(pkg)\n",
        "src/pkg/scripts/talker.py": ROS1_NODE,
        "src/pkg/config/known.yaml": "port: 8080\n",
        "src/pkg/launch/a.launch": ROS1_LAUNCH.replace("ROSPARAM", rosparam),
        "project.yaml": "project: p\nconfigurations:\n  c: [pkg/launch/a.launch]\n",
    })
    os.chmod(root / "src/pkg/scripts/talker.py", 0o755)
    return _findings(root)


def test_ros1_a_rosparam_file_read_decides(write_tree: Any) -> None:
    found = _ros1(write_tree, '<rosparam file="$(find pkg)/config/known.yaml" />')
    assert found.get("parameter-read-not-set") == [("parameter:/shared/frame",)]


@pytest.mark.parametrize("rosparam", [
    '<rosparam file="$(find pkg)/config/$(arg config).yaml" />',  # not named statically
    '<rosparam file="/outside/the/workspace/talker.yaml" />',  # not read
    # a package not in the workspace (survey B, ridgeback teleop.launch's
    # interactive_marker_twist_server): the path is not known statically
    '<rosparam command="load" file="$(find not_here)/config/$(arg config).yaml" />',
], ids=["unnamed-file", "unreadable-file", "absent-package"])
def test_ros1_a_rosparam_not_seen_leaves_its_namespace_undecided(
        write_tree: Any, rosparam: str) -> None:
    found = _ros1(write_tree, rosparam)
    # ~port may come from the file loaded in the node's namespace; /shared/frame cannot
    assert found.get("parameter-read-not-set") == [("parameter:/shared/frame",)]
    assert found["parameter-read-not-set" + UNDECIDED] == [("parameter:/talker/?",)]
    # it sets parameters below the node's namespace, never one named after the node
    # (a phantom /talker was then 'set but never read')
    assert "parameter-set-not-read" not in found
    assert "parameter-set-not-read" + UNDECIDED not in found


def test_ros1_a_rosparam_of_one_parameter_not_seen_sets_it(write_tree: Any) -> None:
    # param=: the file's content is that parameter's value, whatever it is
    found = _ros1(write_tree, '<rosparam param="gains" file="$(find pkg)/$(arg config)" />')
    assert found.get("parameter-set-not-read") == [("parameter:/talker/gains",)]


def test_ros1_a_rosparam_in_a_namespace_not_seen_sets_only_below_it(write_tree: Any) -> None:
    # ns= without param=: a dictionary (roslaunch wants one) loaded below /talker/gains/,
    # as move_base's costmaps in turtlebot3_navigation's move_base.launch
    # (ns="global_costmap", a file named after $(arg model)); ~port is not there
    found = _ros1(write_tree, '<rosparam file="$(find pkg)/$(arg config).yaml" ns="gains" />')
    assert "parameter-set-not-read" not in found  # no phantom /talker/gains
    assert sorted(found["parameter-read-not-set"]) == [("parameter:/shared/frame",),
                                                        ("parameter:/talker/port",)]


SLASH_LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        return LaunchDescription([
            Node(package='talk', executable='talker',
                 parameters=[{'/port': 'ttyS0', 'gain': 2.0}]),
            Node(package='not_here', executable='other'),
        ])
    """


def test_ros2_a_parameter_named_with_a_leading_slash_is_its_nodes(write_tree: Any) -> None:
    # moveit2_tutorials 1968607: parameters=[{"/child_frame_id": ...}] on tf2_ros'
    # static transform node, which declares child_frame_id. launch_ros hands the
    # name as written, so the node gets the override /child_frame_id, declares another
    # name and never reads it. A ROS 2 parameter is its node's alone: the node of unknown
    # interface beside it (not_here/other) cannot be its reader, so the finding is
    # decided. The parameter's full name has two slashes, /talker//port, which the
    # search for its owner did not take for /talker's
    root = write_tree({
        "src/talk/package.xml": package_xml("talk", build_type="ament_python"),
        "src/talk/setup.py": "from setuptools import setup\n"
                             "setup(name='talk', packages=['talk'], entry_points="
                             "{'console_scripts': ['talker = talk.talker:main']})\n",
        "src/talk/resource/talk": "",
        "src/talk/talk/__init__.py": "",
        "src/talk/talk/talker.py": ROS2_NODE,
        "src/talk/launch/talk.launch.py": SLASH_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [talk/launch/talk.launch.py]\n",
    })
    found = _findings(root)
    assert ("parameter:/talker//port",) in found.get("parameter-set-not-read", [])
    assert "parameter-set-not-read" + UNDECIDED not in found
