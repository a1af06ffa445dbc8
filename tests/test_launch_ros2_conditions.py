"""ROS 2 launch conditions: each is decided when its inputs are known (the node is kept
or dropped) and kept on the node as a condition when they are not. Python
(``launch.conditions`` / ``launch.substitutions``) and XML (``if=`` / ``unless=`` with
``$(and)``, ``$(equals)``, ``$(eval)``...) are checked against launch's own rules:
``IfCondition`` takes ``true``/``1``/``false``/``0`` in any case, the boolean
substitutions also YAML's ``yes``/``on``/``off``/``no``, ``EqualsSubstitution`` compares
booleans by truth and numbers by value. ``PythonExpression`` / ``$(eval)`` go through
our bounded evaluator, never ``eval``."""

from __future__ import annotations

from typing import Any

import pytest
from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

PY_HEADER = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import (IfCondition, LaunchConfigurationEquals,
                               LaunchConfigurationNotEquals, UnlessCondition)
from launch.substitutions import (AllSubstitution, AndSubstitution, AnySubstitution,
                                  EqualsSubstitution, IfElseSubstitution,
                                  LaunchConfiguration, NotEqualsSubstitution,
                                  NotSubstitution, OrSubstitution, PythonExpression)
from launch_ros.actions import Node

def node(name, condition):
    return Node(package='p', executable='e', name=name, condition=condition)

