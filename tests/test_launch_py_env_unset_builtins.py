"""A ROS 2 Python launch file that computes with an environment variable the
configuration does not set (drone_autonomous_landing_on_ugv cdfdd52,
ros2_px4_swarming/launch/launch_drone.launch.py: ``ID = int(os.environ['DRONE_ID'])``,
then ``namespace='X500_' + str(ID)``; launch_simulation.launch.py: ``if numDrones > 0:``).
The variable is said once where it is read (LAUNCH_UNKNOWN_VALUE, an info: the
configuration's environment may set it); ``int()`` / ``str()`` of it, arithmetic on it
and a test of it were each said again as a construct not interpreted (LAUNCH_UNSUPPORTED
warnings: "int() of values not known statically", "Python test numDrones > 0"), though
nothing else is unknown there. They are unknown through that variable alone and say no
more; a loop over it still says that its body is not run, and a value unknown for
another cause too still warns."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

DRONE = '''import os
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    ld = LaunchDescription()
    ID = int(os.environ['DRONE_ID'])
    MAVSYS_ID = int(os.environ.get('MAVSYS_ID'))
    if MAVSYS_ID == -1:
        MAVSYS_ID = ID + 1
    ld.add_action(Node(package='pkg', executable='drone', namespace='X500_' + str(ID),
                       name='X500_' + str(ID),
                       parameters=[{'ID': ID}, {'MAVSYS_ID': MAVSYS_ID}]))
    count = int(os.environ['NUM_TARGET'])
    if count > 0:
        ld.add_action(Node(package='pkg', executable='target', name='target'))
    return ld
'''

LOOP = '''import os
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    ld = LaunchDescription()
    drones = int(os.environ['NUM_DRONES'])
    for i in range(drones):
        ld.add_action(Node(package='pkg', executable='drone', name='X500_' + str(i)))
    return ld
'''

MIXED = '''import os
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    ld = LaunchDescription()
    ID = int(os.environ['DRONE_ID'])
    ld.add_action(Node(package='pkg', executable='drone',
                       name='X500_' + str(ID + len(open('/x').read()))))
    return ld
'''


def said(model):
    return sorted((d.code, d.severity, d.location.line) for d in model.diagnostics
                  if d.code.startswith("LAUNCH_"))


def test_values_unknown_only_through_unset_variables_say_no_more(write_tree):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "src/pkg/launch/drone.launch.py": DRONE,
                       "src/pkg/launch/loop.launch.py": LOOP,
                       "src/pkg/launch/mixed.launch.py": MIXED})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/pkg/launch/drone.launch.py"), ws, {}, {})
    assert said(model) == [("LAUNCH_UNKNOWN_VALUE", "info", 8),
                           ("LAUNCH_UNKNOWN_VALUE", "info", 9),
                           ("LAUNCH_UNKNOWN_VALUE", "info", 15)], model.diagnostics
    assert sorted(n.name for n in model.nodes) == ["/X500_?/X500_?", "/target"]
    target = next(n for n in model.nodes if n.name == "/target")
    assert target.conditions  # under the test not known, both branches
    # set, the same file has no unknown and no test left open
    known = load(str(root / "src/pkg/launch/drone.launch.py"), ws, {},
                 {"DRONE_ID": "2", "MAVSYS_ID": "-1", "NUM_TARGET": "0"})
    assert said(known) == [] and [n.name for n in known.nodes] == ["/X500_2/X500_2"]
    # a loop over it: its body is read once, for an item not known, which is still
    # said, as an info too (the configuration can set the variable)
    loop = load(str(root / "src/pkg/launch/loop.launch.py"), ws, {}, {})
    assert ("LAUNCH_UNKNOWN_VALUE", "info", 9) in said(loop)
    assert not any(s == "warning" for _, s, _ in said(loop)), said(loop)
    # unknown for another cause too: still a warning
    mixed = load(str(root / "src/pkg/launch/mixed.launch.py"), ws, {}, {})
    assert any(s == "warning" for _, s, _ in said(mixed)), said(mixed)
