"""The scope of an include's arguments in ROS 2 launch (humble, jazzy and rolling alike):
``IncludeLaunchDescription.execute`` returns a ``SetLaunchConfiguration`` per argument,
performed one after the other in the including scope, then the included description,
which is not scoped either. So the arguments, and what the included file declares or
sets, stay set after the include; only a scoped group (``<group>``, ``GroupAction``)
ends them. Checked with ros2/launch's own LaunchService at the humble and jazzy
branches (bench/README.md, helper followups9); the same launch in XML, YAML and Python."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

INNER = """<launch>
  <arg name="plugin" default="inner_default"/>
  <arg name="extra" default="from_inner"/>
  <node pkg="p" exec="e" name="in_$(var plugin)"/>
</launch>
"""

OUTER = {
    "outer.launch.xml": """<launch>
  <include file="$(dirname)/inner.launch.xml">
    <arg name="plugin" value="first"/>
    <arg name="second" value="$(var plugin)"/>
  </include>
  <node pkg="p" exec="e" name="after_$(var plugin)_$(var extra)_$(var second)"/>
  <group>
    <include file="$(dirname)/inner.launch.xml">
      <arg name="plugin" value="grouped"/>
    </include>
  </group>
  <node pkg="p" exec="e" name="aftergroup_$(var plugin)"/>
</launch>
""",
    "outer.launch.yaml": """launch:
- include:
    file: "$(dirname)/inner.launch.xml"
    arg: [{name: plugin, value: first}, {name: second, value: "$(var plugin)"}]
- node: {pkg: p, exec: e, name: "after_$(var plugin)_$(var extra)_$(var second)"}
- group:
  - include:
      file: "$(dirname)/inner.launch.xml"
      arg: [{name: plugin, value: grouped}]
- node: {pkg: p, exec: e, name: "aftergroup_$(var plugin)"}
""",
    "outer_launch.py": """import os
from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    inner = os.path.join(os.path.dirname(__file__), 'inner.launch.xml')
    return LaunchDescription([
        IncludeLaunchDescription(
            AnyLaunchDescriptionSource(inner),
            launch_arguments=[('plugin', 'first'),
                              ('second', LaunchConfiguration('plugin'))]),
        Node(package='p', executable='e',
             name=['after_', LaunchConfiguration('plugin'), '_',
                   LaunchConfiguration('extra'), '_', LaunchConfiguration('second')]),
        GroupAction([IncludeLaunchDescription(
            AnyLaunchDescriptionSource(inner),
            launch_arguments={'plugin': 'grouped'}.items())]),
        Node(package='p', executable='e', name=['aftergroup_', LaunchConfiguration('plugin')]),
    ])
""",
}


@pytest.mark.parametrize("name", sorted(OUTER))
def test_an_includes_arguments_and_its_files_declarations_stay_set_after_it(
        write_tree, name: str) -> None:
    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_cmake"),
        "src/p/launch/inner.launch.xml": INNER,
        f"src/p/launch/{name}": OUTER[name],
    })
    workspace = scan([str(root / "src")], {})
    model = load(str(root / "src/p/launch" / name), workspace, {}, {})
    assert [n.name for n in model.nodes] == [
        "/in_first",
        # the argument passed, the included file's default, and an argument that read
        # the one set just before it: all still set after the include
        "/after_first_from_inner_first",
        "/in_grouped",
        # the include in a scoped group sets nothing outside it
        "/aftergroup_first",
    ]
    assert model.diagnostics == []
