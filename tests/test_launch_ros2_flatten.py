"""``haros-arch launch --flatten`` on ROS 2 launch files: one XML, YAML or Python file
that our own loader reads as the original (same nodes, same parameters), on every ROS 2
launch file of the fixtures and on small cases written here."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import pytest
from conftest import FIXTURES, ROOT, package_xml
from test_launch_ros2_fixtures import CASES as GOLDEN_CASES

from haros_arch.cli import main
from haros_arch.launch import load
from haros_arch.launch.dialect import ros_version
from haros_arch.launch.ros2.flatten import collect, facts, flatten, param_text
from haros_arch.workspace import scan

SUFFIX = {"xml": ".launch.xml", "yaml": ".launch.yaml", "python": ".launch.py"}
WORKSPACES = [FIXTURES / "launch_ros2" / "src", FIXTURES / "share_ros2" / "src",
              FIXTURES / "python" / "several_nodes" / "src",
              FIXTURES / "cpp" / "several_nodes" / "src", FIXTURES / "build" / "plugins",
              ROOT / "examples" / "src"]


def ros2_launch_files() -> list[tuple[Path, str, dict[str, str]]]:
    """Every ROS 2 launch file of the fixtures with no arguments, and the golden cases
    of fixtures/launch_ros2 with theirs."""
    found = []
    for root in WORKSPACES:
        for path in sorted(root.rglob("*")):
            if path.suffix in (".py", ".xml", ".yaml") and "launch" in path.parent.name and (
                    ros_version(str(path)) == 2):
                found.append((root, str(path.relative_to(root)), {}))
    for name, args in GOLDEN_CASES.values():
        found.append((FIXTURES / "launch_ros2" / "src", name, args))
    return found


FILES = ros2_launch_files()


def roundtrip(root: Path, name: str, args: dict[str, str], fmt: str,
              out: Path) -> tuple[list[str], list[str], str]:
    workspace = scan([str(root)], {})
    model = load(str(root / name), workspace, args, {})
    flat = collect(model, fmt)
    text, _ = flatten(model, fmt)
    path = out / f"flat{SUFFIX[fmt]}"
    path.write_text(text)
    again = load(str(path), workspace, {}, {})
    assert not [d for d in again.diagnostics if d.severity == "error"], again.diagnostics
    return facts(again), facts(model, flat), text


def test_every_fixture_is_found() -> None:
    assert len(FILES) >= 20
    assert {Path(name).suffix for _, name, _ in FILES} == {".py", ".xml", ".yaml"}


@pytest.mark.parametrize("fmt", ["xml", "yaml", "python"])
@pytest.mark.parametrize(("root", "name", "args"), FILES,
                         ids=[f"{n}{'+args' if a else ''}" for _, n, a in FILES])
def test_the_flat_file_loads_as_the_original(root: Path, name: str, args: dict[str, str],
                                             fmt: str, tmp_path: Path) -> None:
    got, want, text = roundtrip(root, name, args, fmt, tmp_path)
    assert got == want, text
    assert "Include" not in text and "<include" not in text and "$(var" not in text


def test_the_fixtures_keep_most_of_what_they_start(tmp_path: Path) -> None:
    """Left out is only what is not known: the composed bringup keeps its container,
    components and parameter files' values."""
    root = FIXTURES / "launch_ros2" / "src"
    got, want, text = roundtrip(root, "rover_bringup/launch/bringup_launch.py", {}, "xml",
                                tmp_path)
    assert got == want and len(got) >= 10
    assert "<node_container" in text and "<composable_node" in text


def write(tmp_path: Path, files: dict[str, str]) -> Path:
    (tmp_path / "pkg").mkdir()
    (tmp_path / "pkg/package.xml").write_text(package_xml("pkg", "ament_cmake"))
    for rel, text in files.items():
        path = tmp_path / "pkg" / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return tmp_path / "pkg"


MAIN = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, RegisterEventHandler
from launch.actions import TimerAction
from launch.conditions import IfCondition
from launch.event_handlers import OnProcessExit
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, Node
from launch_ros.actions import PushRosNamespace, SetParameter, SetRemap
from launch_ros.descriptions import ComposableNode

