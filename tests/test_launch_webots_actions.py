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


def test_webots_actions_start_their_nodes(write_tree: Any) -> None:
    root = write_tree({
        "demo/package.xml": package_xml("demo", "ament_python").replace(
            "</package>", "<exec_depend>webots_ros2_driver</exec_depend></package>"),
        "demo/setup.py": (
            "from setuptools import setup\n"
            "setup(name='demo', packages=['demo'], entry_points={'console_scripts': "
            "['spawn = demo.spawn:main']})\n"),
        "demo/demo/__init__.py": "",
        "demo/demo/spawn.py": "def main():\n    pass\n",
        "demo/launch/robot_launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [demo/launch/robot_launch.py]\n"})
    analysis = analyse_path(str(root / "project.yaml"), Options(cache_dir=None, jobs=1))
    assert analysis.model is not None
    (config,) = analysis.model.configurations
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
