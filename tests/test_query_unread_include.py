"""An include the launch stage cannot read (its package is not in the workspace: tiago's
``$(find cartesian_impedance)/launch/cartesian_impedance.launch``, pointcloud_to_laserscan's
openni2_launch) may start nodes and set parameters we do not see: a topic nobody is seen
to publish, a shared parameter nobody is seen to read, is undecided (the info names the
include), not a finding. A private parameter of a node of known interface stays decided
when the launch sets it: no node of the include reads it."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import pytest
from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.project import load as load_project
from haros_arch.query import run_catalogue

NODE = """#!/usr/bin/env python
import rospy
from std_msgs.msg import String
rospy.init_node('scan')
rospy.Subscriber('points', String, lambda m: None)
rate = rospy.get_param('~rate', 1.0)
"""

LAUNCH = """<launch>
  INCLUDE
  <rosparam>gains: {p: 1.0}</rosparam>
  <node name="scan" pkg="conv" type="scan.py">
    <param name="rte" value="2.0"/>
  </node>
</launch>
"""


def _findings(write_tree: Any, include: str) -> dict[str, list[str]]:
    root: Path = write_tree({
        "src/conv/package.xml": package_xml("conv"),
        "src/conv/CMakeLists.txt": "project(conv)\n",
        "src/conv/scripts/scan.py": NODE,
        "src/conv/launch/a.launch": LAUNCH.replace("INCLUDE", include),
        "project.yaml": "project: p\nconfigurations:\n  c: [conv/launch/a.launch]\n",
    })
    os.chmod(root / "src/conv/scripts/scan.py", 0o755)
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    found: dict[str, list[str]] = {}
    for finding in run_catalogue(model, project):
        found.setdefault(finding.rule, []).append(finding.message)
    return found


def test_without_an_unread_include_the_absences_are_findings(write_tree: Any) -> None:
    found = _findings(write_tree, "")
    assert len(found.get("subscriber-without-publisher", [])) == 1
    assert len(found.get("parameter-set-not-read", [])) == 2  # /gains/p, /scan/rte


@pytest.mark.parametrize("include", [
    '<include file="$(find not_in_workspace)/launch/sensor.launch"/>',
    '<include file="$(arg driver_launch)"/>',
], ids=["absent-package", "file-not-known"])
def test_an_unread_include_leaves_them_undecided(write_tree: Any, include: str) -> None:
    launch_arg = '<arg name="driver_launch"/>\n  ' if "arg" in include else ""
    found = _findings(write_tree, launch_arg + include)
    assert "subscriber-without-publisher" not in found
    undecided = found["subscriber-without-publisher-undecided"]
    assert len(undecided) == 1 and "(not read)" in undecided[0]
    # the shared /gains/p: the include may read it; /scan/rte: scan's own, known
    assert [m.split(" ")[0] for m in found["parameter-set-not-read"]] == ["/scan/rte"]
    assert "/gains/p" in found["parameter-set-not-read-undecided"][0]


ROS2_NODE = """import rclpy
from std_msgs.msg import String


def main():
    rclpy.init()
    node = rclpy.create_node('scan')
    node.create_subscription(String, 'points', lambda m: None, 10)
"""

ROS2_LAUNCH = """from launch import LaunchDescription
from launch.actions import ExecuteProcess, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import EnvironmentVariable, LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare
from vendor_driver.launcher import Controller


def generate_launch_description():
    return LaunchDescription([
        INCLUDE,
        Node(package='conv', executable='scan', name='scan'),
    ])
