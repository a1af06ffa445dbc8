"""launch_ros' Dashing keywords (``node_executable``, ``node_name``, ``node_namespace``,
``node_plugin``): Foxy deprecated them and Galactic removed them, so from Galactic on a
``Node(node_executable=...)`` raises TypeError and the launch file does not load. They
were read as the newer keywords with nothing said (urg_node 369ee4d's urg_node_launch.py,
five years after the rename). Now read so and said: an error where the configuration's
ROS_DISTRO refuses them, a warning where it is Foxy's or not known, nothing for Dashing
and Eloquent."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.launch.ros2 import load
from haros_arch.workspace import scan

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', node_executable='talker', node_name='chatter'),
        Node(package='demo', executable='listener', name='listener'),
        ComposableNodeContainer(
            name='box', namespace='', package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(package='demo', node_plugin='demo::Relay',
                               node_name='relay')]),
    ])
"""


def run(write_tree, env):
    root = write_tree({"src/demo/package.xml": package_xml("demo", "ament_cmake"),
                       "src/demo/launch/main.launch.py": LAUNCH})
    ws = scan([str(root / "src")], env)
    return load(str(root / "src/demo/launch/main.launch.py"), ws, {}, env)


def said(model):
    return [(d.code, d.severity, d.location.line, d.message) for d in model.diagnostics
            if d.code.startswith("LAUNCH_DASHING")]



@pytest.mark.parametrize("distro", ["", "foxy"])
def test_a_warning_where_the_distribution_may_take_them(write_tree, distro):
    model = run(write_tree, {"ROS_DISTRO": distro} if distro else {})
    where = "Foxy" if distro else "not known (no ROS_DISTRO)"
    assert said(model) == [
        ("LAUNCH_DASHING_KEYWORD", "warning", 8,
         "Node is given node_executable= (now executable=), node_name= (now name=), "
         "keywords of Dashing's launch_ros that Foxy deprecated and Galactic removed: "
         "from Galactic on the launch file does not load (TypeError); the distribution "
         f"here is {where}; read as the newer keyword"),
        ("LAUNCH_DASHING_KEYWORD", "warning", 14,
         "ComposableNode is given node_plugin= (now plugin=), node_name= (now name=), "
         "keywords of Dashing's launch_ros that Foxy deprecated and Galactic removed: "
         "from Galactic on the launch file does not load (TypeError); the distribution "
         f"here is {where}; read as the newer keyword")]
    # read as Dashing to Foxy read them
    names = sorted(n.name for n in model.nodes)
    assert "/chatter" in names and "/listener" in names
    (talker,) = [n for n in model.nodes if n.name == "/chatter"]
    assert talker.executable == "talker"


@pytest.mark.parametrize("distro", ["galactic", "humble", "jazzy"])
def test_an_error_where_the_distribution_refuses_them(write_tree, distro):
    model = run(write_tree, {"ROS_DISTRO": distro})
    found = said(model)
    assert [(c, s, line) for c, s, line, _m in found] == [
        ("LAUNCH_DASHING_KEYWORD_REMOVED", "error", 8),
        ("LAUNCH_DASHING_KEYWORD_REMOVED", "error", 14)]
    assert found[0][3] == (
        "Node is given node_executable= (now executable=), node_name= (now name=), "
        f"keywords of Dashing's launch_ros that {distro.capitalize()}'s does not take: "
        "the launch file does not load there (TypeError: unexpected keyword argument); "
        "read as the newer keyword")


@pytest.mark.parametrize("distro", ["dashing", "eloquent"])
def test_nothing_where_they_are_the_api(write_tree, distro):
    assert said(run(write_tree, {"ROS_DISTRO": distro})) == []


CHOSEN_BY_RELEASE = """
import subprocess
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    p = subprocess.Popen("echo $ROS_DISTRO", stdout=subprocess.PIPE, shell=True)
    ros_version = p.communicate()[0]
    if ros_version == b'dashing\\n' or ros_version == b'eloquent\\n':
        driver = Node(package='demo', node_executable='talker', node_name='chatter')
    else:
        driver = Node(package='demo', executable='talker', name='chatter')
    return LaunchDescription([driver])
"""


def test_under_a_test_not_known_a_warning_that_names_it(write_tree):
    """lslidar's ROS 2 drivers choose the keywords by the output of `echo $ROS_DISTRO`:
    the Dashing ones are given only where that says dashing or eloquent. With
    ROS_DISTRO humble that is no launch file that does not load (12 errors on the
    driver's five launch files): a warning naming the test."""
    root = write_tree({"src/demo/package.xml": package_xml("demo", "ament_cmake"),
                       "src/demo/launch/main.launch.py": CHOSEN_BY_RELEASE})
    env = {"ROS_DISTRO": "humble"}
    ws = scan([str(root / "src")], env)
    model = load(str(root / "src/demo/launch/main.launch.py"), ws, {}, env)
    (found,) = said(model)
    assert found[:3] == ("LAUNCH_DASHING_KEYWORD", "warning", 10)
    assert ("the distribution here is Humble, and the call is made only where the Python "
            "test ros_version == b'dashing\\n' or ros_version == b'eloquent\\n' holds, not "
            "known statically, which may keep it from running there") in found[3]
