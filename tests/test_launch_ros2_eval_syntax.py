"""A ROS 2 ``$(eval ...)`` / ``PythonExpression`` whose text, known whole, is no Python
expression is the SyntaxError launch's ``eval`` raises when it performs it: the launch
fails there (odas_ros' ROS 2 odas.launch.xml kept ROS 1's
``if="$(eval arg('rviz') or arg('force_publish_tf'))"``). It was said as an expression
the tool cannot evaluate (``LAUNCH_UNSUPPORTED``), as if the launch might go on. A text
with unknown parts stays undecided."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

XML = """<launch>
  <arg name="rviz" default="false"/>
  <arg name="other" default="$(env SOMEWHERE_UNSET_HERE)"/>
  <node if="$(eval arg('rviz') or arg('force'))" pkg="p" exec="e" name="a"/>
  <node if="$(eval '2 &gt; 1 and len(&quot;$(var rviz)&quot;) == 5')" pkg="p" exec="e" name="b"/>
  <node if="$(eval '$(var other) +')" pkg="p" exec="e" name="c"/>
</launch>
"""

PY = """
from launch import LaunchDescription
from launch.substitutions import PythonExpression
from launch.conditions import IfCondition
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='e', name='d',
             condition=IfCondition(PythonExpression(['1 ==', ' ']))),
    ])
"""


def _run(write_tree, name: str, text: str):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       f"src/pkg/launch/{name}": text})
    ws = scan([str(root / "src")], {})
    return load(str(root / f"src/pkg/launch/{name}"), ws, {}, {})


def _said(model, code: str) -> list[tuple[int, str]]:
    return [(d.location.line, d.message) for d in model.diagnostics if d.code == code]


def test_an_eval_of_no_python_expression_fails_the_launch(write_tree):
    model = _run(write_tree, "main.launch.xml", XML)
    bad = _said(model, "LAUNCH_BAD_VALUE")
    assert [line for line, _ in bad] == [4], bad
    assert "SyntaxError" in bad[0][1] and "arg(" in bad[0][1], bad
    # a known, well-formed expression is evaluated; one with an unknown part (line 6)
    # is not said to fail (its text is not known)
    kept = {n.name: n.conditions for n in model.nodes}
    assert kept.get("/b") == (), kept


def test_a_python_expression_substitution_of_no_expression_fails_too(write_tree):
    model = _run(write_tree, "main.launch.py", PY)
    bad = _said(model, "LAUNCH_BAD_VALUE")
    assert len(bad) == 1 and "SyntaxError" in bad[0][1], bad
