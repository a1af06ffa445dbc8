"""Python's ``eval(text)`` in a launch file, given no globals nor locals, reads the names
of the scope it is called in, as Python does: navigation2's multi-robot test launch file
picks each robot's parameter file with ``eval(f"{robot['name']}_params_file")`` of its
locals ``robot1_params_file`` and ``robot2_params_file``, which was said as "name
'robot1_params_file' is not defined" and left the file unknown."""

from __future__ import annotations

from test_launch_ros2_python import run

BODY = """
def generate_launch_description():
    robot1_params_file = '/params/one.yaml'
    robot2_params_file = '/params/two.yaml'
    nodes = []
    for robot in [{'name': 'robot1'}, {'name': 'robot2'}]:
        params_file = eval(f"{robot['name']}_params_file")
        nodes.append(Node(package='p', executable='e', name=robot['name'] + '_node',
                          parameters=[{'file': params_file, 'twice': eval(' 2 * 3')}]))
    return LaunchDescription(nodes)
"""

BROKEN = """
def generate_launch_description():
    value = eval('1 +')
    missing = eval('nowhere_bound')
    return LaunchDescription([Node(package='p', executable='e', name='n',
                                   parameters=[{'a': value, 'b': missing}])])
"""


def _loud(model):
    return [(d.code, d.message) for d in model.diagnostics
            if d.severity in ("warning", "error")]


def test_eval_reads_the_names_of_its_scope(write_tree):
    model, _ = run(write_tree, BODY)
    assert _loud(model) == []
    params = {p.name: p.value for p in model.params}
    assert params["/robot1_node/file"] == "/params/one.yaml"
    assert params["/robot2_node/file"] == "/params/two.yaml"
    assert params["/robot1_node/twice"] == 6


def test_eval_of_no_expression_is_python_s_error_and_of_an_unbound_name_is_said(write_tree):
    model, _ = run(write_tree, BROKEN)
    messages = [m for _, m in _loud(model)]
    assert any("is no Python expression" in m for m in messages), messages
    # (a file that calls eval may bind names it does not write, `(x := 1)` in a text:
    # not known to be Python's NameError)
    assert any("name nowhere_bound is not defined" in m for m in messages), messages
