"""The launch tree (ROS 1 and ROS 2): includes with their arguments, groups, remaps,
conditions and the nodes with their final names."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from haros_arch.cli import main
from haros_arch.launch import load
from haros_arch.model.launch_tree import LaunchArg, LaunchItem, item_from_data
from haros_arch.model.load import from_data
from haros_arch.model.location import Location
from haros_arch.model.model import Model
from haros_arch.model.runtime import Configuration
from haros_arch.model.serialise import model_to_data, to_data
from haros_arch.workspace import scan

PACKAGE = """<package format="2"><name>pkg</name><version>0.0.0</version>
<description>x</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>
<buildtool_depend>catkin</buildtool_depend></package>"""

MAIN = """<launch>
  <arg name="robot" default="r1"/>
  <arg name="sim" default="false"/>
  <arg name="mode"/>
  <remap from="scan" to="base_scan"/>
  <param name="rate" value="10"/>
  <include file="$(find pkg)/launch/sub.launch" ns="$(arg robot)">
    <arg name="use_cam" value="true"/>
  </include>
  <group ns="sensors">
    <remap from="image" to="cam/image"/>
    <node pkg="pkg" type="cam" name="camera" if="$(arg sim)"/>
    <node pkg="pkg" type="laser" name="laser" unless="$(arg sim)">
      <param name="frame" value="laser_link"/>
    </node>
  </group>
  <group if="$(arg mode)">
    <node pkg="pkg" type="m" name="moder"/>
  </group>
  <node pkg="pkg" type="t" name="talker"/>
</launch>
"""

SUB = """<launch>
  <arg name="use_cam" default="false"/>
  <arg name="rate" default="5"/>
  <node pkg="pkg" type="drv" name="driver" if="$(arg use_cam)"/>
</launch>
"""


def shape(item: LaunchItem) -> Any:
    """The tree as nested tuples: what each item is, says and contains."""
    cond = item.condition
    return (item.kind, item.name, item.location.line, item.namespace, item.detail,
            None if cond is None else (cond.statement, cond.text, cond.values, cond.holds),
            item.skipped, [(a.name, a.value, a.origin, a.location.line) for a in item.args],
            item.remaps, item.params, [shape(child) for child in item.children])


def tree(tmp_path: Path, args: dict[str, str]) -> LaunchItem:
    """The ROS 1 fixture's tree."""
    (tmp_path / "pkg" / "launch").mkdir(parents=True)
    (tmp_path / "pkg" / "package.xml").write_text(PACKAGE)
    (tmp_path / "pkg" / "launch" / "main.launch").write_text(MAIN)
    (tmp_path / "pkg" / "launch" / "sub.launch").write_text(SUB)
    workspace = scan([str(tmp_path)], {})
    model = load(str(tmp_path / "pkg/launch/main.launch"), workspace, args, {})
    assert len(model.tree) == 1
    return model.tree[0]


def test_ros1_tree_keeps_includes_arguments_groups_and_conditions(tmp_path: Path) -> None:
    root = tree(tmp_path, {"mode": "true"})
    remap = [("scan", "base_scan")]
    assert shape(root) == (
        "file", "pkg/launch/main.launch", 0, "/", "", None, False,
        [("mode", "true", "command line", 0), ("robot", "r1", "default", 2),
         ("sim", "false", "default", 3)],
        remap, ["/rate"], [
            ("file", "pkg/launch/sub.launch", 7, "/r1/", "", None, False,
             [("use_cam", "true", "include", 8), ("rate", "5", "default", 3)], [], [], [
                 ("node", "/r1/driver", 4, "/r1/", "pkg/drv",
                  ("if", "$(arg use_cam)", {"use_cam": "true"}, True), False, [], remap,
                  [], [])]),
            ("group", "/sensors/", 10, "/sensors/", "", None, False, [],
             [("image", "cam/image")], [], [
                 ("node", "camera", 12, "", "pkg/cam",
                  ("if", "$(arg sim)", {"sim": "false"}, False), True, [], [], [], []),
                 ("node", "/sensors/laser", 13, "/sensors/", "pkg/laser",
                  ("unless", "$(arg sim)", {"sim": "false"}, True), False, [],
                  [*remap, ("image", "cam/image")], ["/sensors/laser/frame"], [])]),
            ("group", "", 17, "/", "", ("if", "$(arg mode)", {"mode": "true"}, True), False,
             [], [], [], [("node", "/moder", 18, "/", "pkg/m", None, False, [], remap, [],
                           [])]),
            ("node", "/talker", 20, "/", "pkg/t", None, False, [], remap, [], [])])


