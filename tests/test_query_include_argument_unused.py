"""A ROS 2 include that passes an argument the included file never declares nor reads
(nor any file it includes) has it ignored in silence: turtlebot3 448b4fa passed nav2's
bringup ``params`` where it declares ``params_file``, so the robot's parameter file was
never loaded. The launch stage records how each passed argument is used
(``LaunchArg.use``); launch-include-argument-unused reports the unused ones, and an
argument that a part of the included files not read may use is undecided."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from conftest import package_xml

from haros_arch.launch import load as load_launch
from haros_arch.model.launch_tree import include_args, item_from_data
from haros_arch.model.serialise import to_data
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.workspace import scan

HEAD = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription, OpaqueFunction
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
"""

BRINGUP = HEAD + """
def generate_launch_description():
    here = os.path.join(get_package_share_directory('nav'), 'launch')
    return LaunchDescription([
        DeclareLaunchArgument('params_file', default_value='/opt/nav.yaml'),
        DeclareLaunchArgument('map', default_value=''),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join(here, 'inner.launch.py'))),
        Node(package='nav', executable='planner', name='planner',
             parameters=[LaunchConfiguration('params_file')]),
    ])
"""

# read, never declared, two includes down; and read in an OpaqueFunction
INNER = HEAD + """
def late(context):
    if context.launch_configurations.get('rviz', 'false') == 'true':
        return [Node(package='nav', executable='rviz', name='rviz')]
    return []


def generate_launch_description():
    return LaunchDescription([
        Node(package='nav', executable='controller', name='controller',
             parameters=[{'use_sim_time': LaunchConfiguration('use_sim_time',
                                                              default='false')}]),
        OpaqueFunction(function=late),
    ])
"""

ROBOT = HEAD + """
def generate_launch_description():
    nav = os.path.join(get_package_share_directory('nav'), 'launch', 'bringup.launch.py')
    return LaunchDescription([
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(nav),
            launch_arguments={'map': '/maps/m.yaml', 'use_sim_time': 'true',
                              'rviz': 'true', 'params': '/bot/nav.yaml'}.items()),
    ])
"""

ROBOT_XML = """<launch>
  <include file="$(find-pkg-share nav)/launch/bringup.launch.py">
    <arg name="map" value="/maps/m.yaml"/>
    <arg name="params" value="/bot/nav.yaml"/>
  </include>
</launch>
"""


