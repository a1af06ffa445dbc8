"""``ros_gz_sim create -string <description>``: the description is the text of the
argument, in a Python launch file usually the output of a xacro ``Command``
(Universal_Robots_ROS2_GZ_Simulation's ur_sim_control.launch.py:157). It was not read
(ROBOT_DESCRIPTION_UNKNOWN, "-database, -stdin"), so the controller manager its
gz_ros2_control plugin starts, and the controllers the launch file spawns into it, were
missing from the graph."""

from __future__ import annotations

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project
from tests.conftest import package_xml

URDF = """<?xml version="1.0"?>
<robot name="bot" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="controllers" default=""/>
  <link name="base"/>
  <gazebo>
    <plugin filename="gz_ros2_control-system"
            name="gz_ros2_control::GazeboSimROS2ControlPlugin">
      <parameters>$(arg controllers)</parameters>
    </plugin>
  </gazebo>
</robot>
"""

CONTROLLERS = """controller_manager:
  ros__parameters:
    update_rate: 100
    joint_state_broadcaster:
      type: joint_state_broadcaster/JointStateBroadcaster
"""

LAUNCH = """
from launch import LaunchDescription
from launch.substitutions import Command, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    share = FindPackageShare("bot")
    description = Command([
        "xacro ", PathJoinSubstitution([share, "urdf", "bot.urdf.xacro"]),
        " controllers:=", PathJoinSubstitution([share, "config", "controllers.yaml"])])
    return LaunchDescription([
        Node(package="ros_gz_sim", executable="create",
             arguments=["-name", "bot", %s, "-allow_renaming", "true"]),
        Node(package="controller_manager", executable="spawner",
             arguments=["joint_state_broadcaster"]),
    ])
"""


def _config(write_tree, string: str):
    root = write_tree({
        "bot/package.xml": package_xml("bot", "ament_cmake"),
        "bot/CMakeLists.txt": "project(bot)\nament_package()\n",
        "bot/urdf/bot.urdf.xacro": URDF,
        "bot/config/controllers.yaml": CONTROLLERS,
        "bot/launch/sim.launch.py": LAUNCH % string,
    })
    project = Project("bot", str(root / "project.yaml"), workspace=[str(root)],
                      configurations=[ConfigurationSpec("c", ["bot/launch/sim.launch.py"], {})],
                      distro="jazzy")
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    return config


def test_a_description_given_as_the_output_of_a_xacro_command(write_tree) -> None:
    config = _config(write_tree, '"-string", description')
    assert not [d for d in config.diagnostics if d.code == "ROBOT_DESCRIPTION_UNKNOWN"]
    (described,) = config.robot_descriptions
    assert described.file == "bot/urdf/bot.urdf.xacro"
    manager = config.node("/controller_manager")
    assert manager is not None and manager.origin == "description"
    broadcaster = config.node("/joint_state_broadcaster")
    assert broadcaster is not None and broadcaster.origin == "plugin"
    update = config.parameter("/controller_manager/update_rate")
    assert update is not None and update.value == 100


def test_a_string_not_known_says_so(write_tree) -> None:
    config = _config(write_tree, '"-string", open("/tmp/bot.urdf").read()')
    (said,) = [d.message for d in config.diagnostics if d.code == "ROBOT_DESCRIPTION_UNKNOWN"]
    assert "-string" in said
    assert config.node("/controller_manager") is None
