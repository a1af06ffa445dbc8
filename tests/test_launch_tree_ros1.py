"""The ROS 1 launch tree: includes with their arguments, groups, remaps, conditions."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from haros_arch.launch import load
from haros_arch.model.launch_tree import LaunchItem, item_from_data
from haros_arch.model.serialise import to_data
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
