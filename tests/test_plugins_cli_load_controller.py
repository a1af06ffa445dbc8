"""A Python launch file's ``ExecuteProcess(cmd=['ros2', 'control', 'load_controller',
...])`` loads a controller into the controller manager as a spawner does: the controller
is a node of the manager's process, with the parameters of the file the command gives,
and the command's DirectNode calls the manager's services. It was a process the reader
could not name (``LAUNCH_PROCESS``), and the controller was not there. ``ros2 run
controller_manager spawner ...`` as an ExecuteProcess is that spawner."""

from __future__ import annotations

import os
import shutil

from conftest import FIXTURES

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project

LAUNCH = """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import ExecuteProcess
from launch_ros.actions import Node

def generate_launch_description():
    params = os.path.join(get_package_share_directory('ros2_bringup'), 'params',
                          'controllers.yaml')
    return LaunchDescription([
        Node(package='controller_manager', executable='ros2_control_node',
             namespace='robot', parameters=[{'follower.type': 'ros2_ctrl/Follower'}]),
        ExecuteProcess(cmd=[%s]),
    ])
"""


def _configuration(tmp_path, cmd: str):
    root = tmp_path / "plugins"
    shutil.copytree(FIXTURES / "build" / "plugins", root)
    (root / "ros2_bringup" / "launch" / "cli.launch.py").write_text(LAUNCH % cmd)
    project = Project("plugins", os.path.join(root, "project.yaml"), workspace=[str(root)],
                      configurations=[ConfigurationSpec(
                          "c", ["ros2_bringup/launch/cli.launch.py"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    return model.configurations[0]


def test_ros2_control_load_controller_loads_the_controller_with_its_file(tmp_path):
    config = _configuration(tmp_path, (
        "'ros2', 'control', 'load_controller', '--set-state', 'active', 'follower', "
        "params, '-c', '/robot/controller_manager'"))
    follower = config.node("/robot/follower")
    assert follower is not None and follower.origin == "plugin"
    assert follower.node.name == "ros2_ctrl/ros2_ctrl/Follower"
    gain = next(p for p in config.parameters if p.name == "/robot/follower/gain")
    assert gain.value == 2.0 and gain.is_read
    assert "LAUNCH_PROCESS" not in [d.code for d in config.diagnostics]
    (cli,) = [n for n in config.nodes if n.node and n.node.package == "ros2controlcli"]
    assert sorted(link.resource.name for link in cli.links) == [
        "/robot/controller_manager/configure_controller",
        "/robot/controller_manager/list_controllers",
        "/robot/controller_manager/load_controller",
        "/robot/controller_manager/set_parameters",
        "/robot/controller_manager/switch_controller"]


def test_a_load_without_a_state_or_file_only_loads(tmp_path):
    config = _configuration(tmp_path, (
        "'ros2', 'control', 'load_controller', 'follower', '-c', '/robot/controller_manager'"))
    assert config.node("/robot/follower") is not None
    (cli,) = [n for n in config.nodes if n.node and n.node.package == "ros2controlcli"]
    assert sorted(link.resource.name.rsplit("/", 1)[-1] for link in cli.links) == [
        "list_controllers", "load_controller"]


def test_ros2_run_spawner_as_a_process_is_the_spawner(tmp_path):
    config = _configuration(tmp_path, (
        "'ros2', 'run', 'controller_manager', 'spawner', 'follower', "
        "'-c', '/robot/controller_manager', '--param-file', params"))
    assert config.node("/robot/follower") is not None
