"""A ROS 1 launch file may include itself with other arguments: roslaunch keeps no
list of the files it reads, so the recursion ends where the arguments say (a file that
starts one node per part of a robot, "arms" including it for "right_arm" and
"left_arm"). Only the same file with the same arguments again is a cycle."""
from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

SENDER = """<launch>
  <arg name="part" />
  <arg name="self" value="$(find pkg)/launch/send.launch" />
  <group unless="$(eval arg('part') in ('all', 'arms'))">
    <node name="send_$(arg part)" pkg="p" type="sender" />
  </group>
  <group if="$(eval arg('part') == 'arms')">
    <include file="$(arg self)"> <arg name="part" value="right_arm" /> </include>
    <include file="$(arg self)"> <arg name="part" value="left_arm" /> </include>
  </group>
  <group if="$(eval arg('part') == 'all')">
    <include file="$(arg self)"> <arg name="part" value="arms" /> </include>
    <include file="$(arg self)"> <arg name="part" value="head" /> </include>
  </group>
</launch>
"""


def _load(write_tree, main: str, args: dict[str, str] | None = None):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg"),
                       "src/pkg/launch/send.launch": SENDER,
                       "src/pkg/launch/main.launch": main})
    ws = scan([str(root / "src")], {})
    return load(str(root / "src/pkg/launch/main.launch"), ws, args or {}, {})


def test_include_of_itself_with_other_arguments_is_read(write_tree):
    model = _load(write_tree, """<launch>
      <include file="$(find pkg)/launch/send.launch"> <arg name="part" value="all" /> </include>
    </launch>""")
    assert [d.code for d in model.diagnostics if d.code == "LAUNCH_INCLUDE_CYCLE"] == []
    assert sorted(n.name for n in model.nodes) == [
        "/send_head", "/send_left_arm", "/send_right_arm"]


def test_include_of_itself_with_the_same_arguments_is_a_cycle(write_tree):
    model = _load(write_tree, """<launch>
      <arg name="x" default="1" />
      <include file="$(find pkg)/launch/main.launch"> <arg name="x" value="$(arg x)" /> </include>
    </launch>""")
    cycles = [d for d in model.diagnostics if d.code == "LAUNCH_INCLUDE_CYCLE"]
    assert [(d.location.file, d.location.line) for d in cycles] == [
        ("pkg/launch/main.launch", 3)]
