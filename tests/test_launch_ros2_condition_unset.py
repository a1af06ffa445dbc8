"""``LaunchConfigurationEquals`` / ``NotEquals`` of a configuration nothing declares or
sets: launch compares it as unequal, with no error (its KeyError path), so the nodes
it guards silently never start. interbotix_xslocobot_nav (9ece3701^) starts its map
server, AMCL and lifecycle managers under ``LaunchConfigurationEquals(
'slam_toolbox_mode', ...)`` and declares ``slam_mode``: nothing said so. Now a warning,
LAUNCH_CONDITION_UNSET; where an action not seen may declare it, undecided."""

from __future__ import annotations

from typing import Any

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

HEADER = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import LaunchConfigurationEquals, LaunchConfigurationNotEquals
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('slam_mode', default_value='localization'),
%s
        Node(package='nav2_amcl', executable='amcl', name='amcl',
             condition=LaunchConfigurationEquals('slam_toolbox_mode', 'localization')),
        Node(package='nav2_map_server', executable='map_server', name='map_saver',
             condition=LaunchConfigurationNotEquals('slam_toolbox_mode', 'localization')),
        Node(package='slam_toolbox', executable='sync_slam_toolbox_node', name='slam',
             condition=LaunchConfigurationEquals('slam_mode', 'localization')),
    ])
"""


def _load(write_tree, before: str = "") -> Any:
    root = write_tree({"src/p/package.xml": package_xml("p", "ament_python"),
                       "src/p/launch/nav.launch.py": HEADER % before})
    return load(str(root / "src/p/launch/nav.launch.py"), scan([str(root / "src")], {}),
                {}, {})


def test_a_configuration_nothing_sets_is_unequal_and_said(write_tree) -> None:
    model = _load(write_tree)
    assert {n.name: n.conditions for n in model.nodes} == {"/map_saver": (), "/slam": ()}
    said = [d for d in model.diagnostics if d.code == "LAUNCH_CONDITION_UNSET"]
    assert len(said) == 2 and all("slam_toolbox_mode" in d.message for d in said)
    assert all(d.severity == "warning" and d.location.file == "p/launch/nav.launch.py"
               for d in said)


def test_an_action_not_seen_may_set_it(write_tree) -> None:
    model = _load(write_tree, "        IncludeLaunchDescription(PythonLaunchDescriptionSource("
                              "unknown_path())),")
    assert sorted(n.name for n in model.nodes) == ["/amcl", "/map_saver", "/slam"]
    assert all(n.conditions for n in model.nodes if n.name != "/slam")
    assert not [d for d in model.diagnostics if d.code == "LAUNCH_CONDITION_UNSET"]
    assert [d for d in model.diagnostics if d.code == "LAUNCH_UNKNOWN_VALUE"
            and "slam_toolbox_mode" in d.message]
