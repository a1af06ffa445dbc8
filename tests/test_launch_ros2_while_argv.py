"""``while`` loops in a Python launch file, and ``sys.argv``.

A ``while`` whose test is known each time it is checked runs its body until the test
fails (within the evaluation's step budget, as every loop), then its ``else`` unless a
``break`` left it; a test not known is said, as before (lexus_bringup's ZED launch file
pads a pose with ``while len(pose) < 6: pose.append('0.0')``).

``sys.argv`` is the command line of ``ros2 launch`` as a user runs the configuration:
``[<ros2>, 'launch', <package>, <file>, 'name:=value', ...]`` (its first item, the
path of the ros2 script, not known here), for the file the configuration starts and
every file it includes. tmr_ros2's launch files copy ``sys.argv[4:]``, the launch
arguments, into the driver's arguments with a ``while`` loop, wheeltec's usb_cam parses
``sys.argv[4:]``: both were LAUNCH_PY_UNSUPPORTED."""

from __future__ import annotations

from test_launch_ros2_python import run

PADDED = """
def generate_launch_description():
    pose = ['1.0', '2.0']
    while len(pose) < 6:
        pose.append('0.0')
    i = 0
    while True:
        i += 1
        if i >= 3:
            break
    else:
        pose = []
    n = 0
    while n < 2:
        n += 1
    else:
        n = 10
    return LaunchDescription([Node(package='p', executable='e', name='n',
                                   arguments=pose + [str(i), str(n)])])
"""


def test_a_while_loop_with_known_tests_runs(write_tree):
    model, _ = run(write_tree, PADDED)
    assert [n.args for n in model.nodes] == ["1.0 2.0 0.0 0.0 0.0 0.0 3 10"]
    assert not any(d.code == "LAUNCH_PY_UNSUPPORTED" for d in model.diagnostics)


def test_a_while_loop_with_a_test_not_known_is_said(write_tree):
    model, _ = run(write_tree, """
import subprocess

def generate_launch_description():
    args = []
    while subprocess.call(['true']) != 0:
        args.append('x')
    return LaunchDescription([Node(package='p', executable='e', name='n', arguments=args)])
""")
    said = [d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert any("while" in m for m in said), said


ARGV = """
import sys

def generate_launch_description():
    args = []
    if len(sys.argv) >= 5:
        i = 4
        while i < len(sys.argv):
            args.append(sys.argv[i])
            i = i + 1
    return LaunchDescription([Node(package='p', executable='e', name=sys.argv[2] + '_node',
                                   arguments=args + sys.argv[1:2] + [sys.argv[3]])])
"""


def test_sys_argv_is_the_ros2_launch_command_line(write_tree):
    model, _ = run(write_tree, ARGV, args={"robot_ip": "10.0.0.2"})
    assert [(n.name, n.args) for n in model.nodes] == [
        ("/pkg_node", "robot_ip:=10.0.0.2 launch main.launch.py")]
    assert not any(d.code in ("LAUNCH_PY_UNSUPPORTED", "LAUNCH_UNSUPPORTED")
                   for d in model.diagnostics), [d.message for d in model.diagnostics]
    model, _ = run(write_tree, ARGV)
    assert [(n.name, n.args) for n in model.nodes] == [
        ("/pkg_node", "launch main.launch.py")]
