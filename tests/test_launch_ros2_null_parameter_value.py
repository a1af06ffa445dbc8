"""A parameter value made of substitutions whose text is YAML's null: launch_ros reads
such a value's text as YAML (``evaluate_parameter_dict``), and ``''``, ``~`` or ``null``
read as None, which it refuses with a TypeError ("Allowed value types are ..."): ros2
launch stops there. ros_gz_sim's gz_spawn_model.launch.py hands ``x``, ``y``, ... of its
arguments to the create node, and its XML twin gives them ``''``: those were parameters
"set as str ()" that the node reads as doubles. A plain string is dumped as YAML first
(``''`` stays a string), and ParameterValue(value_type=str) keeps the text."""

from __future__ import annotations

from test_launch_ros2_python import run


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
    assert params == {"world": "empty", "label": "", "text": ""}
    refused = sorted(d.message for d in model.diagnostics if d.code == "LAUNCH_BAD_VALUE")
    assert len(refused) == 2
    assert "parameter none of /create" in refused[0] and "TypeError" in refused[0]
    assert "parameter x of /create is given ''" in refused[1]
    # at the node that is given them
    lines = (root / "src/pkg/launch/main.launch.py").read_text().splitlines()
    assert {lines[d.location.line - 1].strip() for d in model.diagnostics
            if d.code == "LAUNCH_BAD_VALUE"} == {
                "Node(package='p', executable='create', name='create',"}
