"""Python launch file shapes met on real workspaces (survey Z49, 2026-12-02)."""

from __future__ import annotations

from test_launch_ros2_python import run


def test_an_on_exit_substitution_is_a_bad_value_not_a_callable(write_tree):
    """go2_ros2_sdk's webrtc_web.launch.py gives each node
    ``on_exit=LaunchConfiguration('on_exit', default='shutdown')``: no callable, which
    the warning said it was. launch's OnProcessExit keeps a value that is neither
    callable nor iterable as the one entity to run, and the launch service refuses it
    when the process exits (RuntimeError: expected a LaunchDescriptionEntity); text is
    iterated when the handler is made, each character no entity (TypeError)."""
    model, _ = run(write_tree, """
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessExit

def later(event, context):
    return []

def generate_launch_description():
    on_exit = LaunchConfiguration('on_exit', default='shutdown')
    first = Node(package='p', executable='first', name='first', on_exit=on_exit)
    return LaunchDescription([
        first,
        Node(package='p', executable='second', name='second', on_exit='shutdown'),
        Node(package='p', executable='third', name='third', on_exit=later),
        RegisterEventHandler(OnProcessExit(target_action=first, on_exit=on_exit)),
    ])
""")
    assert sorted(n.name for n in model.nodes) == ["/first", "/second", "/third"]
    # (lines of the file the test helper writes: the launch text starts at line 11)
    said = sorted((d.code, d.location.line, d.message.split(",")[0])
                  for d in model.diagnostics
                  if d.code in ("LAUNCH_BAD_VALUE", "LAUNCH_PY_UNSUPPORTED"))
    assert said == [
        ("LAUNCH_BAD_VALUE", 20, "on_exit is given a substitution"),
        ("LAUNCH_BAD_VALUE", 23, "on_exit is given the text 'shutdown'"),
        ("LAUNCH_BAD_VALUE", 25, "OnProcessExit is given a substitution"),
        ("LAUNCH_PY_UNSUPPORTED", 24, "on_exit with a callable is not interpreted")]
