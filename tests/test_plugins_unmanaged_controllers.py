"""A ROS 2 spawner that loads controllers into a controller manager the configuration
does not start (elkapod_core's simulation: controllers.launch.py:84-99 spawns
elkapod_gait_controller with ``--param-file elkapod_motion_manager.yaml`` into the
manager of Gazebo's gz_ros2_control, started by elkapod_gazebo's launch file, not in
the repository). The controller runs all the same once that manager is up: it is a
node instance of its own, in the manager's namespace, with the spawner's files, as a
ROS 1 controller of a manager not seen is. Before, it was not in the graph at all, and
the ``/**`` entries of the file the spawner gives it beside the motion manager's node
were "set but never read" for the motion manager (13 warnings)."""

from __future__ import annotations

import os

from conftest import FIXTURES
from test_plugins_controller_overrides import LEADER, MOVER, MOVER_SETUP, PLUGINS_XML

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

PLUGINS = FIXTURES / "build" / "plugins"

SHARED_FILE = """/**:
  ros__parameters:
    gate: false
    speed: 2.0
    nobody: 1
/robot/leader:
  ros__parameters:
    type: ros2_ctrl/Leader
/robot/stranger:
  ros__parameters:
    type: elsewhere_pkg/Stranger
    depth: 3
"""

LAUNCH = """
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    shared = os.path.join(get_package_share_directory('ros2_bringup'), 'config',
                          'shared.yaml')
    return LaunchDescription([
        Node(package='mover_pkg', executable='mover', namespace='robot',
             parameters=[shared]),
        Node(package='controller_manager', executable='spawner', namespace='robot',
             arguments=[SPAWNED, '--param-file', shared]),
    ])
"""


def _tree(write_tree, spawned: str, manager: bool = False) -> str:
    files = {f"src/ros2_ctrl/{name}": (PLUGINS / "ros2_ctrl" / name).read_text()
             for name in ("CMakeLists.txt", "package.xml")}
    files["src/ros2_ctrl/ros2_ctrl.xml"] = PLUGINS_XML
    files["src/ros2_ctrl/src/follower.cpp"] = LEADER
    files.update({f"src/ros2_bringup/{name}": (PLUGINS / "ros2_bringup" / name).read_text()
                  for name in ("CMakeLists.txt", "package.xml")})
    files["src/ros2_bringup/params/shared.yaml"] = SHARED_FILE
    launch = LAUNCH.replace("SPAWNED", spawned)
    if manager:  # the guard: the configuration starts the manager itself
        launch = launch.replace(
            "        Node(package='controller_manager', executable='spawner'",
            "        Node(package='controller_manager', executable='ros2_control_node',\n"
            "             namespace='robot', parameters=[{'robot_description': '<robot/>'}]),"
            "\n        Node(package='controller_manager', executable='spawner'")
    files["src/ros2_bringup/launch/c.launch.py"] = launch
    files["src/mover_pkg/package.xml"] = (
        '<package format="3"><name>mover_pkg</name><version>0.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>MIT</license><exec_depend>rclpy</exec_depend>'
        '<export><build_type>ament_python</build_type></export></package>')
    files["src/mover_pkg/setup.py"] = MOVER_SETUP
    files["src/mover_pkg/mover_pkg/__init__.py"] = ""
    files["src/mover_pkg/mover_pkg/mover.py"] = MOVER
    files["project.yaml"] = ("project: p\ndistro: jazzy\nconfigurations:\n"
                             "  c: [ros2_bringup/launch/c.launch.py]\n")
    return write_tree(files)


def _analysed(root: str):
    model = analyse(load(os.path.join(root, "project.yaml")), {},
                    Options(cache_dir=None, jobs=1))
    return model, model.configuration("c")


def _unread(model) -> tuple[list[str], list[str]]:
    findings = run_catalogue(model)
    unread = sorted(f.message.split(" is set")[0] for f in findings
                    if f.rule == "parameter-set-not-read")
    undecided = [f.message for f in findings
                 if f.rule == "parameter-set-not-read-undecided"]
    return unread, undecided


def test_a_controller_of_a_manager_not_started_is_a_node_of_its_own(write_tree):
    model, config = _analysed(_tree(write_tree, "'leader'"))
    leader = next(n for n in config.nodes if n.name == "/robot/leader")
    assert leader.node is not None and leader.origin == "plugin"
    gate = config.parameter("/robot/leader/gate")
    assert gate is not None and [r.node.name for r in gate.readers] == ["/robot/leader"]
    unread, _ = _unread(model)
    # gate: the controller reads its copy; speed: the mover; nobody: neither reads it
    # (both interfaces are known), so it stays a finding
    assert unread == ["/robot/mover/nobody"]
    # the manager's own files, not seen, may give the controller more: a read of it is
    # never "read but not set" for that
    assert config.parameter("/robot/leader/?").set_by_launch


def test_a_controller_of_an_unknown_class_leaves_the_shared_setting_undecided(
        write_tree):
    model, config = _analysed(_tree(write_tree, "'stranger'"))
    stranger = next(n for n in config.nodes if n.name == "/robot/stranger")
    assert stranger.node is None  # its class is in no package here nor in a model
    assert any(d.code == "PLUGIN_NOT_FOUND" for d in config.diagnostics)
    unread, undecided = _unread(model)
    # gate and nobody may be read by the controller whose code is not known; speed is
    # the mover's; depth is its own parameter, set for an unknown interface
    assert unread == []
    assert undecided and "/robot/stranger" in undecided[0]


def test_a_controller_of_a_manager_started_here_is_that_managers(write_tree):
    model, config = _analysed(_tree(write_tree, "'leader'", manager=True))
    leaders = [n for n in config.nodes if n.name == "/robot/leader"]
    assert len(leaders) == 1 and config.parameter("/robot/leader/?") is None
    unread, _ = _unread(model)
    assert unread == ["/robot/mover/nobody"]
