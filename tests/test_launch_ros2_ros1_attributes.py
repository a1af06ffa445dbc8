"""Two ROS 1 habits in a ROS 2 XML (or YAML) launch file that ros2 launch refuses:
``<group ns="robot">`` and ``<arg ... doc="...">``. launch's GroupAction.parse reads only
``scoped``, ``forwarding`` and its ``<keep>`` children, DeclareLaunchArgument.parse only
``name``, ``default``, ``description`` and its ``<choice>`` children (ros2/launch humble and
jazzy, launch/actions/group_action.py, declare_launch_argument.py), and expose_action
then checks every attribute was read (launch/frontend/expose.py): "Unexpected
attribute(s)", the launch fails. The tool took ``ns`` as a namespace and ``doc`` as a
description, silently; now each is LAUNCH_UNEXPECTED_ATTRIBUTE, an error, and the group
pushes no namespace (a namespace is launch_ros' ``<push-ros-namespace>``)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan


def _run(write_tree, name: str, text: str):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       f"src/pkg/launch/{name}": text})
    return load(str(root / "src/pkg/launch" / name), scan([str(root / "src")], {}), {}, {})


def test_group_ns_and_arg_doc_are_refused(write_tree) -> None:
    model = _run(write_tree, "main.launch.xml", """<launch>
  <arg name="map" default="m" doc="the map"/>
  <arg name="world" default="w" description="the world"/>
  <group ns="robot">
    <node pkg="p" exec="e" name="n"/>
  </group>
  <group>
    <push-ros-namespace namespace="arm"/>
    <node pkg="p" exec="e" name="m"/>
  </group>
</launch>
""")
    # (map and world, which nothing reads, are LAUNCH_ARG_UNUSED: not this test's)
    found = sorted((d.code, d.location.line, d.severity) for d in model.diagnostics
                   if d.code != "LAUNCH_ARG_UNUSED")
    assert found == [("LAUNCH_UNEXPECTED_ATTRIBUTE", 2, "error"),
                     ("LAUNCH_UNEXPECTED_ATTRIBUTE", 4, "error")]
    assert any("doc=" in d.message for d in model.diagnostics)
    assert any("ns=" in d.message for d in model.diagnostics)
    assert sorted(n.name for n in model.nodes) == ["/arm/m", "/n"]


def test_in_yaml_too(write_tree) -> None:
    model = _run(write_tree, "main.launch.yaml", """launch:
- arg: {name: map, default: m, doc: the map}
- group:
    ns: robot
    children:
    - node: {pkg: p, exec: e, name: n}
""")
    assert sorted(d.code for d in model.diagnostics if d.code != "LAUNCH_ARG_UNUSED") == [
        "LAUNCH_UNEXPECTED_ATTRIBUTE", "LAUNCH_UNEXPECTED_ATTRIBUTE"]
    assert [n.name for n in model.nodes] == ["/n"]
