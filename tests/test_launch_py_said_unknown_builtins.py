"""A construct a Python launch file's interpreter does not run is said once, where it is
(LAUNCH_PY_UNSUPPORTED), and its value says no more where it is used. A builtin or an
operator applied to that value made a new unknown that did not remember it was said:
``'robot_' + str(int(subprocess.check_output(...)))`` said the call, then again "int()
of values not known statically" and "str() ..." where the node used the name; a loop
over a value not known said the loop, then ``str(i)`` of its item where the node used
it (drone_autonomous_landing_on_ugv's ``'X500_' + str(i)`` in ``for i in
range(numDrones)``; the loop itself was said again, as ``range()`` of the value made
another unknown). What they compute is unknown through the said construct alone, and
said there only."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

CALL = '''import subprocess
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    serial = subprocess.check_output(['cat', '/etc/robot_id'])
    name = 'robot_' + str(int(serial) + 1)
    return LaunchDescription([Node(package='pkg', executable='drone', name=name)])
'''

LOOP = '''from launch import LaunchDescription
from launch_ros.actions import Node
from helpers import drone_count


def generate_launch_description():
    ld = LaunchDescription()
    for i in range(drone_count()):
        ld.add_action(Node(package='pkg', executable='drone', name='X500_' + str(i)))
    return ld
'''


def said(model):
    return sorted((d.code, d.location.line) for d in model.diagnostics
                  if d.severity != "info")


def test_a_said_unknown_is_not_said_again_through_builtins(write_tree):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "src/pkg/launch/call.launch.py": CALL,
                       "src/pkg/launch/loop.launch.py": LOOP})
    ws = scan([str(root / "src")], {})
    call = load(str(root / "src/pkg/launch/call.launch.py"), ws, {}, {})
    assert said(call) == [("LAUNCH_PY_UNSUPPORTED", 7)], call.diagnostics
    assert [n.name for n in call.nodes] == ["/robot_?"]
    loop = load(str(root / "src/pkg/launch/loop.launch.py"), ws, {}, {})
    assert said(loop) == [("LAUNCH_PY_UNSUPPORTED", 8)], loop.diagnostics
    assert [n.name for n in loop.nodes] == ["/X500_?"]
