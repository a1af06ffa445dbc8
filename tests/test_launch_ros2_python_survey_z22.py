"""Python launch file shapes met on real workspaces (survey Z22, 2026-12-01)."""

from __future__ import annotations

from test_launch_ros2_python import codes, run


def test_isinstance_of_a_known_value_stops_a_flattening_helper(write_tree):
    """panther_ros' welcomeMsg.py: ``flatten(lst)`` recurses while ``isinstance(lst,
    list)``. With isinstance never known, both branches ran, the loop went over a
    string's characters and each one-character string recursed on itself until the call
    depth bound stopped the whole file: no node of the bringup was seen."""
    model, _ = run(write_tree, """
from launch.actions import LogInfo

def flatten(lst):
    if isinstance(lst, list):
        flat = []
        for element in lst:
            flat.extend(flatten(element))
        return flat
    else:
        return [lst]

def generate_launch_description():
    stats = {'Serial': LaunchConfiguration('serial'), 'Site': 'https://example.com'}
    nested = [item for name, value in stats.items() for item in (f'{name}: ', value, '\\n')]
    parts = flatten(nested)
    known = [p for p in parts if isinstance(p, (str, int))]
    return LaunchDescription([LogInfo(msg=parts),
                              Node(package='p', executable='e', name='n', namespace=known[0])])
""")
    assert "LAUNCH_PY_BUDGET" not in codes(model)
    # the first str of the flattened list, 'Serial: ', names the namespace
    [node] = model.nodes
    assert node.name.startswith("/Serial") and node.name.endswith("/n")


def test_isinstance_of_a_value_not_plain_stays_unknown(write_tree):
    """A package path found at launch time stands for a ``str``; a class other than a
    builtin type is not decided: the node exists only under the test."""
    model, _ = run(write_tree, """
from launch.substitutions import TextSubstitution

def generate_launch_description():
    share = get_package_share_directory('not_installed_anywhere')
    nodes = []
    if isinstance(share, str):
        nodes.append(Node(package='p', executable='e', name='a'))
    if isinstance('x', TextSubstitution):
        nodes.append(Node(package='p', executable='e', name='b'))
    if isinstance(3, str):
        nodes.append(Node(package='p', executable='e', name='c'))
    return LaunchDescription(nodes)
""")
    names = {n.name: n for n in model.nodes}
    assert sorted(names) == ["/a", "/b"]
    assert names["/a"].conditions and names["/b"].conditions