def test_ros1_tree_undecided_condition_keeps_the_part_with_unknown_value(
        tmp_path: Path) -> None:
    root = tree(tmp_path, {})
    group = root.children[2]
    assert group.kind == "group" and not group.skipped
    assert group.condition is not None and group.condition.holds is None
    assert group.condition.values == {"mode": None}
    assert [c.name for c in group.children] == ["/moder"]
    assert root.arg("mode") is not None and root.arg("mode").origin == "unset"  # type: ignore[union-attr]


def test_ros1_skipped_group_names_what_it_would_start(tmp_path: Path) -> None:
    root = tree(tmp_path, {"mode": "false"})
    group = root.children[2]
    assert group.skipped and group.condition is not None and group.condition.holds is False
    assert [(c.kind, c.name, c.detail, c.skipped) for c in group.children] == [
        ("node", "moder", "pkg/m", True)]


def test_tree_round_trips_through_json(tmp_path: Path) -> None:
    root = tree(tmp_path, {"mode": "true"})
    again = item_from_data(to_data(root))
    assert again is not None and shape(again) == shape(root)


PACKAGE2 = """<package format="3"><name>pkg2</name><version>0.0.0</version>
<description>x</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>
<buildtool_depend>ament_cmake</buildtool_depend>
<export><build_type>ament_cmake</build_type></export></package>"""

BRINGUP = """import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace, SetRemap


def generate_launch_description():
    here = os.path.dirname(__file__)
    use_sim = LaunchConfiguration('use_sim')
    return LaunchDescription([
        DeclareLaunchArgument('use_sim', default_value='false'),
        DeclareLaunchArgument('robot', default_value='r1'),
        GroupAction([
            PushRosNamespace(LaunchConfiguration('robot')),
            SetRemap(src='scan', dst='base_scan'),
            Node(package='pkg2', executable='drv', name='driver'),
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(os.path.join(here, 'sim.launch.py')),
                launch_arguments={'world': 'empty'}.items(),
                condition=IfCondition(use_sim)),
        ]),
        Node(package='pkg2', executable='viz', name='viz', condition=IfCondition(use_sim)),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(here, 'sim.launch.py')),
            launch_arguments={'world': 'house'}.items()),
    ])
"""

SIM = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('world', default_value='default'),
        DeclareLaunchArgument('gui', default_value='true'),
        Node(package='pkg2', executable='sim', name='sim',
             parameters=[{'world': LaunchConfiguration('world')}]),
    ])
"""


def tree2(tmp_path: Path, args: dict[str, str]) -> LaunchItem:
    """The ROS 2 fixture's tree."""
    folder = tmp_path / "pkg2" / "launch"
    folder.mkdir(parents=True, exist_ok=True)
    (tmp_path / "pkg2" / "package.xml").write_text(PACKAGE2)
    (folder / "bringup.launch.py").write_text(BRINGUP)
    (folder / "sim.launch.py").write_text(SIM)
    workspace = scan([str(tmp_path)], {})
    model = load(str(folder / "bringup.launch.py"), workspace, args, {})
    assert len(model.tree) == 1
    return model.tree[0]


def test_ros2_tree_with_sim_on(tmp_path: Path) -> None:
    remap = [("scan", "base_scan")]
    sim = ("file", "pkg2/launch/sim.launch.py")
    assert shape(tree2(tmp_path, {"use_sim": "true"})) == (
        "file", "pkg2/launch/bringup.launch.py", 0, "/", "", None, False,
        [("use_sim", "true", "command line", 14), ("robot", "r1", "default", 15)], [], [], [
            ("group", "", 16, "/r1", "", None, False, [], remap, [], [
                ("node", "/r1/driver", 19, "/r1/", "pkg2/drv", None, False, [], remap, [],
                 []),
                (*sim, 20, "/r1", "", ("if", "use_sim", {"use_sim": "true"}, True), False,
                 [("world", "empty", "include", 20), ("gui", "true", "default", 10)], [], [],
                 [("node", "/r1/sim", 11, "/r1/", "pkg2/sim", None, False, [], remap,
                   ["/r1/sim/world"], [])])]),
            ("node", "/viz", 25, "/", "pkg2/viz", ("if", "use_sim", {"use_sim": "true"}, True),
             False, [], [], [], []),
            (*sim, 26, "/", "", None, False,
             [("world", "house", "include", 26), ("gui", "true", "default", 10)], [], [], [
                 ("node", "/sim", 11, "/", "pkg2/sim", None, False, [], [], ["/sim/world"],
                  [])])])