def generate_launch_description():
    first = Node(package='pkg', executable='spawner', name='first')
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='fast'),
        DeclareLaunchArgument('maybe'),
        SetParameter('use_sim_time', True),
        GroupAction([
            PushRosNamespace('robot'),
            SetRemap('cmd_vel', '/cmd'),
            Node(package='pkg', executable='drive', name='driver', arguments=['-v', 'x'],
                 parameters=[{'code': '1', 'mode': LaunchConfiguration('mode'),
                              'gains': [1.5, 2.0], 'flags': ['a', 'true'], 'nested': {'a': 3},
                              'empty': ''}],
                 remappings=[('odom', 'odom_raw')]),
            ComposableNodeContainer(package='rclcpp_components',
                executable='component_container', name='box', namespace='',
                composable_node_descriptions=[
                    ComposableNode(package='pkg', plugin='pkg::Cam', name='cam',
                                   parameters=[{'fps': 30}])]),
        ]),
        LoadComposableNodes(target_container='/elsewhere/box', composable_node_descriptions=[
            ComposableNode(package='pkg', plugin='pkg::Late', name='late')]),
        Node(package='pkg', executable='maybe',
             condition=IfCondition(LaunchConfiguration('maybe'))),
        TimerAction(period=2.0, actions=[Node(package='pkg', executable='later', name='later')]),
        first,
        RegisterEventHandler(OnProcessExit(target_action=first, on_exit=[
            Node(package='pkg', executable='after', name='after')])),
    ])
"""


def small(tmp_path: Path, fmt: str) -> tuple[str, list[str], Any, Any]:
    pkg = write(tmp_path, {"launch/main.launch.py": MAIN})
    workspace = scan([str(tmp_path)], {})
    model = load(str(pkg / "launch/main.launch.py"), workspace, {}, {})
    text, notes = flatten(model, fmt)
    out = tmp_path / f"flat{SUFFIX[fmt]}"
    out.write_text(text)
    return text, notes, model, load(str(out), workspace, {}, {})


@pytest.mark.parametrize("fmt", ["xml", "yaml", "python"])
def test_a_small_bringup_in_each_format(tmp_path: Path, fmt: str) -> None:
    text, notes, model, again = small(tmp_path, fmt)
    assert facts(again) == facts(model, collect(model, fmt))
    names = sorted(n.name for n in again.nodes)
    assert names == ["/after", "/first", "/late", "/later", "/robot/box", "/robot/cam",
                     "/robot/driver"]
    driver = {p.key: p.value for p in again.params if p.node == "/robot/driver"}
    assert driver == {"use_sim_time": True, "code": "1", "mode": "fast", "gains": [1.5, 2.0],
                      "flags": ["a", "true"], "nested.a": 3, "empty": ""}
    [node] = [n for n in again.nodes if n.name == "/robot/driver"]
    assert node.remaps == [("cmd_vel", "/cmd"), ("odom", "odom_raw")]
    assert node.args == "-v x"
    [cam] = [n for n in again.nodes if n.executable == "pkg::Cam"]
    assert cam.composable and cam.container == "/robot/box"
    [late] = [n for n in again.nodes if n.executable == "pkg::Late"]
    assert late.container == "/elsewhere/box"
    [later] = [n for n in again.nodes if n.name == "/later"]
    assert [c.statement for c in later.conditions] == ["timer"]
    assert [c.statement for n in again.nodes if n.name == "/after" for c in n.conditions] == []
    assert len(notes) == 2
    assert notes[0].startswith("node /? (pkg/launch/main.launch.py:") and (
        "left out" in notes[0])
    assert notes[1].startswith("node /after (") and "written to start at once" in notes[1]
    assert "haros-arch: node /after" in text


def test_xml_keeps_strings_that_read_as_numbers_strings(tmp_path: Path) -> None:
    text, _, _, _ = small(tmp_path, "xml")
    assert "<node_container pkg=\"rclcpp_components\"" in text
    assert '<param name="code" value="\'1\'"/>' in text
    assert '<param name="flags" value="[a, \'true\']"/>' in text
    assert '<timer period="2.0">' in text


def test_param_text_reads_back_as_the_value() -> None:
    assert param_text("1") == "'1'"
    assert param_text("base_link") == "base_link"
    assert param_text(1e-05) == "1.0e-05"
    assert param_text(True) == "true"
    assert param_text(float("inf")) == ".inf"
    assert param_text("$(var x)") is None  # would be read as a substitution


def test_cli_flatten_ros2_yaml_and_python(tmp_path: Path, capsys: Any) -> None:
    pkg = write(tmp_path, {"launch/main.launch.py": MAIN})
    file = str(pkg / "launch/main.launch.py")
    assert main(["launch", file, "--workspace", str(tmp_path), "--flatten",
                 "--format", "yaml", "--arg", "maybe:=true"]) == 0
    out, err = capsys.readouterr()
    assert out.startswith("# flattened by haros-arch") and "\nlaunch:\n" in out
    assert "exec: maybe" in out and "note: node /after" in err
    assert main(["launch", file, "--workspace", str(tmp_path), "--flatten",
                 "--format", "python"]) == 0
    out, _ = capsys.readouterr()
    assert "def generate_launch_description():" in out and "package='pkg'," in out
    compile(out, "flat.launch.py", "exec")
    assert main(["launch", file, "--workspace", str(tmp_path), "--format", "yaml"]) == 2


def test_a_yaml_launch_file_keeps_a_plain_string_a_string(tmp_path: Path) -> None:
    """launch_yaml gives ``value: 'false'`` as the string (launch_xml's ``value="false"``
    is the boolean); with a substitution the text is read as YAML, as launch_ros does."""
    pkg = write(tmp_path, {"launch/a.launch.yaml": (
        "launch:\n- arg: {name: x, default: 'false'}\n- node:\n    pkg: pkg\n    exec: e\n"
        "    name: n\n    param:\n    - {name: s, value: 'false'}\n"
        "    - {name: t, value: false}\n    - {name: u, value: \"'1'\"}\n"
        "    - {name: v, value: $(var x)}\n    - {name: y, value: [a, 'true']}\n")})
    model = load(str(pkg / "launch/a.launch.yaml"), scan([str(tmp_path)], {}), {}, {})
    assert {p.key: p.value for p in model.params} == {
        "s": "false", "t": False, "u": "'1'", "v": False, "y": ["a", "true"]}


def test_a_component_with_no_name_is_kept_in_python_only(tmp_path: Path) -> None:
    """launch_ros's XML and YAML ``composable_node`` need ``name=`` (the real launch
    refuses the file without it); Python's ``ComposableNode`` does not."""
    pkg = write(tmp_path, {"launch/c.launch.py": (
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import ComposableNodeContainer\n"
        "from launch_ros.descriptions import ComposableNode\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([ComposableNodeContainer(name='box', namespace='',\n"
        "        package='rclcpp_components', executable='component_container',\n"
        "        composable_node_descriptions=[ComposableNode(package='pkg',\n"
        "                                                     plugin='pkg::Cam')])])\n")})
    model = load(str(pkg / "launch/c.launch.py"), scan([str(tmp_path)], {}), {}, {})
    text, notes = flatten(model, "xml")
    assert "<composable_node" not in text and "no name" in notes[0]
    text, notes = flatten(model, "python")
    assert "ComposableNode(\n" in text and "plugin='pkg::Cam',\n" in text
    compile(text, "flat.launch.py", "exec")
    assert notes == []


