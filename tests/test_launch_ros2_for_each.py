"""launch's ``ForEach`` and ``ForLoop`` (Kilted): navigation2's
cloned_multi_tb3_simulation_launch.py starts each robot's stack with
``ForEach(LaunchConfiguration('robots'), function=generate_robot_actions)``, the robots
a ``;``-separated list of YAML mappings. Not interpreted, the configuration had no node
at all. Python and front-end forms, values known, given on the command line, or not
known, and the errors launch raises."""

from __future__ import annotations

import test_launch_ros2 as frontend
from test_launch_ros2_python import run

ROBOTS = """
from launch.actions import ForEach, ForLoop

def robot(name: str = '', pose: dict = {}, id: int = 0):
    return [Node(package='drive', executable='base', namespace=name,
                 name='base_' + str(id),
                 parameters=[{'x': pose.get('x', 0.0), 'id': id}])]

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robots', default_value=(
            "{name: 'robot1', pose: {x: 0.5}, id: 1};"
            "{name: 'robot2', id: 2};")),
        ForEach(LaunchConfiguration('robots'), function=robot),
    ])
"""


def test_python_for_each_calls_the_function_per_iteration(write_tree) -> None:
    model, _ = run(write_tree, ROBOTS)
    assert [n.name for n in model.nodes] == ["/robot1/base_1", "/robot2/base_2"]
    params = {p.name: p.value for p in model.params}
    assert params["/robot1/base_1/x"] == 0.5
    assert params["/robot2/base_2/x"] == 0.0  # the default of pose.get
    assert params["/robot2/base_2/id"] == 2
    assert "LAUNCH_PY_UNSUPPORTED" not in [d.code for d in model.diagnostics]
    assert all(not n.conditions for n in model.nodes)


def test_python_for_each_takes_the_command_line_value(write_tree) -> None:
    model, _ = run(write_tree, ROBOTS, args={"robots": "{name: a};{name: b};{name: c}"})
    assert [n.name for n in model.nodes] == ["/a/base_0", "/b/base_0", "/c/base_0"]
    model, _ = run(write_tree, ROBOTS, args={"robots": ""})
    assert model.nodes == []  # no iteration (launch warns and goes on)
    model, _ = run(write_tree, ROBOTS, args={"robots": "{}"})
    assert [n.name for n in model.nodes] == ["/base_0"]  # one, with the defaults


def test_python_for_each_over_values_not_known_runs_once_under_the_loop(write_tree) -> None:
    model, _ = run(write_tree, ROBOTS.replace(
        "LaunchConfiguration('robots')", "Command(['list_robots'])").replace(
        "from launch.actions import", "from launch.substitutions import Command\n"
                                       "from launch.actions import"))
    assert len(model.nodes) == 1
    node = model.nodes[0]
    assert "?" in node.name
    assert [c.statement for c in node.conditions] == ["for"]
    assert "not known statically" in node.conditions[0].text


def test_python_for_each_values_launch_refuses_are_errors(write_tree) -> None:
    model, _ = run(write_tree, ROBOTS, args={"robots": "{name: a};robot2"})
    assert model.nodes == []
    bad = [d for d in model.diagnostics if d.code == "LAUNCH_BAD_VALUE"]
    assert len(bad) == 1 and "not a YAML mapping" in bad[0].message
    assert bad[0].severity == "error"
    model, _ = run(write_tree, ROBOTS, args={"robots": "{name: [a"})
    assert model.nodes == []
    assert any("not valid YAML" in d.message for d in model.diagnostics
               if d.code == "LAUNCH_BAD_VALUE")


def test_python_for_loop_gives_i(write_tree) -> None:
    model, _ = run(write_tree, """
from launch.actions import ForLoop

def lidar(i):
    return [Node(package='drive', executable='lidar', name=f'lidar_{i}')]

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('count', default_value='3'),
        ForLoop(LaunchConfiguration('count'), function=lidar),
    ])
""")
    assert [n.name for n in model.nodes] == ["/lidar_0", "/lidar_1", "/lidar_2"]


def test_xml_for_each_and_for_with_their_substitutions(write_tree) -> None:
    model, _ = frontend.run(write_tree, "multi.launch.xml", """
<launch>
  <arg name="robots" default="{name: 'alpha', id: 1};{name: 'beta'}"/>
  <arg name="cams" default="2"/>
  <for_each values="$(var robots)">
    <node pkg="drive" exec="base" name="base_$(for-var id 0)" namespace="$(for-var name)"/>
  </for_each>
  <for len="$(var cams)" name="k">
    <node pkg="cam" exec="driver" name="cam_$(index k)"/>
  </for>
</launch>
""")
    assert [n.name for n in model.nodes] == [
        "/alpha/base_1", "/beta/base_0", "/cam_0", "/cam_1"]
    assert "LAUNCH_UNKNOWN_TAG" not in frontend.codes(model)


def test_yaml_for_each(write_tree) -> None:
    model, _ = frontend.run(write_tree, "multi.launch.yaml", """
launch:
  - arg: {name: robots, default: "{name: 'a'};{name: 'b'}"}
  - for_each:
      values: $(var robots)
      children:
        - node: {pkg: drive, exec: base, name: base, namespace: $(for-var name)}
""")
    assert [n.name for n in model.nodes] == ["/a/base", "/b/base"]


def test_for_var_outside_a_loop_and_a_length_not_a_number(write_tree) -> None:
    model, _ = frontend.run(write_tree, "bad.launch.xml", """
<launch>
  <node pkg="drive" exec="base" name="base_$(for-var id)"/>
  <for len="two" name="i">
    <node pkg="cam" exec="driver" name="cam_$(index i)"/>
  </for>
</launch>
""")
    assert [n.name for n in model.nodes] == ["/base_?"]
    messages = [d.message for d in model.diagnostics if d.code == "LAUNCH_BAD_VALUE"]
    assert any("for-var / index id" in m for m in messages)
    assert any("ForLoop length 'two'" in m for m in messages)
