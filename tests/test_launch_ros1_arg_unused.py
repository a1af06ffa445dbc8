"""A ROS 1 ``<arg>`` that nothing else in its file names is said where it is declared,
LAUNCH_ARG_UNUSED (an info), as for ROS 2: roslaunch's arguments belong to their file, so
one no ``$(arg)``, ``$(eval)`` or include value names changes nothing. Autoware-AI/drivers
d5111e9's baumer.launch declared ``brightness`` (line 5) and never gave the camera node
the parameter, which the node read with its own default (vlg22_main.cpp:201), so
``brightness:=0.5`` did nothing. An argument used only where a condition skips, in
``$(eval)`` by its bare name, or handed to an include's ``<arg>`` is used; nothing is said
for a file with ``<include pass_all_args="true">`` (its arguments go on to the included
file), nor for an ``<include>``'s own ``<arg>`` children (values passed, not declared)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

TOP = """\
<launch>
  <arg name="fps" default="20"/>
  <arg name="brightness" default="0.7"/>
  <arg name="sim" default="false"/>
  <arg name="rate" default="10"/>
  <arg name="scale" default="0.5"/>
  <arg name="robot" default="r1"/>
  <node pkg="demo" type="cam" name="cam">
    <param name="fps" value="$(arg fps)"/>
    <param name="rate" value="$(eval rate * 2)"/>
  </node>
  <group if="$(arg sim)">
    <param name="scale" value="$(arg scale)"/>
  </group>
  <include file="$(find demo)/launch/inner.launch">
    <arg name="robot" value="$(arg robot)"/>
    <arg name="brightness" value="1"/>
  </include>
</launch>
"""

INNER = """\
<launch>
  <arg name="robot"/>
  <arg name="brightness" default="0"/>
  <node pkg="demo" type="cam" name="$(arg robot)"/>
</launch>
"""


def _said(write_tree, top: str = TOP, inner: str = INNER) -> list[tuple[str, str, int]]:
    root = write_tree({"src/demo/package.xml": package_xml("demo"),
                       "src/demo/launch/top.launch": top,
                       "src/demo/launch/inner.launch": inner})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/demo/launch/top.launch"), ws, {}, {})
    return [(d.location.file or "", d.message, d.location.line)
            for d in model.diagnostics if d.code == "LAUNCH_ARG_UNUSED"]


def test_an_argument_nothing_in_its_file_names_is_said(write_tree) -> None:
    # brightness: the top file only passes a value of its own to the include's argument
    # of that name; the inner file declares it and nothing reads it
    assert _said(write_tree) == [
        ("demo/launch/inner.launch", "launch argument brightness is declared but nothing "
         "in the launch reads it: its value changes nothing", 3),
        ("demo/launch/top.launch", "launch argument brightness is declared but nothing in "
         "the launch reads it: its value changes nothing", 3)]


def test_guard_used_arguments_and_pass_all_args(write_tree) -> None:
    used = TOP.replace('<arg name="brightness" value="1"/>',
                       '<arg name="brightness" value="$(arg brightness)"/>')
    assert _said(write_tree, used, INNER.replace(
        '<node pkg="demo" type="cam" name="$(arg robot)"/>',
        '<node pkg="demo" type="cam" name="$(arg robot)" args="$(arg brightness)"/>')) == []
    # every argument of a file that passes them all on may be read by the included file
    passing = TOP.replace('<include file="$(find demo)/launch/inner.launch">',
                          '<include file="$(find demo)/launch/inner.launch" '
                          'pass_all_args="true">')
    assert [line for file, _, line in _said(write_tree, passing)
            if file.endswith("top.launch")] == []
    # an eval that names an argument made at run time: any may be read
    dynamic = TOP.replace('$(eval rate * 2)', "$(eval arg(sel) * 2)").replace(
        '<arg name="rate" default="10"/>',
        '<arg name="rate" default="10"/>\n  <arg name="sel" default="rate"/>')
    assert [line for file, _, line in _said(write_tree, dynamic)
            if file.endswith("top.launch")] == []
