"""A ROS 1 ``<node>`` whose program sleeps and runs ``roslaunch $@`` (timed_roslaunch,
kinova-movo's copy in si_utils) starts the launch file its arguments name: it is read
as the top-level file of a roslaunch of its own, in the node's namespace (roslaunch sets
the process's ROS_NAMESPACE), with the ``name:=value`` words as arguments and the node's
conditions; the script itself is not a node of unknown interface. A script that does
something else stays a node; a file whose name is not known stays unknown, said."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

TIMED = """\
#!/bin/bash
# delay the launch of a roslaunch file
if [ "$1" = "-h" ]; then
    echo "use: timed_roslaunch DELAY PKG FILE [args]"
else
    sleep $1
    shift
    roslaunch $@
fi
"""

OTHER_SCRIPT = """\
#!/bin/bash
sleep $1
shift
rosrun other talker "$@"
"""

MAIN = """<launch>
  <arg name="go"/>
  <group ns="robot">
    <node pkg="bringup" type="timed_roslaunch" name="delayed" if="$(arg go)"
          args="3 other child.launch rate:=5 _ignored:=1"/>
    <node pkg="bringup" type="delayed_run" name="runner" args="2 x" if="$(arg go)"/>
    <node pkg="bringup" type="timed_roslaunch" name="unknown" args="4 $(env NOT_SET) child.launch"/>
  </group>
  <node pkg="timed_roslaunch" type="timed_roslaunch.sh" name="published"
        args="1 other child.launch rate:=7 __ns:=elsewhere"/>
</launch>
"""

CHILD = """<launch>
  <arg name="rate"/>
  <node pkg="other" type="talker" name="talker">
    <param name="rate" value="$(arg rate)"/>
  </node>
</launch>
"""


def _model(write_tree):
    root = write_tree({
        "src/bringup/package.xml": package_xml("bringup", "catkin"),
        "src/bringup/scripts/timed_roslaunch": TIMED,
        "src/bringup/scripts/delayed_run": OTHER_SCRIPT,
        "src/bringup/launch/main.launch": MAIN,
        "src/other/package.xml": package_xml("other", "catkin"),
        "src/other/launch/sub/child.launch": CHILD})
    ws = scan([str(root / "src")], {})
    return load(str(root / "src/bringup/launch/main.launch"), ws, {}, {})


def test_the_launched_file_is_read_in_the_node_namespace(write_tree) -> None:
    model = _model(write_tree)
    names = sorted(n.name for n in model.nodes)
    assert names == ["/elsewhere/talker", "/robot/runner", "/robot/talker"]
    rates = {p.name: p.value for p in model.params if p.name.endswith("/rate")}
    assert rates == {"/robot/talker/rate": 5, "/elsewhere/talker/rate": 7}


def test_the_launched_nodes_keep_the_node_condition(write_tree) -> None:
    model = _model(write_tree)
    talker = next(n for n in model.nodes if n.name == "/robot/talker")
    runner = next(n for n in model.nodes if n.name == "/robot/runner")
    assert [c.text for c in runner.conditions] == ["$(arg go)"]
    assert [c.text for c in talker.conditions] == ["$(arg go)"]
    published = next(n for n in model.nodes if n.name == "/elsewhere/talker")
    assert not published.conditions


def test_a_file_not_known_stays_unknown_and_said(write_tree) -> None:
    model = _model(write_tree)
    said = [d for d in model.diagnostics if d.code == "LAUNCH_UNKNOWN_VALUE"
            and "through roslaunch" in d.message]
    assert [d.location.line for d in said] == [7]
    assert [u.namespace for u in model.unread_includes] == ["/robot/"]


def test_the_script_and_launched_packages_are_used(write_tree) -> None:
    model = _model(write_tree)
    used = {(u.package, u.kind) for u in model.package_uses}
    assert {("bringup", "node"), ("timed_roslaunch", "node"), ("other", "file")} <= used
