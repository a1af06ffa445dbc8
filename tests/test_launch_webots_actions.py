"""webots_ros2_driver's launch actions (webots_ros2 f442d2f7's robot launch files):
``WebotsController`` runs the package's ``driver`` for a robot, a node named after the
robot; ``WebotsLauncher(ros2_supervisor=True)`` starts the simulator (no ROS node) and its
``_supervisor`` is the ``Ros2Supervisor`` node the file adds; ``WaitForControllerConnection``
starts its ``nodes_to_start`` once the driver connects. They were calls not interpreted:
the driver, the supervisor and every node started after the connection (the controller
spawners) were missing from the graph."""

from __future__ import annotations

from typing import Any

from conftest import package_xml

from haros_arch.api import analyse_path
from haros_arch.pipeline import Options

LAUNCH = """
import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from ament_index_python.packages import get_package_share_directory
from webots_ros2_driver.webots_launcher import WebotsLauncher
from webots_ros2_driver.webots_controller import WebotsController
from webots_ros2_driver.wait_for_controller_connection import WaitForControllerConnection


def generate_launch_description():
    package_dir = get_package_share_directory('demo')
    webots = WebotsLauncher(world=os.path.join(package_dir, 'worlds', 'arena.wbt'),
                            ros2_supervisor=True)
    driver = WebotsController(
        robot_name='My robot',
        namespace='r1',
        parameters=[{'robot_description': os.path.join(package_dir, 'robot.urdf'),
                     'use_sim_time': True}],
        remappings=[('/diffdrive_controller/cmd_vel', '/cmd_vel')],
        respawn=True)
    arm = WebotsController(robot_name='arm', condition=IfCondition(LaunchConfiguration('arm')))
    spawner = Node(package='demo', executable='spawn', name='spawn')
    waiting = WaitForControllerConnection(target_driver=driver, nodes_to_start=[spawner])
    return LaunchDescription([
        DeclareLaunchArgument('arm', default_value='false'),
        webots, webots._supervisor, driver, arm, waiting])
"""


SPAWN_SETUP = ("from setuptools import setup\n"
               "setup(name='demo', packages=['demo'], entry_points={'console_scripts': "
               "['spawn = demo.spawn:main']})\n")


def _configuration(write_tree: Any, launch: str, files: dict[str, str] | None = None,
                   distro: str | None = None) -> Any:
    """The one configuration of a package ``demo`` (ament_python, depending on
    webots_ros2_driver, with a ``spawn`` entry point unless ``files`` gives another
    setup.py) whose launch file is ``launch``."""
    root = write_tree({
        "demo/package.xml": package_xml("demo", "ament_python").replace(
            "</package>", "<exec_depend>webots_ros2_driver</exec_depend></package>"),
        "demo/setup.py": SPAWN_SETUP,
        "demo/demo/__init__.py": "",
        "demo/demo/spawn.py": "def main():\n    pass\n",
        "demo/launch/robot_launch.py": launch,
        "project.yaml": "project: p\n" + (f"distro: {distro}\n" if distro else "")
                        + "configurations:\n  c: [demo/launch/robot_launch.py]\n",
        **(files or {})})
    analysis = analyse_path(str(root / "project.yaml"), Options(cache_dir=None, jobs=1))
    assert analysis.model is not None
    (config,) = analysis.model.configurations
    return config


