"""The controller manager a gz_ros2_control (ign_ros2_control) plugin starts, as
gz_ros2_control_plugin.cpp builds it: its ``<parameters>`` files are ``--params-file``
arguments of the process, so a section ``/**/controller_manager:`` (rosbot_ros 5b024d7,
rosbot_controller/config/diff_drive_controller.yaml) is the manager's, as rcl matches
it: its controllers' classes were not read (PLUGIN_CLASS_UNKNOWN) and the controllers
the launch file spawns had no interface (no /joint_states, no odometry). Its
``<ros><remapping>`` rules go to ``rclcpp::init``, rules of the whole process: rosbot's
``rosbot_base_controller/cmd_vel_unstamped:=cmd_vel`` makes the base controller
subscribe ``/cmd_vel``. ``controller_manager_prefix_node_name`` names the manager
``<prefix>_controller_manager``."""

from __future__ import annotations

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project
from tests.conftest import package_xml

URDF = """<?xml version="1.0"?>
<robot name="bot">
  <link name="base"/>
  <gazebo>
    <plugin filename="ign_ros2_control-system"
            name="ign_ros2_control::IgnitionROS2ControlPlugin">
      <parameters>$(find bot)/config/controllers.yaml</parameters>
      %s
      <ros>
        <remapping>base_controller/cmd_vel_unstamped:=cmd_vel</remapping>
      </ros>
    </plugin>
  </gazebo>
</robot>
"""

CONTROLLERS = """/**/%(manager)s:
  ros__parameters:
    update_rate: 20
    joint_state_broadcaster:
      type: joint_state_broadcaster/JointStateBroadcaster
    base_controller:
      type: diff_drive_controller/DiffDriveController

/**/base_controller:
  ros__parameters:
    wheel_separation: 0.19
    use_stamped_vel: false
"""

LAUNCH = """
from launch import LaunchDescription
from launch.substitutions import Command, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    share = FindPackageShare("bot")
    description = Command(["xacro ", PathJoinSubstitution([share, "urdf", "bot.urdf.xacro"])])
    return LaunchDescription([
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             parameters=[{"robot_description": description}]),
        Node(package="ros_gz_sim", executable="create",
             arguments=["-name", "bot", "-topic", "robot_description"]),
        Node(package="controller_manager", executable="spawner",
             arguments=["joint_state_broadcaster", "-c", "%(manager)s"]),
        Node(package="controller_manager", executable="spawner",
             arguments=["base_controller", "-c", "%(manager)s"]),
    ])
"""


def _config(write_tree, prefix: str | None):
    manager = f"{prefix}_controller_manager" if prefix else "controller_manager"
    element = (f"<controller_manager_prefix_node_name>{prefix}"
               "</controller_manager_prefix_node_name>") if prefix else ""
    root = write_tree({
        "bot/package.xml": package_xml("bot", "ament_cmake"),
        "bot/CMakeLists.txt": "project(bot)\nament_package()\n",
        "bot/urdf/bot.urdf.xacro": URDF % element,
        "bot/config/controllers.yaml": CONTROLLERS % {"manager": manager},
        "bot/launch/sim.launch.py": LAUNCH % {"manager": manager},
    })
    project = Project("bot", str(root / "project.yaml"), workspace=[str(root)],
                      configurations=[ConfigurationSpec("c", ["bot/launch/sim.launch.py"], {})],
                      distro="humble")
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    return config


def _topics(config, node: str) -> set[tuple[str, str]]:
    return {(link.kind, link.resource.name) for link in config.links
            if link.node.name == node and link.kind in ("publish", "subscribe")}


def test_the_manager_takes_wildcard_sections_and_the_plugin_s_remaps(write_tree) -> None:
    config = _config(write_tree, None)
    manager = config.node("/controller_manager")
    assert manager is not None and manager.origin == "description"
    assert not [d for d in config.diagnostics if d.code.startswith("PLUGIN_")]
    assert config.parameter("/controller_manager/update_rate").value == 20
    assert config.parameter("/base_controller/wheel_separation").value == 0.19
    assert ("publish", "/joint_states") in _topics(config, "/joint_state_broadcaster")
    base = _topics(config, "/base_controller")
    assert {("subscribe", "/cmd_vel"), ("publish", "/base_controller/odom")} <= base
    assert ("subscribe", "/base_controller/cmd_vel_unstamped") not in base


def test_the_manager_s_name_takes_the_prefix_element(write_tree) -> None:
    config = _config(write_tree, "arm")
    assert config.node("/controller_manager") is None
    manager = config.node("/arm_controller_manager")
    assert manager is not None and manager.origin == "description"
    assert not [d for d in config.diagnostics if d.code.startswith("PLUGIN_")]
    assert ("publish", "/joint_states") in _topics(config, "/joint_state_broadcaster")


def test_the_manager_serves_the_services_the_spawners_call(write_tree) -> None:
    """The plugin makes ``ControllerManager(resource_manager, executor, name, ns)``
    (gazebo_ros2_control_plugin.cpp, gz_ros2_control_plugin.cpp): the manager's services,
    which the spawners call, were no node's (the instance had no interface: unknown,
    so every spawner client was undecided). Now served by it, partial for the rest."""
    config = _config(write_tree, None)
    manager = config.node("/controller_manager")
    assert manager.node is not None and manager.node.completeness == "partial"
    served = {link.resource.name for link in config.links
              if link.node.name == "/controller_manager" and link.kind == "server"}
    assert {"/controller_manager/load_controller", "/controller_manager/switch_controller",
            "/controller_manager/list_controllers"} <= served
    called = {link.resource.name for link in config.links
              if link.node.name.startswith("/spawner") and link.kind == "client"}
    assert called and called <= served