def generate_launch_description():
    sim = LaunchConfiguration('sim')
    mode = LaunchConfiguration('mode')
    count = LaunchConfiguration('count')
    robot = LaunchConfiguration('robot')
    return LaunchDescription([
        DeclareLaunchArgument('sim', default_value='True'),
        DeclareLaunchArgument('mode', default_value='nav'),
        DeclareLaunchArgument('count', default_value='2'),
        DeclareLaunchArgument('robot'),
"""

# (node name, Python condition, XML attribute, kept?, conditional?) with sim=True,
# mode=nav, count=2 and robot unset
CASES = [
    ("if_true", "IfCondition(sim)", 'if="$(var sim)"', True, False),
    ("if_false", "IfCondition('0')", 'if="0"', False, False),
    ("unless_true", "UnlessCondition(sim)", 'unless="$(var sim)"', False, False),
    ("if_unknown", "IfCondition(robot)", 'if="$(var robot)"', True, True),
    ("unless_unknown", "UnlessCondition(robot)", 'unless="$(var robot)"', True, True),
    ("cfg_equals", "LaunchConfigurationEquals('mode', 'nav')", None, True, False),
    ("cfg_equals_no", "LaunchConfigurationEquals('mode', 'slam')", None, False, False),
    ("cfg_not_equals", "LaunchConfigurationNotEquals('mode', 'slam')", None, True, False),
    ("cfg_equals_unknown", "LaunchConfigurationEquals('robot', 'r1')", None, True, True),
    ("and_known", "IfCondition(AndSubstitution(sim, 'yes'))",
     'if="$(and $(var sim) yes)"', True, False),
    ("and_false_decides", "IfCondition(AndSubstitution(robot, 'off'))",
     'if="$(and $(var robot) off)"', False, False),
    ("and_unknown", "IfCondition(AndSubstitution(robot, sim))",
     'if="$(and $(var robot) $(var sim))"', True, True),
    ("or_true_decides", "IfCondition(OrSubstitution(robot, '1'))",
     'if="$(or $(var robot) 1)"', True, False),
    ("or_unknown", "IfCondition(OrSubstitution(robot, 'false'))",
     'if="$(or $(var robot) false)"', True, True),
    ("not", "IfCondition(NotSubstitution(sim))", 'if="$(not $(var sim))"', False, False),
    ("not_unknown", "IfCondition(NotSubstitution(robot))", 'if="$(not $(var robot))"',
     True, True),
    ("equals_bool", "IfCondition(EqualsSubstitution(sim, '1'))",
     'if="$(equals $(var sim) 1)"', True, False),
    ("equals_number", "IfCondition(EqualsSubstitution(count, '2.0'))",
     'if="$(equals $(var count) 2.0)"', True, False),
    ("equals_text", "IfCondition(EqualsSubstitution(mode, 'Nav'))",
     'if="$(equals $(var mode) Nav)"', False, False),
    ("not_equals", "IfCondition(NotEqualsSubstitution(mode, 'slam'))",
     'if="$(not-equals $(var mode) slam)"', True, False),
    ("equals_unknown", "IfCondition(EqualsSubstitution(robot, 'r1'))",
     'if="$(equals $(var robot) r1)"', True, True),
    ("any", "IfCondition(AnySubstitution('false', robot, 'on'))",
     'if="$(any false $(var robot) on)"', True, False),
    ("all", "IfCondition(AllSubstitution(sim, 'true', 'no'))",
     'if="$(all $(var sim) true no)"', False, False),
    ("all_unknown", "IfCondition(AllSubstitution(sim, robot))",
     'if="$(all $(var sim) $(var robot))"', True, True),
    ("if_else", "IfCondition(IfElseSubstitution(sim, 'false', 'true'))",
     'if="$(if $(var sim) false true)"', False, False),
    ("expression", "IfCondition(PythonExpression([count, ' > 1 and \\'', mode, "
     "'\\' == \\'nav\\'']))", "if=\"$(eval '$(var count) > 1 and \\'$(var mode)\\' == "
     "\\'nav\\'')\"", True, False),
    ("expression_math", "IfCondition(PythonExpression(['abs(-', count, ') == 2']))",
     "if=\"$(eval 'abs(-$(var count)) == 2' 'math')\"", True, False),
    ("expression_unknown", "IfCondition(PythonExpression(['\\'', robot, "
     "'\\' == \\'r1\\'']))", "if=\"$(eval '\\'$(var robot)\\' == \\'r1\\'')\"", True, True),
    ("expression_never_run", "IfCondition(PythonExpression(\"__import__('os').getpid() "
     "> 0\"))", "if=\"$(eval '__import__(\\'os\\').getpid() > 0')\"", True, True),
]


def load_text(write_tree, name: str, text: str) -> Any:
    root = write_tree({"src/p/package.xml": package_xml("p", "ament_python"),
                       f"src/p/launch/{name}": text})
    workspace = scan([str(root / "src")], {})
    return load(str(root / "src/p/launch" / name), workspace, {}, {})


def python_file() -> str:
    lines = [f"        node('{name}', {cond})," for name, cond, _, _, _ in CASES]
    return PY_HEADER + "\n".join(lines) + "\n    ])\n"


def xml_file() -> str:
    lines = ['<launch>', '  <arg name="sim" default="True"/>',
             '  <arg name="mode" default="nav"/>', '  <arg name="count" default="2"/>',
             '  <arg name="robot"/>']
    lines += [f'  <node pkg="p" exec="e" name="{name}" {attr}/>'
              for name, _, attr, _, _ in CASES if attr]
    return "\n".join([*lines, "</launch>"])


@pytest.mark.parametrize("form", ["python", "xml"])
def test_each_condition_decided_or_kept(write_tree, form: str) -> None:
    if form == "python":
        model = load_text(write_tree, "c.launch.py", python_file())
    else:
        model = load_text(write_tree, "c.launch.xml", xml_file())
    cases = [c for c in CASES if form == "python" or c[2]]
    got = {n.name.lstrip("/"): bool(n.conditions) for n in model.nodes}
    expected = {name: conditional for name, _, _, kept, conditional in cases if kept}
    assert got == expected
    for node in model.nodes:
        for cond in node.conditions:
            statement = "unless" if node.name.startswith("/unless") else "if"
            assert (cond.kind, cond.statement) == ("launch", statement)
            assert cond.location.line == node.location.line
    # the import is refused, not run; the unset argument is reported
    assert "LAUNCH_UNSUPPORTED" in {d.code for d in model.diagnostics}
    assert "LAUNCH_ARG_UNSET" in {d.code for d in model.diagnostics}
    # real launch cannot build $(any)/$(all) from XML (its parse passes args=): an error
    bad = sorted(d.location.line for d in model.diagnostics if d.code == "LAUNCH_BAD_VALUE")
    expected = [] if form == "python" else [
        number for number, line in enumerate(xml_file().splitlines(), 1)
        if 'name="any"' in line or 'name="all' in line]
    assert bad == expected and (form == "python" or len(expected) == 3)


def test_nav2_common_launch_config_as_bool_and_has_node_params(write_tree) -> None:
    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_python"),
        "src/p/config/params.yaml": "slam_toolbox:\n  ros__parameters:\n    mode: mapping\n",
        "src/p/launch/nav.launch.py": """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import PythonExpression
from launch_ros.actions import Node
from nav2_common.launch import HasNodeParams, LaunchConfigAsBool

def generate_launch_description():
    params = os.path.join(get_package_share_directory('p'), 'config', 'params.yaml')
    slam = LaunchConfigAsBool('slam')
    return LaunchDescription([
        DeclareLaunchArgument('slam', default_value='yes'),
        DeclareLaunchArgument('sim'),
        Node(package='p', executable='e', name='slam_node', condition=IfCondition(slam)),
        Node(package='p', executable='e', name='sim_node',
             condition=IfCondition(LaunchConfigAsBool('sim'))),
        Node(package='p', executable='e', name='with_own',
             condition=IfCondition(HasNodeParams(source_file=params,
                                                node_name='slam_toolbox'))),
        Node(package='p', executable='e', name='without_own',
             condition=IfCondition(PythonExpression(['not ', HasNodeParams(
                 source_file=params, node_name='slam_toolbox')]))),
        Node(package='p', executable='e', name='amcl_params',
             condition=IfCondition(HasNodeParams(params, 'amcl'))),
    ])
"""})
    workspace = scan([str(root / "src")], {})
    model = load(str(root / "src/p/launch/nav.launch.py"), workspace, {}, {})
    assert [(n.name, bool(n.conditions)) for n in model.nodes] == [
        ("/slam_node", False), ("/sim_node", True), ("/with_own", False)]
    assert "LAUNCH_PY_UNSUPPORTED" not in {d.code for d in model.diagnostics}