def _tree(write_tree: Any, inner: str = INNER, robot: str = ROBOT,
          name: str = "robot.launch.py") -> Path:
    return write_tree({
        "src/nav/package.xml": package_xml("nav", "ament_cmake"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/bringup.launch.py": BRINGUP,
        "src/nav/launch/inner.launch.py": inner,
        "src/bot/package.xml": package_xml("bot", "ament_cmake").replace(
                "<export>", "<exec_depend>nav</exec_depend><export>"),
        "src/bot/CMakeLists.txt": "project(bot)\n",
        f"src/bot/launch/{name}": robot,
        "project.yaml": f"project: p\ndistro: humble\nconfigurations:\n"
                        f"  robot: [bot/launch/{name}]\n",
    })


def _uses(root: Path, name: str = "robot.launch.py") -> dict[str, tuple[str, str]]:
    ws = scan([str(root / "src")], {})
    model = load_launch(str(root / "src/bot/launch" / name), ws, {}, {})
    return {a.name: (a.use, a.file) for a in include_args(model.tree)}


def _findings(root: Path) -> dict[str, list[Any]]:
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    found: dict[str, list[Any]] = {}
    for finding in run_catalogue(model, project):
        if finding.rule.startswith("launch-include-argument-unused"):
            found.setdefault(finding.rule, []).append(finding)
    return found


def test_each_passed_argument_is_declared_read_or_unused(write_tree: Any) -> None:
    uses = _uses(_tree(write_tree))
    bringup = "nav/launch/bringup.launch.py"
    assert uses == {"map": ("declared", bringup), "use_sim_time": ("read", bringup),
                    "rviz": ("read", bringup), "params": ("unused", bringup)}


def test_the_rule_reports_the_unused_argument_with_what_the_file_declares(
        write_tree: Any) -> None:
    found = _findings(_tree(write_tree))
    [finding] = found["launch-include-argument-unused"]
    assert finding.severity == "warning"
    assert finding.message == (
        "params:=/bot/nav.yaml is passed to the include of nav/launch/bringup.launch.py, "
        "which neither declares nor reads it, nor does any file it includes: ros2 launch "
        "ignores it (it declares params_file)")
    assert (finding.location.file, finding.location.line) == (
        "bot/launch/robot.launch.py", ROBOT.lstrip("\n").splitlines().index(
            "        IncludeLaunchDescription(") + 1)
    assert "launch-include-argument-unused-undecided" not in found


def test_the_xml_frontend_include_is_checked_too(write_tree: Any) -> None:
    root = _tree(write_tree, robot=ROBOT_XML, name="robot.launch.xml")
    assert _uses(root, "robot.launch.xml") == {
        "map": ("declared", "nav/launch/bringup.launch.py"),
        "params": ("unused", "nav/launch/bringup.launch.py")}


def test_a_part_not_read_makes_the_unused_undecided(write_tree: Any) -> None:
    # an include the reader cannot follow (its package is not here) may read anything
    inner = INNER.replace("        OpaqueFunction(function=late),\n", (
        "        OpaqueFunction(function=late),\n"
        "        IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(\n"
        "            get_package_share_directory('elsewhere'), 'x.launch.py'))),\n"))
    root = _tree(write_tree, inner=inner)
    assert _uses(root)["params"][0] == "unknown"
    assert _uses(root)["map"][0] == "declared"
    found = _findings(root)
    assert "launch-include-argument-unused" not in found
    [info] = found["launch-include-argument-unused-undecided"]
    assert info.severity == "info"
    assert info.message == (
        "1 possible finding(s) not reported (first: argument params of the include of "
        "nav/launch/bringup.launch.py at bot/launch/robot.launch.py:12:9): part of the "
        "included files was not read, and may read them: the include of ?/x.launch.py "
        "(nav/launch/inner.launch.py:21) (1)")


def test_a_launch_configuration_of_unknown_name_makes_it_undecided(
        write_tree: Any) -> None:
    inner = INNER.replace("LaunchConfiguration('use_sim_time',",
                          "LaunchConfiguration(os.environ['WHICH'],")
    uses = _uses(_tree(write_tree, inner=inner))
    assert uses["params"][0] == "unknown"
    assert uses["use_sim_time"][0] == "unknown"  # no longer read by name


def test_the_use_survives_a_saved_model(write_tree: Any) -> None:
    ws_root = _tree(write_tree)
    ws = scan([str(ws_root / "src")], {})
    model = load_launch(str(ws_root / "src/bot/launch/robot.launch.py"), ws, {}, {})
    again = [item_from_data(to_data(item)) for item in model.tree]
    assert {a.name: a.use for a in include_args(i for i in again if i is not None)} == {
        a.name: a.use for a in include_args(model.tree)}
    assert {a.use for a in include_args(model.tree)} == {"declared", "read", "unused"}


def test_an_argument_read_by_an_action_its_condition_skips_is_read(write_tree: Any) -> None:
    # webots_ros2_epuck's robot_tools_launch.py reads fill_map in its mapper's parameters,
    # the mapper under IfCondition(use_mapper), false by default: the includer's
    # fill_map:=True is used when the mapper runs, not ignored
    inner = HEAD + """
from launch.conditions import IfCondition

def generate_launch_description():
    return LaunchDescription([
        Node(package='nav', executable='mapper', name='mapper',
             parameters=[{'fill_map': LaunchConfiguration('rviz', default='true')}],
             condition=IfCondition(LaunchConfiguration('mapper', default='false'))),
    ])
"""
    uses = _uses(_tree(write_tree, inner=inner))
    assert uses["rviz"] == ("read", "nav/launch/bringup.launch.py")
    assert uses["params"] == ("unused", "nav/launch/bringup.launch.py")