def test_ros2_tree_names_what_a_false_condition_leaves_out(tmp_path: Path) -> None:
    root = tree2(tmp_path, {})
    group, viz = root.children[0], root.children[1]
    assert group.pushed == ["r1"] and group.namespace == "/r1"
    off = ("if", "use_sim", {"use_sim": "false"}, False)
    assert shape(group.children[1]) == (
        "include", "pkg2/launch/sim.launch.py", 20, "", "", off, True, [], [], [], [])
    assert shape(viz) == ("node", "viz", 25, "", "pkg2/viz", off, True, [], [], [], [])
    assert root.arg("use_sim") == LaunchArg("use_sim", "false", "default", Location(
        "pkg2", "pkg2/launch/bringup.launch.py", 14, 9))


def test_cli_prints_the_tree_and_json_includes_it(tmp_path: Path, capsys: Any) -> None:
    tree(tmp_path, {})
    main_file = str(tmp_path / "pkg/launch/main.launch")
    code = main(["launch", main_file, "--workspace", str(tmp_path), "--tree",
                 "--arg", "mode:=false"])
    assert code == 0
    lines = [line.rstrip() for line in capsys.readouterr().out.splitlines()]
    assert "│   ├── arg use_cam = true  (include pkg/launch/main.launch:8)" in lines
    assert "├── group  pkg/launch/main.launch:17  (left out)" in lines
    assert "│   ├── if $(arg mode) with mode=false: false" in lines
    assert "│   └── node /r1/driver  pkg/drv  pkg/launch/sub.launch:4" in lines
    code = main(["launch", main_file, "--workspace", str(tmp_path), "--format", "json"])
    assert code == 0
    data = json.loads(capsys.readouterr().out)
    assert [c["name"] for c in data["tree"][0]["children"]] == [
        "pkg/launch/sub.launch", "/sensors/", "", "/talker"]


def test_a_saved_model_keeps_each_configuration_launch_tree(tmp_path: Path) -> None:
    root = tree(tmp_path, {"mode": "true"})
    model = Model("p", configurations=[Configuration("c", launch_tree=[root])])
    again = from_data(json.loads(json.dumps(model_to_data(model))))
    assert [shape(i) for i in again.configurations[0].launch_tree] == [shape(root)]
    old = model_to_data(Model("p", configurations=[Configuration("c")]))
    assert "launch_tree" not in old["configurations"][0]  # documents stay as they were
    assert from_data(old).configurations[0].launch_tree == []


def test_ros1_condition_on_the_environment_names_the_variable(tmp_path: Path) -> None:
    (tmp_path / "pkg" / "launch").mkdir(parents=True)
    (tmp_path / "pkg" / "package.xml").write_text(PACKAGE)
    (tmp_path / "pkg" / "launch" / "env.launch").write_text(
        '<launch><group if="$(optenv LOGITECH 0)"><node pkg="pkg" type="a" name="a"/>'
        '</group></launch>')
    workspace = scan([str(tmp_path)], {})
    for env, values, holds in (({}, {"$LOGITECH": None}, False),
                               ({"LOGITECH": "1"}, {"$LOGITECH": "1"}, True)):
        model = load(str(tmp_path / "pkg/launch/env.launch"), workspace, {}, env)
        cond = model.tree[0].children[0].condition
        assert cond is not None and (cond.values, cond.holds) == (values, holds)


def test_ros2_condition_on_the_environment_names_the_variable(tmp_path: Path) -> None:
    folder = tmp_path / "pkg2" / "launch"
    folder.mkdir(parents=True)
    (tmp_path / "pkg2" / "package.xml").write_text(PACKAGE2)
    (folder / "env.launch.xml").write_text(
        '<launch><node pkg="pkg2" exec="a" name="a" if="$(env USE_A false)"/></launch>')
    workspace = scan([str(tmp_path)], {})
    model = load(str(folder / "env.launch.xml"), workspace, {}, {"USE_A": "true"})
    cond = model.tree[0].children[0].condition
    assert cond is not None and (cond.values, cond.holds) == ({"$USE_A": "true"}, True)
