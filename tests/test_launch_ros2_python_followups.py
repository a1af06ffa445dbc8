"""Python launch file shapes the surveys Z20 and Z22 left (2026-12-01)."""

from __future__ import annotations

from test_launch_ros2_python import codes, run


def test_isinstance_of_a_substitution_is_decided(write_tree):
    """panther_ros' welcomeMsg.py flattens a list holding ``LaunchConfiguration`` and
    ``Command`` objects with a helper recursing while ``isinstance(lst, list)``: no
    substitution is a list (nor any builtin type), and neither is a text made when launch
    runs (a share folder found then), so the helper returns ``[lst]`` for each without
    looping over it. A substitution is an instance of its own launch class
    and of ``Substitution``; a class not read stays not known."""
    model, _ = run(write_tree, """
from launch.actions import LogInfo
from launch.substitutions import Command, LaunchConfiguration, Substitution, TextSubstitution
import launch

def flatten(lst):
    if isinstance(lst, list):
        flat = []
        for element in lst:
            flat.extend(flatten(element))
        return flat
    else:
        return [lst]

def generate_launch_description():
    serial = LaunchConfiguration('serial')
    share = get_package_share_directory('not_installed_anywhere')
    parts = flatten([['Serial: ', serial, '\\n'], Command('ros2 pkg xml -t version p'),
                     [share + '/x']])
    nodes = [LogInfo(msg=parts)]
    if len(parts) == 5:
        nodes.append(Node(package='p', executable='e', name='five'))
    if isinstance(serial, (str, int, float, bool, dict, tuple)):
        nodes.append(Node(package='p', executable='e', name='plain'))
    if isinstance(IfCondition('true'), list):
        nodes.append(Node(package='p', executable='e', name='condition'))
    if isinstance(serial, launch.substitutions.LaunchConfiguration) \\
            and isinstance(serial, (str, Substitution)):
        nodes.append(Node(package='p', executable='e', name='own'))
    if isinstance(serial, TextSubstitution):
        nodes.append(Node(package='p', executable='e', name='other'))
    return LaunchDescription(nodes)
""")
    assert codes(model) == ["LAUNCH_UNSUPPORTED"]  # the test on TextSubstitution only
    names = {n.name: n for n in model.nodes}
    assert sorted(names) == ["/five", "/other", "/own"]
    assert not names["/five"].conditions and not names["/own"].conditions
    assert names["/other"].conditions
