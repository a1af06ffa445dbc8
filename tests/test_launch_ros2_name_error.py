"""A name the launch file's code binds nowhere (sllidar_ros2's sllidar_s2_launch.py reads
``channel_type``, which it never declares nor assigns) is Python's NameError where it is
read: said so, and taken by a ``try`` whose handler catches NameError, as Python does.
A name the file binds somewhere the interpreter does not run, or may bind without
writing it (``globals()``, ``from m import *``), stays "not defined here"."""

from __future__ import annotations

from test_launch_ros2_python import run

UNDEFINED = """
def generate_launch_description():
    port = LaunchConfiguration('serial_port', default='/dev/ttyUSB0')
    return LaunchDescription([
        Node(package='sllidar_ros2', executable='sllidar_node', name='sllidar_node',
             parameters=[{'channel_type': channel_type, 'serial_port': port}]),
    ])
"""

CAUGHT = """
def generate_launch_description():
    try:
        name = robot_name
    except NameError:
        name = 'fallback'
    return LaunchDescription([Node(package='p', executable='e', name=name)])
"""

BOUND_ELSEWHERE = """
def later():
    global channel_type
    channel_type = 'serial'

def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='e', name='n', parameters=[{'c': channel_type}]),
    ])
"""

DYNAMIC = """
globals()['channel_type'] = 'serial'

def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='e', name='n', parameters=[{'c': channel_type}]),
    ])
"""


def _said(model):
    return [(d.code, d.severity, d.message) for d in model.diagnostics
            if d.severity in ("warning", "error")]


def test_a_name_bound_nowhere_is_a_name_error(write_tree):
    model, _ = run(write_tree, UNDEFINED)
    (said,) = _said(model)
    assert said[0] == "LAUNCH_PY_UNSUPPORTED"
    assert "channel_type is not defined anywhere in the file" in said[2]
    assert "NameError" in said[2]


def test_a_handler_of_name_error_takes_it(write_tree):
    model, _ = run(write_tree, CAUGHT)
    assert _said(model) == []
    assert [n.name for n in model.nodes] == ["/fallback"]


def test_a_name_bound_where_the_reader_does_not_run_or_cannot_see_is_not_known(write_tree):
    for body in (BOUND_ELSEWHERE, DYNAMIC):
        model, _ = run(write_tree, body)
        messages = [m for _, _, m in _said(model)]
        assert any("channel_type is not defined here" in m for m in messages), messages
        assert not any("NameError" in m for m in messages), messages