@pytest.mark.parametrize("fmt", ["xml", "yaml", "python"])
def test_a_node_with_no_name_keeps_its_parameter_file_as_a_path(tmp_path: Path,
                                                                 fmt: str) -> None:
    """launch_ros hands a Node's parameter file to the node, which applies the section
    for the name its code gives; with that name unknown here only /** applies, so the
    flat file keeps the file's path (and the values known)."""
    pkg = write(tmp_path, {
        "config/p.yaml": "/**:\n  ros__parameters:\n    rate: 5\n"
                         "driver:\n  ros__parameters:\n    port: /dev/tty\n",
        "launch/u.launch.xml": "<launch>\n  <node pkg=\"pkg\" exec=\"drive\">\n"
                               "    <param from=\"$(dirname)/../config/p.yaml\"/>\n"
                               "    <param name=\"gain\" value=\"2\"/>\n  </node>\n</launch>\n"})
    workspace = scan([str(tmp_path)], {})
    model = load(str(pkg / "launch/u.launch.xml"), workspace, {}, {})
    assert model.nodes[0].params_files_given == [str(pkg / "launch/../config/p.yaml")]
    text, notes = flatten(model, fmt)
    out = tmp_path / f"flat{SUFFIX[fmt]}"
    out.write_text(text)
    again = load(str(out), workspace, {}, {})
    assert notes == [] and "config/p.yaml" in text
    assert facts(again) == facts(model)
    assert [os.path.realpath(f) for f in again.nodes[0].params_files_given] == [
        str(pkg / "config/p.yaml")]
    assert {p.key: p.value for p in again.params if p.pattern is None} == {
        "rate": 5, "gain": 2}
    assert [(p.pattern, p.key, p.value) for p in again.params if p.pattern] == [
        ("/driver", "port", "/dev/tty")]


