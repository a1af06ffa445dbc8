"""An assignment expression (``name := value``, PEP 572) in a Python launch file: its
value, bound to the name in the scope around it (in a comprehension, the scope the
comprehension is in). scenario_simulator_v2's scenario_test_runner.launch.py:196 writes
``if (it := collect_vehicle_parameters()) != []: parameters += it``; the reader said
"NamedExpr is not interpreted" and "name it is not defined here" (four warnings) and
the parameters added were not known."""

from __future__ import annotations

from test_launch_ros2_python import codes, run


def test_an_assignment_expression_binds_its_name(write_tree) -> None:
    model, _ = run(write_tree, """
def extra():
    return [{'rate': 10}]

def generate_launch_description():
    parameters = [{'base': 1}]
    if (it := extra()) != []:
        parameters += it
    names = [last for word in ['a', 'b'] if (last := word + '_node')]
    return LaunchDescription([
        Node(package='p', executable='e', name=names[1], parameters=parameters),
        Node(package='p', executable='e', name=last)])
""")
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model), [
        d.message for d in model.diagnostics]
    first, second = model.nodes
    assert (first.name, second.name) == ("/b_node", "/b_node")
    assert {p.name: p.value for p in model.params} == {"/b_node/base": 1, "/b_node/rate": 10}
