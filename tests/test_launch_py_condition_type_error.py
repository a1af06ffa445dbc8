"""A ROS 2 Python launch file that makes a condition of a plain bool, or combines two
conditions with an operator, fails when launch loads it: IfCondition normalises its
predicate to substitutions and raises TypeError for a bool, and launch's conditions
define no ``&``. amigo_ros2 edec88a's go2_deploy.launch.py gave rviz2
``IfCondition(LaunchConfiguration('use_rviz')) & IfCondition(mode == 'pose_collection')``,
``mode`` a LaunchConfiguration, whose comparison with a str is Python's False. Both are
said as the TypeError they are (LAUNCH_PY_UNSUPPORTED, as other Python errors of the
file), not as operations on values not known; a condition of text or substitutions is
not."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

PY = """
from launch import LaunchDescription
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    mode = LaunchConfiguration('mode')
    use_rviz = LaunchConfiguration('use_rviz')
    return LaunchDescription([
        Node(package='rviz2', executable='rviz2', name='a',
             condition=IfCondition(use_rviz) & IfCondition(LaunchConfiguration('map'))),
        Node(package='rviz2', executable='rviz2', name='b',
             condition=IfCondition(mode == 'mapping')),
        Node(package='rviz2', executable='rviz2', name='c',
             condition=IfCondition(PythonExpression(["'", mode, "' == 'mapping'"]))),
    ])
"""


def test_conditions_of_a_bool_or_an_operator_are_type_errors(write_tree) -> None:
    root = write_tree({"src/demo/package.xml": package_xml("demo", "ament_python"),
                       "src/demo/launch/view.launch.py": PY})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/demo/launch/view.launch.py"), ws, {}, {})
    said = sorted((d.location.line, d.message) for d in model.diagnostics
                  if d.code == "LAUNCH_PY_UNSUPPORTED" and "TypeError" in d.message)
    assert said == [
        (12, "IfCondition(use_rviz) & IfCondition(LaunchConfiguration('map')) fails: "
             "TypeError: unsupported operand type(s) for &: a launch condition"),
        (14, "IfCondition(mode == 'mapping') fails: TypeError: its predicate is False, a "
             "bool, where launch takes text or substitutions")]
