"""A ROS 2 ``$(eval ...)`` / ``PythonExpression`` of a known text that names something
launch's ``eval`` does not have is the NameError it raises when it performs it: the
launch fails there. launch evaluates the text with Python's builtins and the names of
``math`` (and the module itself), nothing else: a launch configuration is ``$(var x)``,
not ``x`` (cybership_software_suite's all.launch.xml wrote
``if="$(eval vessel_model == 'drillship')"``). It was said as an expression the tool
cannot evaluate (``LAUNCH_UNSUPPORTED``), as if the launch might go on. A builtin or a
name of math the tool's evaluator does not offer is not said to fail, nor a name of the
``python_modules`` an expression is given."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

XML = """<launch>
  <arg name="vessel_model" default="drillship"/>
  <node if="$(eval vessel_model == 'drillship')" pkg="p" exec="e" name="a"/>
  <node if="$(eval '\\'$(var vessel_model)\\' == \\'drillship\\'')" pkg="p" exec="e" name="b"/>
  <node if="$(eval 'isinstance(1, int) and factorial(3) == 6')" pkg="p" exec="e" name="c"/>
  <node if="$(eval 'numpy.isfinite(1.0)' 'numpy')" pkg="p" exec="e" name="d"/>
  <node if="$(eval 'math.floor(1.5) == 1')" pkg="p" exec="e" name="f"/>
</launch>
"""

PY = """
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch_ros.actions import Node

def generate_launch_description():
    flag = LaunchConfiguration('flag')
    return LaunchDescription([
        DeclareLaunchArgument('flag', default_value='true'),
        Node(package='p', executable='e', name='a',
             condition=IfCondition(PythonExpression([flag, ' and True']))),
        Node(package='p', executable='e', name='b',
             condition=IfCondition(PythonExpression(['np.isfinite(1.0)'],
                                                    python_modules=['numpy as np']))),
    ])
"""


def _run(write_tree, name: str, text: str):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       f"src/pkg/launch/{name}": text})
    ws = scan([str(root / "src")], {})
    return load(str(root / f"src/pkg/launch/{name}"), ws, {}, {})


def _said(model, code: str) -> list[tuple[int, str]]:
    return [(d.location.line, d.message) for d in model.diagnostics if d.code == code]


def test_an_eval_of_a_name_launch_does_not_have_fails_the_launch(write_tree):
    model = _run(write_tree, "main.launch.xml", XML)
    bad = _said(model, "LAUNCH_BAD_VALUE")
    # only line 3: a builtin (isinstance), a name of math (factorial), a name of the
    # expression's modules (numpy), the module math itself: none is said to fail
    assert [line for line, _ in bad] == [3], bad
    assert "NameError" in bad[0][1] and "'vessel_model'" in bad[0][1], bad
    # the same test written with $(var) is evaluated and holds
    kept = {n.name: n.conditions for n in model.nodes}
    assert kept.get("/b") == (), kept


def test_a_python_expression_of_a_bare_lowercase_true_fails_too(write_tree):
    # launch's eval of "true and True": NameError on `true`
    model = _run(write_tree, "main.launch.py", PY)
    bad = _said(model, "LAUNCH_BAD_VALUE")
    assert len(bad) == 1 and "NameError" in bad[0][1] and "'true'" in bad[0][1], bad
