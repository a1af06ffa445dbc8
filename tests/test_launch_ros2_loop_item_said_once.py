"""An item of a loop over a value not known statically is said once, where the loop is,
not again at each use. autoware_core's vehicle_info.launch.py sets a global parameter
per item of a vehicle description file of a package not in the workspace, ``for (k, v)
in vehicle_param.items(): SetParameter(name=k, value=v)``: every node after it took the
unknown parameters and said LAUNCH_UNSUPPORTED "unpacking" at its own line (30 times in
autoware_core), which also made each of those launch files look partly unread. A name
unpacked from a value not known takes that value's own unknown."""

from __future__ import annotations

from test_launch_ros2_python import run

BODY = """
import yaml

def setup(context, *args, **kwargs):
    path = LaunchConfiguration('vehicle_info_param_file').perform(context)
    with open(path, 'r') as f:
        params = yaml.safe_load(f)['/**']['ros__parameters']
    return [SetParameter(name=k, value=v) for (k, v) in params.items()]

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('vehicle_info_param_file'),
        OpaqueFunction(function=setup),
        Node(package='p', executable='a', name='a'),
        Node(package='p', executable='b', name='b'),
    ])
"""


def test_the_unknown_items_are_said_at_the_loop_only(write_tree):
    model, root = run(write_tree, BODY)
    assert [n.name for n in model.nodes] == ["/a", "/b"]
    said = [(d.code, d.location.line, d.message) for d in model.diagnostics
            if d.severity in ("warning", "error")]
    lines = (root / "src/pkg/launch/main.launch.py").read_text().splitlines()
    nodes = {i + 1 for i, line in enumerate(lines) if "Node(package" in line}
    assert len(nodes) == 2
    assert not any(line in nodes for _, line, _ in said), said
    # the loop itself is said, once: the value not known (each action the loop makes
    # is under it, which is not said again: "Python test for (k, v) in ...")
    loop = next(i + 1 for i, line in enumerate(lines) if "for (k, v) in" in line)
    assert sorted(m for _, line, m in said if line == loop) == [
        ".items() on a value not known statically"]
