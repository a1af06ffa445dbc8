"""A loop over a count an environment variable gives (a drone swarm's
``for i in range(int(os.environ['NUM_DRONES']))``), the variable not set in the
configuration: the variable is said where it is read (an info), and the loop, whose body
is read once for an item not known, is said as an info too, not as a construct the
reader does not interpret (a warning): setting the variable in the configuration's
environment decides it. With it set, the loop runs that many times."""

from __future__ import annotations

from test_launch_ros2_python import run

BODY = """
def generate_launch_description():
    count = int(os.environ['NUM_DRONES'])
    nodes = []
    for i in range(count):
        nodes.append(Node(package='p', executable='drone', name='drone_' + str(i)))
    return LaunchDescription(nodes)
"""


def test_a_loop_over_an_unset_variable_is_an_info(write_tree):
    model, root = run(write_tree, BODY)
    loud = [(d.code, d.message) for d in model.diagnostics
            if d.severity in ("warning", "error")]
    assert loud == []
    lines = (root / "src/pkg/launch/main.launch.py").read_text().splitlines()
    loop = next(i + 1 for i, line in enumerate(lines) if "for i in range" in line)
    (said,) = [d for d in model.diagnostics if d.location.line == loop]
    assert said.code == "LAUNCH_UNKNOWN_VALUE" and said.severity == "info"
    assert "NUM_DRONES" in said.message and "read once" in said.message
    assert [n.name for n in model.nodes] == ["/drone_?"]


def test_with_the_variable_set_the_loop_runs(write_tree):
    model, _ = run(write_tree, BODY, env={"NUM_DRONES": "2"})
    assert sorted(n.name for n in model.nodes) == ["/drone_0", "/drone_1"]
    assert not [d for d in model.diagnostics if d.code.startswith("LAUNCH_")]
