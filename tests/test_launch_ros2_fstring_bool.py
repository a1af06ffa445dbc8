"""A bool in an f-string of a ROS 2 Python launch file (reachy2_core's reachy.launch.py
computes ``fake_py = LaunchConfiguration("fake").perform(context) == "true"`` and starts
its controllers under ``IfCondition(PythonExpression(f"not {fake_py} and not
{gazebo_py}"))``): Python writes ``True`` or ``False``, so the condition is known at the
arguments' defaults; it was LAUNCH_UNSUPPORTED "bool in a string" and the condition
undecided. ``"x" + True`` stays the TypeError Python raises."""

from __future__ import annotations

from test_launch_ros2_python import codes, run

BODY = """
def launch_setup(context, *args, **kwargs):
    fake = LaunchConfiguration('fake').perform(context) == 'true'
    sim = LaunchConfiguration('sim').perform(context) == 'true'
    return [
        Node(package='p', executable='e', name='real_only',
             condition=IfCondition(PythonExpression(f"not {fake} and not {sim}"))),
        Node(package='p', executable='e', name='fake_only',
             condition=IfCondition(PythonExpression(f"{fake}"))),
        Node(package='p', executable='e', name='probe',
             parameters=[{'text': f"sim={sim}"}]),
    ]

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('fake', default_value='false'),
        DeclareLaunchArgument('sim', default_value='false'),
        OpaqueFunction(function=launch_setup),
    ])
"""


def test_a_bool_in_an_f_string_is_its_python_text(write_tree):
    model, _ = run(write_tree, BODY)
    assert "LAUNCH_UNSUPPORTED" not in codes(model), [
        d.message for d in model.diagnostics]
    assert sorted(n.name for n in model.nodes) == ["/probe", "/real_only"]
    values = {p.name: p.value for p in model.params}
    assert values.get("/probe/text") == "sim=False"


def test_a_bool_added_to_a_string_is_no_text(write_tree):
    body = BODY.replace('f"sim={sim}"', '"sim=" + sim')
    model, _ = run(write_tree, body)
    values = {p.name: p.value for p in model.params}
    assert values.get("/probe/text") != "sim=False"
