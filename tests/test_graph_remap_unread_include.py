"""A remap that reaches an include the launch stage could not read (its package is not
in the workspace nor installed) may be used by the nodes that file starts: it is not
reported as changing no name, but counted in remap-unused-undecided, which names the
include. autoware_mini (UT-ADL, f0a4c3e) writes ``<remap from="/radar_fc/vehicle_motion"
to="/localization/current_velocity"/>`` in lexus.launch before including
``$(find vehicle_platform)/launch/platform.launch`` (its comment: "remap to let
/radar_fc/vehicle_motion subscribe to /localization/current_velocity"): the radar
driver that subscribes it is in that file, and the remap was a warning against the three
nodes of the file's own group."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

NODE = """#!/usr/bin/env python
import rospy
from std_msgs.msg import String
rospy.init_node('panel')
pub = rospy.Publisher('engage', String, queue_size=1)
rospy.spin()
"""


def _findings(write_tree, remap: str, include: str):
    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\ncatkin_install_python(PROGRAMS "
                                    "nodes/panel.py DESTINATION bin)\n",
        "src/robot/nodes/panel.py": NODE,
        "src/robot/launch/car.launch": f"""
            <launch>
              {remap}
              {include}
              <group ns="vehicle">
                <node pkg="robot" type="panel.py" name="panel"/>
              </group>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [robot/launch/car.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    return [f for f in run_catalogue(model) if f.rule.startswith("remap-unused")]


REMAP = '<remap from="/radar_fc/vehicle_motion" to="/localization/current_velocity"/>'
UNREAD = '<include file="$(find vehicle_platform)/launch/platform.launch"/>'


def test_a_remap_an_unread_include_takes_is_undecided(write_tree) -> None:
    findings = _findings(write_tree, REMAP, UNREAD)
    assert [f.rule for f in findings] == ["remap-unused-undecided"]
    assert "platform.launch" in findings[0].message


def test_a_remap_after_the_include_or_without_one_is_reported(write_tree) -> None:
    # the include comes before the remap: roslaunch gives its nodes only the remaps
    # written before it
    findings = _findings(write_tree, UNREAD, REMAP)
    assert [f.rule for f in findings] == ["remap-unused"]
    findings = _findings(write_tree, REMAP, "")
    assert [f.rule for f in findings] == ["remap-unused"]


def test_a_relative_remap_reaches_only_an_include_above_its_namespace(write_tree) -> None:
    # the group's remap of a relative name resolves in /vehicle: an include in /other
    # starts no node whose name it may be
    remap = '<group ns="vehicle"><remap from="motion" to="/velocity"/></group>'
    include = ('<group ns="other"><remap from="motion" to="/velocity"/>'
               '<include file="$(find vehicle_platform)/launch/platform.launch"/></group>')
    findings = _findings(write_tree, remap.replace("</group>", "") + "<node pkg=\"robot\" "
                         "type=\"panel.py\" name=\"p2\"/></group>", include)
    assert [f.rule for f in findings] == ["remap-unused"]


ROS2_NODE = """import rclpy
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node('panel')
pub = node.create_publisher(String, 'engage', 10)
rclpy.spin(node)
"""

ROS2_LAUNCH = """
from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node, SetRemap
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    platform = IncludeLaunchDescription(PythonLaunchDescriptionSource(PathJoinSubstitution(
        [FindPackageShare('vehicle_platform'), 'launch', 'platform.launch.py'])))
    return LaunchDescription([GroupAction([
        SetRemap('/radar_fc/vehicle_motion', '/localization/current_velocity'),
        INCLUDE
        Node(package='robot', executable='panel', name='panel'),
    ])])
"""


def _ros2_findings(write_tree, include: str):
    root = write_tree({
        "src/robot/package.xml": package_xml("robot", build_type="ament_python"),
        "src/robot/setup.py": ("from setuptools import setup\nsetup(name='robot', "
                               "entry_points={'console_scripts': "
                               "['panel = robot.panel:main']})\n"),
        "src/robot/robot/__init__.py": "",
        "src/robot/robot/panel.py": ROS2_NODE,
        "src/robot/launch/car.launch.py": ROS2_LAUNCH.replace("INCLUDE", include),
        "project.yaml": "project: p\nconfigurations:\n  c: [robot/launch/car.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    return [f for f in run_catalogue(model) if f.rule.startswith("remap-unused")]


def test_a_ros2_set_remap_an_unread_include_takes_is_undecided(write_tree) -> None:
    # launch_ros gives a SetRemap to every node launched after it in its group, those
    # of an included file too
    findings = _ros2_findings(write_tree, "platform,")
    assert [f.rule for f in findings] == ["remap-unused-undecided"]
    assert "platform.launch.py" in findings[0].message
    findings = _ros2_findings(write_tree, "")
    assert [f.rule for f in findings] == ["remap-unused"]
