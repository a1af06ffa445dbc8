"""A parameter value made of substitutions whose text is YAML's null: launch_ros reads
such a value's text as YAML (``evaluate_parameter_dict``), and ``~``, ``null`` or blanks
read as None, which it refuses with a TypeError ("Allowed value types are ..."): ros2
launch stops there. The empty text is the empty string (launch_ros#300 wraps it in
quotes first, since 2022: Humble on, and the last Foxy and Galactic releases): ros_gz's
gz_spawn_model gives its create node ``x=''``, a string the node's double refuses, a
mismatch that its message says with the value, ``''``. A plain Python string is dumped
as YAML first, and ParameterValue(value_type=str) keeps the text."""

from __future__ import annotations

from test_launch_ros2_python import run

from haros_arch.model import Parameter
from haros_arch.query.catalogue import render
from haros_arch.query.interpreter import Evaluator


def test_substitutions_that_read_as_null_are_refused(write_tree):
    model, root = run(write_tree, """
from launch_ros.parameter_descriptions import ParameterValue

def generate_launch_description():
    x = LaunchConfiguration('x')
    return LaunchDescription([
        DeclareLaunchArgument('x', default_value=''),
        DeclareLaunchArgument('world', default_value='empty'),
        DeclareLaunchArgument('none', default_value='~'),
        Node(package='p', executable='create', name='create',
             parameters=[{'x': x, 'world': LaunchConfiguration('world'),
                          'none': LaunchConfiguration('none'),
                          'label': '', 'text': ParameterValue(x, value_type=str)}]),
    ])
""")
    params = {p.name.rsplit("/", 1)[-1]: p.value for p in model.params}
    assert params == {"x": "", "world": "empty", "label": "", "text": ""}
    refused = [d.message for d in model.diagnostics if d.code == "LAUNCH_BAD_VALUE"]
    assert len(refused) == 1
    assert "parameter none of /create is given '~'" in refused[0] and "TypeError" in refused[0]
    # at the node that is given it
    lines = (root / "src/pkg/launch/main.launch.py").read_text().splitlines()
    assert {lines[d.location.line - 1].strip() for d in model.diagnostics
            if d.code == "LAUNCH_BAD_VALUE"} == {
                "Node(package='p', executable='create', name='create',"}


def test_an_empty_value_is_said_as_one() -> None:
    parameter = Parameter("/create/x", value="")
    text = render("{p.name} is set as str ({p.value})", {"p": parameter}, Evaluator("", {}))
    assert text == "/create/x is set as str ('')"