"""


def _ros2_findings(write_tree: Any, include: str) -> dict[str, list[str]]:
    root: Path = write_tree({
        "src/conv/package.xml": package_xml("conv", "ament_python"),
        "src/conv/setup.py": "from setuptools import setup\nsetup(name='conv', "
                             "packages=['conv'], entry_points={'console_scripts': "
                             "['scan = conv.scan:main']})\n",
        "src/conv/conv/__init__.py": "",
        "src/conv/conv/scan.py": ROS2_NODE,
        "src/conv/launch/a.launch.py": ROS2_LAUNCH.replace("INCLUDE", include),
        "project.yaml": "project: p\nconfigurations:\n  c: [conv/launch/a.launch.py]\n",
    })
    project = load(str(root / "project.yaml"))
    environment = {"PATH": os.environ.get("PATH", ""), "HOME": str(root / "home")}
    model = analyse(project, environment, Options(cache_dir=None))
    found: dict[str, list[str]] = {}
    for finding in run_catalogue(model, project):
        found.setdefault(finding.rule, []).append(finding.message)
    return found


@pytest.mark.parametrize("include", [
    "Node(package='conv', executable='scan', name='other')",
    "IncludeLaunchDescription(PythonLaunchDescriptionSource(PathJoinSubstitution(["
    "FindPackageShare('not_in_workspace'), 'launch', 'sensor.launch.py'])))",
    "IncludeLaunchDescription(PythonLaunchDescriptionSource(["
    "LaunchConfiguration('lidar_dir'), '/lidar.launch.py']))",
    "ExecuteProcess(cmd=['ros2', 'launch', 'not_in_workspace', 'sensor.launch.py'])",
    "IncludeLaunchDescription(PythonLaunchDescriptionSource(["
    "EnvironmentVariable('HOME'), '/gen/sensor.launch.py']))",
    "Controller(robot='r1')",
], ids=["none", "absent-package", "file-not-known", "ros2-launch-absent-package",
        "outside-the-workspace", "action-not-interpreted"])
def test_a_ros2_unread_include_leaves_them_undecided(write_tree: Any, include: str) -> None:
    """turtlebot3_bringup's robot.launch.py includes its lidar driver's launch file from
    a package not installed here (``[lidar_pkg_dir, LDS_LAUNCH_FILE]``); webots_ros2's
    launch files start the simulated robot's driver through ``WebotsController(...)``, a
    class the interpreter does not run: ROS 2 kept no trace of an include it could not
    read nor of an action not known, so every absence was decided."""
    found = _ros2_findings(write_tree, include)
    if include.startswith("Node"):
        assert len(found.get("subscriber-without-publisher", [])) == 2
        return
    assert "subscriber-without-publisher" not in found
    undecided = found["subscriber-without-publisher-undecided"]
    said = "action not interpreted" if include.startswith("Controller") else "(not read)"
    assert len(undecided) == 1 and said in undecided[0]


ROS2_READER = ROS2_NODE.replace(
    "    node.create_subscription(String, 'points', lambda m: None, 10)\n",
    "    node.create_subscription(String, 'points', lambda m: None, 10)\n"
    "    node.declare_parameter('frame', rclpy.Parameter.Type.STRING)\n"
    "    frame = node.get_parameter('frame').value\n")


@pytest.mark.parametrize("after", [True, False], ids=["include-after", "include-before"])
def test_a_ros2_unread_include_sets_no_parameter_of_a_node_before_it(
        write_tree: Any, after: bool) -> None:
    """A ROS 2 parameter belongs to its node: a file included and not read can set it only
    through a ``SetParameter`` that reaches the nodes launched after the include (Autoware:
    one include of ``topic_state_monitor?.launch.xml``, a name not known, left 285 "read
    but never set" of every node undecided). Before the node, it may; after it, not."""
    include = ("IncludeLaunchDescription(PythonLaunchDescriptionSource(PathJoinSubstitution(["
               "FindPackageShare('not_in_workspace'), 'launch', 'sensor.launch.py'])))")
    launch = ROS2_LAUNCH.replace("        INCLUDE,\n", "") if after else ROS2_LAUNCH.replace(
        "INCLUDE", include)
    if after:
        launch = launch.replace("name='scan'),\n", f"name='scan'),\n        {include},\n")
    root: Path = write_tree({
        "src/conv/package.xml": package_xml("conv", "ament_python"),
        "src/conv/setup.py": "from setuptools import setup\nsetup(name='conv', "
                             "packages=['conv'], entry_points={'console_scripts': "
                             "['scan = conv.scan:main']})\n",
        "src/conv/conv/__init__.py": "",
        "src/conv/conv/scan.py": ROS2_READER,
        "src/conv/launch/a.launch.py": launch,
        "project.yaml": "project: p\nconfigurations:\n  c: [conv/launch/a.launch.py]\n",
    })
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    found = {f.rule: f.message for f in run_catalogue(model, project)}
    if after:
        assert found["parameter-read-not-set"].startswith("/scan/frame ")
    else:
        assert "parameter-read-not-set" not in found
        assert "(not read)" in found["parameter-read-not-set-undecided"]


@pytest.mark.parametrize(("tag", "undecided"), [
    ("<vendor_bridge bridge_name='b' config_file='c.yaml'/>", True),
    ("<vendor_bridge bridge_name='b' if='false'/>", False),
    ("", False),
], ids=["extension-tag", "extension-tag-off", "none"])
def test_a_ros2_xml_tag_of_a_launch_extension_leaves_them_undecided(
        write_tree: Any, tag: str, undecided: bool) -> None:
    """A package's Python can expose launch actions as XML tags (ros_gz's
    ``<ros_gz_bridge>``, which ``launch.ros2.package_actions`` knows; a vendor's that it
    does not): ros2 launch runs one (or fails without the package); an unknown one was
    dropped with a warning, so every absence beside it was decided."""
    launch = f"<launch>\n  {tag}\n  <node pkg='conv' exec='scan' name='scan'/>\n</launch>\n"
    root: Path = write_tree({
        "src/conv/package.xml": package_xml("conv", "ament_python"),
        "src/conv/setup.py": "from setuptools import setup\nsetup(name='conv', "
                             "packages=['conv'], entry_points={'console_scripts': "
                             "['scan = conv.scan:main']})\n",
        "src/conv/conv/__init__.py": "",
        "src/conv/conv/scan.py": ROS2_NODE,
        "src/conv/launch/a.launch.xml": launch,
        "project.yaml": "project: p\nconfigurations:\n  c: [conv/launch/a.launch.xml]\n",
    })
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    found: dict[str, list[str]] = {}
    for finding in run_catalogue(model, project):
        found.setdefault(finding.rule, []).append(finding.message)
    if undecided:
        assert "subscriber-without-publisher" not in found
        (said,) = found["subscriber-without-publisher-undecided"]
        assert "action not interpreted (<vendor_bridge>)" in said
    else:
        assert len(found["subscriber-without-publisher"]) == 1
    if tag:
        assert [d.code for d in model.configurations[0].diagnostics
                if d.code == "LAUNCH_UNKNOWN_TAG"] == ["LAUNCH_UNKNOWN_TAG"]


COMPONENT_LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    rectify = [ComposableNode(package='image_proc', plugin='image_proc::RectifyNode',
                              name='rectify', namespace='camera')]
    return LaunchDescription([
        LOAD,
        Node(package='conv', executable='scan', name='scan'),
    ])
"""


@pytest.mark.parametrize("load", [
    "ComposableNodeContainer(name='container', namespace='camera', "
    "package='rclcpp_components', executable='component_container', "
    "composable_node_descriptions=rectify)",
    "LoadComposableNodes(target_container='/camera/container', "
    "composable_node_descriptions=rectify)",
], ids=["container-here", "container-elsewhere"])
def test_components_loaded_into_a_container_started_elsewhere_leave_them_undecided(
        write_tree: Any, load: str) -> None:
    """clearpath_sensors' image_rectify.launch.py loads image_proc's RectifyNode into
    ``<namespace>/image_processing_container``, which the camera's launch file starts
    with the camera driver in it: the driver that publishes the image is not seen, and
    the subscriber-without-publisher warnings on the image were decided all the same."""
    root: Path = write_tree({
        "src/conv/package.xml": package_xml("conv", "ament_python"),
        "src/conv/setup.py": "from setuptools import setup\nsetup(name='conv', "
                             "packages=['conv'], entry_points={'console_scripts': "
                             "['scan = conv.scan:main']})\n",
        "src/conv/conv/__init__.py": "",
        "src/conv/conv/scan.py": ROS2_NODE,
        "src/conv/launch/a.launch.py": COMPONENT_LAUNCH.replace("LOAD", load),
        "project.yaml": "project: p\ndistro: jazzy\n"
                        "configurations:\n  c: [conv/launch/a.launch.py]\n",
    })
    project = load_project(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    found: dict[str, list[str]] = {}
    for finding in run_catalogue(model, project):
        found.setdefault(finding.rule, []).append(finding.message)
    codes = {d.code for c in model.configurations for d in c.diagnostics}
    if load.startswith("ComposableNodeContainer"):
        assert any(m.startswith("/scan subscribes to /points")
                   for m in found["subscriber-without-publisher"])
        assert "LAUNCH_CONTAINER_EXTERNAL" not in codes
        return
    assert "subscriber-without-publisher" not in found
    assert "LAUNCH_CONTAINER_EXTERNAL" in codes
    assert all("container /camera/container (started elsewhere)" in m
               for m in found["subscriber-without-publisher-undecided"])



@pytest.mark.parametrize("command", [
    "ExecuteProcess(cmd=['ros2', 'bag', 'play', LaunchConfiguration('bag_file')])",
    "ExecuteProcess(cmd=['sleep', '5'])",
    "ExecuteProcess(cmd=['MicroXRCEAgent', 'udp4', '-p', '8888'])",
    "ExecuteProcess(cmd=[['micro-ros-agent udp4 --port 8888 -v ']], shell=True)",
    "ExecuteProcess(cmd=['xterm', '-e', 'ros2', 'bag', 'play'])",
    "ExecuteProcess(cmd=['gnome-terminal -- bash -c \"MicroXRCEAgent udp4 -p 8888\"'], "
    "shell=True)",
], ids=["ros2-bag-play", "no-ros-tool", "xrce-agent", "micro-ros-agent-shell",
        "bag-play-in-xterm", "xrce-agent-in-a-terminal-shell"])
def test_a_ros2_command_not_interpreted_may_be_the_missing_side(
        write_tree: Any, command: str) -> None:
    """ouster's replay launch plays a bag, ``ros2 bag play $(var bag_file) --clock``: the
    player publishes what was recorded, which is not seen, so the point cloud node's
    subscriptions are undecided, not "nothing publishes". A command that is no ROS tool
    leaves them decided. PX4's ROS 2 launch files start the micro XRCE-DDS agent so,
    which publishes the flight controller's topics: what the agent bridges is not seen
    either. So in a terminal or a shell the process opens (cabot-navigation's
    ``ExecuteProcess(cmd=['xterm', '-e', 'ros2', 'bag', 'play'])``: ``shell_run``)."""
    found = _ros2_findings(write_tree, command)
    if "sleep" in command:
        assert len(found.get("subscriber-without-publisher", [])) == 1
        return
    assert "subscriber-without-publisher" not in found
    undecided = found["subscriber-without-publisher-undecided"]
    process = ("process ros2 bag play" if "bag" in command
               else "process MicroXRCEAgent udp4 -p" if "MicroXRCEAgent" in command
               else "process micro-ros-agent udp4 --port")
    assert len(undecided) == 1 and process in undecided[0], undecided


@pytest.mark.parametrize(("command", "process"), [
    ("ExecuteProcess(cmd=['gazebo', '--verbose', '-s', 'libgazebo_ros_init.so', "
     "'-s', 'libgazebo_ros_factory.so', 'empty.world'])",
     "gazebo -s libgazebo_ros_init.so -s libgazebo_ros_factory.so"),
    ("ExecuteProcess(cmd=['/usr/bin/gzserver', '--server-plugin=libgazebo_ros_factory.so'])",
     "gzserver -s libgazebo_ros_factory.so"),
    ("ExecuteProcess(cmd=['gazebo -s libgazebo_ros_factory.so'], shell=True)",
     "gazebo -s libgazebo_ros_factory.so"),
    ("ExecuteProcess(cmd=['gazebo', '--verbose', 'empty.world'])", None),
], ids=["gazebo-ros-plugins", "gzserver-option", "shell-line", "gazebo-alone"])
def test_gazebo_with_gazebo_ros_system_plugins_may_be_the_missing_side(
        write_tree: Any, command: str, process: str | None) -> None:
    """tello_ros d961961's simple_launch.py runs ``gazebo --verbose -s
    libgazebo_ros_init.so -s libgazebo_ros_factory.so world`` as a process: the factory
    plugin serves ``/spawn_entity``, which its inject_entity.py calls, and the drone it
    spawns loads a plugin serving ``/drone1/tello_action``. Neither is read here, so the
    absences they may fill are undecided; a Gazebo given no gazebo_ros plugin starts no
    ROS node of its own."""
    found = _ros2_findings(write_tree, command)
    if process is None:
        assert len(found.get("subscriber-without-publisher", [])) == 1
        return
    assert "subscriber-without-publisher" not in found
    undecided = found["subscriber-without-publisher-undecided"]
    assert len(undecided) == 1 and f"process {process} (" in undecided[0]
