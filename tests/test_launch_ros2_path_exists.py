"""``os.path.exists`` / ``isfile`` / ``isdir`` in a Python launch file, of a path in a
package folder of the workspace (raspimouse_ros2_examples' teleop_joy.launch.py loads
``config/joy_<joyconfig>.yml`` only when it exists): true when the package holds it,
the ``if`` taking its path alone; any other path (outside the workspace's packages, or
one the package does not hold) is not known here (an info, LAUNCH_UNKNOWN_VALUE, not an
unsupported call), and the ``if`` takes both branches. The launch file is never run:
no path outside the workspace is looked at."""

from __future__ import annotations

from test_launch_ros2_python import codes, run

BODY = """
import os
from os.path import isdir, isfile
from ament_index_python.packages import get_package_share_directory

def generate_launch_description():
    share = get_package_share_directory('pkg')
    nodes = []
    for name in ('joy_f710', 'joy_dualshock3'):
        path = os.path.join(share, 'config', name + '.yml')
        if os.path.exists(path) and isfile(path) and isdir(os.path.join(share, 'config')):
            nodes.append(Node(package='pkg', executable='teleop', name=name,
                              parameters=[path]))
        else:
            nodes.append(Node(package='pkg', executable='teleop', name=name + '_default'))
    if os.path.exists('/dev/input/js0'):
        nodes.append(Node(package='pkg', executable='joy', name='joy'))
    return LaunchDescription(nodes)
"""


def test_a_file_a_package_of_the_workspace_holds_exists(write_tree):
    model, _ = run(write_tree, BODY, extra={
        "src/pkg/config/joy_f710.yml": "joy_f710:\n  ros__parameters:\n    axis: 1\n"})
    # the file the package holds: its path alone; the one it does not hold, and a
    # device outside the workspace: both paths, each under its test
    assert [n.name for n in model.nodes] == [
        "/joy_f710", "/joy_dualshock3", "/joy_dualshock3_default", "/joy"]
    # (the file not held, loaded on its path: what it sets is not known)
    assert [p.name for p in model.params] == ["/joy_f710/axis", "/joy_dualshock3/?"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    assert "LAUNCH_UNKNOWN_VALUE" in codes(model)


PATHLIB = """
from pathlib import Path
from ament_index_python.packages import get_package_share_directory, get_package_share_path

def generate_launch_description():
    config = Path(get_package_share_directory('pkg'), 'config', 'joy_f710.yml')
    assert config.is_file()
    assert config.parent.is_dir() and config.exists()
    nodes = [Node(package='pkg', executable='teleop', name='teleop', parameters=[config])]
    if (get_package_share_path('pkg') / 'config' / 'extra.yml').is_file():
        nodes.append(Node(package='pkg', executable='extra', name='extra'))
    return LaunchDescription(nodes)
"""


def test_pathlib_tests_of_a_path_the_workspace_holds(write_tree):
    """roverrobotics_driver's launch files ``assert hardware_config.is_file()`` of a
    ``pathlib.Path`` of a file of the package: true here, as ``os.path.isfile`` of its
    text (it was LAUNCH_PY_UNSUPPORTED); a file the package does not hold is not known,
    the ``if`` taking both branches."""
    model, _ = run(write_tree, PATHLIB, extra={
        "src/pkg/config/joy_f710.yml": "teleop:\n  ros__parameters:\n    axis: 1\n"})
    assert [n.name for n in model.nodes] == ["/teleop", "/extra"]
    assert [p.name for p in model.params] == ["/teleop/axis"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    assert "LAUNCH_PY_FAILED" not in codes(model)
