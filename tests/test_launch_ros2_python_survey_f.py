"""Python launch file shapes met on real workspaces (survey F, 2026-12-06)."""

from __future__ import annotations

from test_launch_ros2_python import run


def test_an_error_under_a_test_not_known_is_not_said_to_happen(write_tree):
    """stereolabs' zed_multi_camera.launch.py: ``serials_arr`` is the empty list of the
    argument's default, the number of cameras is not known, and ``serials_arr[cam_idx]``
    runs only under ``if len(serials_arr) == num_cams``, inside a loop over the cameras:
    with one camera at least, the list then has one. The evaluator, taking both sides of
    the test, indexed the empty list and said "serials_arr[cam_idx] fails: IndexError",
    which the code never does. It is said with the test that may rule those values
    out; an error with no such test around it is still said as Python's."""
    model, _ = run(write_tree, """
import os

def generate_launch_description():
    names = os.environ['CAMERAS'].split(',')
    serials = []
    nodes = []
    idx = 0
    for name in names:
        if len(serials) == len(names):
            serial = serials[idx]
        else:
            serial = '0'
        nodes.append(Node(package='p', executable='cam', name=name,
                          parameters=[{'serial': serial}]))
        idx += 1
    return LaunchDescription(nodes)
""")
    found = [d.message for d in model.diagnostics if "serials[idx]" in d.message]
    assert found, [d.message for d in model.diagnostics]
    assert found == [
        "serials[idx] fails: IndexError: list index out of range, with the values known "
        "here; it runs under len(serials) == len(names), a test not known statically, "
        "which may rule them out"]


def test_an_error_with_no_test_around_it_is_still_said(write_tree):
    model, _ = run(write_tree, """
def generate_launch_description():
    serials = []
    serial = serials[0]
    return LaunchDescription([Node(package='p', executable='cam', name='c')])
""")
    assert [d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"] == [
        "serials[0] fails: IndexError: list index out of range"]
