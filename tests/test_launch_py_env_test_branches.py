"""A Python ``if`` over an environment variable the configuration does not set, whose
branches set a name to different values: Eurobot-2026-Main's startup_launch.py:12-28
(``ros_domain_id = os.getenv('ROS_DOMAIN_ID')``, then ``if ros_domain_id == '11':
robot_config_name = 'robot_config_white.yaml'`` ``elif ... == '13'`` ... ``else``) and
the file name given to the node as its parameter file. The variable is said where it is
read (LAUNCH_UNKNOWN_VALUE, an info) and the test over it says no more; but the name
after the ``if`` was "robot_config_name, set in both branches (a test not known
statically)", a LAUNCH_UNSUPPORTED warning at its use, for the same cause. Now it is
unknown for that said cause and says no more either: the file, not known, is said as a
parameter file made of an unset variable is (``os.getenv(...) + '.yaml'``)."""

from __future__ import annotations

from conftest import package_xml
from test_launch_ros2_python import run

from haros_arch.launch import load
from haros_arch.workspace import scan

LAUNCH = '''import os
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    src_dir = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
    ros_domain_id = os.getenv('ROS_DOMAIN_ID')
    if ros_domain_id == '11':
        robot_config_name = 'robot_config_white.yaml'
    elif ros_domain_id == '13':
        robot_config_name = 'robot_config_black.yaml'
    else:
        robot_config_name = 'robot_config_default.yaml'
    direct = os.getenv('ROBOT_CONFIG') + '.yaml'
    return LaunchDescription([
        Node(package='pkg', executable='startup', name='startup_node',
             parameters=[os.path.join(src_dir, 'params', robot_config_name)]),
        Node(package='pkg', executable='other', name='other',
             parameters=[os.path.join(src_dir, 'params', direct)])])
'''

PARAMS = "/**:\n  ros__parameters:\n    side: {side}\n"


def said(model):
    return sorted((d.code, d.severity, d.location.line) for d in model.diagnostics)


def test_branches_over_an_unset_variable_say_no_more_than_the_variable(write_tree):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "src/pkg/launch/startup.launch.py": LAUNCH,
                       **{f"src/pkg/params/robot_config_{side}.yaml": PARAMS.format(side=side)
                          for side in ("white", "black", "default")}})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/pkg/launch/startup.launch.py"), ws, {}, {})
    assert said(model) == [("LAUNCH_PARAM_FILE", "warning", 17),
                           ("LAUNCH_PARAM_FILE", "warning", 19),
                           ("LAUNCH_UNKNOWN_VALUE", "info", 8),
                           ("LAUNCH_UNKNOWN_VALUE", "info", 15)], model.diagnostics
    assert "robot_config_?.yaml" in next(d.message for d in model.diagnostics
                                         if d.location.line == 17)
    # the variable set: the branch is decided, its file read
    known = load(str(root / "src/pkg/launch/startup.launch.py"), ws, {},
                 {"ROS_DOMAIN_ID": "13", "ROBOT_CONFIG": "robot_config_white"})
    assert said(known) == []
    assert sorted((p.name, p.value) for p in known.params) == [
        ("/other/side", "white"), ("/startup_node/side", "black")]


UNSAID = """
def nodes(serial):
    if isinstance(serial, TextSubstitution):
        name = 'text_driver'
    else:
        name = 'other_driver'
    return [Node(package='p', executable='a', name=name)]

def generate_launch_description():
    return LaunchDescription(nodes(LaunchConfiguration('serial', default='x')))
"""


def test_branches_over_a_test_nothing_said_of_still_say_it(write_tree):
    # guard: a test whose value says nothing of why (an isinstance of a launch object)
    # leaves the name after it not known "set in both branches", a warning at its use
    model, _ = run(write_tree, UNSAID)
    assert [n.name for n in model.nodes] == ["/?_driver"]
    assert [(d.code, d.message) for d in model.diagnostics] == [
        ("LAUNCH_UNSUPPORTED", "name, set in both branches (a test not known statically)")]