def test_webots_actions_start_their_nodes(write_tree: Any) -> None:
    config = _configuration(write_tree, LAUNCH)
    nodes = {instance.name: instance for instance in config.nodes}
    assert not any(d.code == "LAUNCH_PY_UNSUPPORTED" for d in config.diagnostics), [
        d.message for d in config.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    # the driver: named after the robot, `` `` made ``_`` as Driver.cpp does
    driver = nodes["/r1/My_robot"]
    assert driver.remaps == [("/diffdrive_controller/cmd_vel", "/cmd_vel")]
    unknown = [d.message for d in config.diagnostics if d.code == "NODE_PACKAGE_UNKNOWN"]
    assert any("webots_ros2_driver/driver " in message for message in unknown), unknown
    assert {p.name for p in config.parameters if p.name.startswith("/r1/My_robot/")} >= {
        "/r1/My_robot/robot_description", "/r1/My_robot/use_sim_time"}
    # under the action's condition: not started with the default
    assert "/arm" not in nodes
    # the supervisor the launcher makes for the file to add
    assert "/Ros2Supervisor/Ros2Supervisor" in nodes, sorted(nodes)
    assert not any(d.code == "NODE_NAME_GUESSED" for d in config.diagnostics)
    # started once the driver connects: an event's condition
    spawn = nodes["/spawn"]
    assert [c.statement for c in spawn.conditions] == ["event"]


CONTROL_LAUNCH = """
import os
from launch import LaunchDescription
from launch_ros.actions import Node
from ament_index_python.packages import get_package_share_directory
from webots_ros2_driver.webots_controller import WebotsController
from webots_ros2_driver.wait_for_controller_connection import WaitForControllerConnection


def generate_launch_description():
    package_dir = get_package_share_directory('demo')
    driver = WebotsController(
        robot_name='bot',
        namespace='r1',
        parameters=[{'robot_description': os.path.join(package_dir, 'resource', 'bot.urdf')},
                    os.path.join(package_dir, 'resource', 'control.yaml')],
        remappings=[('diffdrive_controller/odom', 'odom')])
    spawners = [Node(package='controller_manager', executable='spawner',
                     arguments=[name, '-c', 'r1/controller_manager'])
                for name in ('diffdrive_controller', 'joint_state_broadcaster')]
    waiting = WaitForControllerConnection(target_driver=driver, nodes_to_start=spawners)
    return LaunchDescription([driver, waiting])
"""
BOT = """<?xml version="1.0"?>
<robot name="bot">
  <link name="base_link"/>
  <webots>
    <plugin type="webots_ros2_control::Ros2Control"/>
  </webots>
  <ros2_control name="WebotsControl" type="system">
    <hardware><plugin>webots_ros2_control::Ros2ControlSystem</plugin></hardware>
    <joint name="left_wheel_joint"><command_interface name="velocity"/></joint>
  </ros2_control>
</robot>
"""
CONTROL = """r1/controller_manager:
  ros__parameters:
    update_rate: 50
    diffdrive_controller:
      type: diff_drive_controller/DiffDriveController
    joint_state_broadcaster:
      type: joint_state_broadcaster/JointStateBroadcaster
r1/diffdrive_controller:
  ros__parameters:
    left_wheel_names: ["left_wheel_joint"]
"""


def test_a_webots_driver_runs_the_controller_manager_its_description_loads(
        write_tree: Any) -> None:
    """A robot description whose ``<webots>`` loads webots_ros2_control's
    ``Ros2Control`` makes the driver's process run a controller manager,
    ``<namespace>/controller_manager``, with the process's parameter files and remapping
    rules (webots_ros2's TurtleBot3, e-puck, TIAGo, ROSbot and UR5e). There was none: the
    spawners' clients had no server (seven client-without-server-undecided on
    webots_ros2 f442d2f7) and no controller, so no /odom, /joint_states or cmd_vel."""
    config = _configuration(write_tree, CONTROL_LAUNCH, {
        "demo/setup.py": (
            "import os\nfrom glob import glob\nfrom setuptools import setup\n"
            "setup(name='demo', packages=['demo'], data_files=["
            "(os.path.join('share', 'demo', 'resource'), glob('resource/*'))])\n"),
        "demo/resource/bot.urdf": BOT,
        "demo/resource/control.yaml": CONTROL}, distro="jazzy")
    nodes = {instance.name: instance for instance in config.nodes}
    manager = nodes["/r1/controller_manager"]
    assert manager.completeness == "partial"
    served = {link.resource.name for link in config.links
              if link.node is manager and link.kind == "server"}
    assert "/r1/controller_manager/load_controller" in served
    links = {(link.node.name, link.kind, link.resource.name) for link in config.links}
    asked = {name for _, kind, name in links if kind == "client"
             and name.startswith("/r1/controller_manager/")}
    assert asked and asked <= served, asked - served
    # the process's remapping rule reaches the controller it loads
    assert ("/r1/diffdrive_controller", "publish", "/r1/odom") in links
    assert ("/r1/joint_state_broadcaster", "publish", "/r1/joint_states") in links
    # the manager's own entry of the process's file
    update = next(p for p in config.parameters if p.name == "/r1/controller_manager/update_rate")
    assert update.value == 50


HANDLER_LAUNCH = """
import launch
from launch import LaunchDescription
from launch.actions import ExecuteProcess
from launch_ros.actions import Node


def started_again():
    return [Node(package='demo', executable='spawn', name='again')]


def driver_when_spawned(event, driver):
    if 'success=True' in event.text.decode():
        return driver
    return None


def generate_launch_description():
    spawner = ExecuteProcess(cmd=['ros2', 'service', 'call', '/spawn'])
    driver = Node(package='demo', executable='spawn', name='driver')
    return LaunchDescription([
        spawner,
        launch.actions.RegisterEventHandler(event_handler=launch.event_handlers.OnProcessIO(
            target_action=spawner,
            on_stdout=lambda event: driver_when_spawned(event, driver))),
        launch.actions.RegisterEventHandler(event_handler=launch.event_handlers.OnProcessExit(
            target_action=spawner, on_exit=started_again)),
    ])
"""


def test_an_output_handler_s_callable_starts_what_it_returns(write_tree: Any) -> None:
    """webots_ros2's URDF robots start their driver from an ``OnProcessIO`` handler,
    ``on_stdout=lambda event: get_webots_driver_node(event, driver)``: the callable was
    not called, so the driver (and the controller manager its description loads) was
    missing. It is called with the event, not known here, and what it may return runs
    under the event. A callable run on a process's exit is not: there it starts again
    what the file started (webots_ros2_husarion's reset handler)."""
    config = _configuration(write_tree, HANDLER_LAUNCH)
    nodes = {instance.name: instance for instance in config.nodes}
    assert "/again" not in nodes
    driver = nodes["/driver"]
    assert [c.statement for c in driver.conditions] == ["event"]
    said = [d.message for d in config.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert any("OnProcessExit with a callable" in message for message in said), said