def test_a_timer_whose_period_is_not_a_number_is_left_out(tmp_path: Path) -> None:
    pkg = write(tmp_path, {"launch/t.launch.xml": (
        "<launch>\n  <arg name=\"delay\" default=\"3.0\"/>\n"
        "  <timer period=\"$(var delay)\">\n"
        "    <node pkg=\"pkg\" exec=\"late\" name=\"late\"/>\n  </timer>\n"
        "  <timer period=\"1.5\">\n    <node pkg=\"pkg\" exec=\"soon\" name=\"soon\"/>\n"
        "  </timer>\n</launch>\n")})
    model = load(str(pkg / "launch/t.launch.xml"), scan([str(tmp_path)], {}), {}, {})
    text, notes = flatten(model, "xml")
    assert '<timer period="1.5">' in text and 'name="late"' not in text
    assert [n.split(" (")[0] for n in notes] == ["node /late"]


def test_a_python_string_parameter_stays_a_string(tmp_path: Path) -> None:
    """launch_ros (jazzy) dumps a Python string as YAML and reads it back, so '1',
    'true' and '[x, y]' stay strings (the real launch gives the same); a substitution's
    text is read as YAML."""
    pkg = write(tmp_path, {"launch/p.launch.py": (
        "from launch import LaunchDescription\n"
        "from launch.actions import DeclareLaunchArgument\n"
        "from launch.substitutions import LaunchConfiguration\n"
        "from launch_ros.actions import Node\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([DeclareLaunchArgument('x', default_value='true'),\n"
        "        Node(package='pkg', executable='e', name='n', parameters=[{\n"
        "            'a': '[x, y]', 'b': '1', 'c': 'true', 'g': ['1', '2'],\n"
        "            'f': LaunchConfiguration('x'), 'h': 2.5}])])\n")})
    model = load(str(pkg / "launch/p.launch.py"), scan([str(tmp_path)], {}), {}, {})
    assert {p.key: p.value for p in model.params} == {
        "a": "[x, y]", "b": "1", "c": "true", "g": ["1", "2"], "f": True, "h": 2.5}


def test_xml_writes_text_of_several_lines_as_a_literal_block() -> None:
    text = '<robot name="arm">\n  <link name="world"/>\n</robot>\n'
    assert param_text(text) == (
        '|\n  <robot name="arm">\n    <link name="world"/>\n  </robot>\n')
    assert param_text("C:\\path") is None  # launch would read the backslash as an escape


def test_a_list_of_mixed_types_is_written_in_xml_but_not_in_python(tmp_path: Path) -> None:
    pkg = write(tmp_path, {"launch/m.launch.xml": (
        "<launch>\n  <node pkg=\"pkg\" exec=\"e\" name=\"n\">\n"
        "    <param name=\"cov\" value=\"[1e-3, 0.5]\"/>\n  </node>\n</launch>\n")})
    model = load(str(pkg / "launch/m.launch.xml"), scan([str(tmp_path)], {}), {}, {})
    assert [p.value for p in model.params] == [["1e-3", 0.5]]  # YAML 1.1: 1e-3 is text
    text, notes = flatten(model, "xml")
    assert notes == [] and '<param name="cov" value="[1e-3, 0.5]"/>' in text
    text, notes = flatten(model, "python")
    assert notes == ["parameter /n:cov cannot be written as a python value (['1e-3', 0.5]); "
                     "left out"]


def test_a_node_section_that_cannot_be_kept_as_a_path_is_left_out_and_said(
        tmp_path: Path) -> None:
    pkg = write(tmp_path, {
        "config/p.yaml": "cam:\n  ros__parameters:\n    fps: 30\n",
        "launch/c.launch.py": (
            "from launch import LaunchDescription\n"
            "from launch_ros.actions import ComposableNodeContainer\n"
            "from launch_ros.descriptions import ComposableNode\n"
            "def generate_launch_description():\n"
            "    return LaunchDescription([ComposableNodeContainer(name='box', namespace='',\n"
            "        package='rclcpp_components', executable='component_container',\n"
            "        composable_node_descriptions=[ComposableNode(package='pkg',\n"
            "            plugin='pkg::Cam', parameters=['" + str(tmp_path) +
            "/pkg/config/p.yaml'])])])\n")})
    model = load(str(pkg / "launch/c.launch.py"), scan([str(tmp_path)], {}), {}, {})
    assert [(p.pattern, p.key) for p in model.params] == [("/cam", "fps")]
    text, notes = flatten(model, "python")
    assert notes == ["parameter /?:fps for nodes named /cam comes from a component's "
                     "parameter file, not kept as a path; left out"]
    assert "# haros-arch: parameter /?:fps" in text
