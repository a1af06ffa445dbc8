"""launch_pal's ``include_launch_py_description(pkg, paths, **kwargs)`` (PAL Robotics'
TIAGo, PMB2 launch files; tiago_simulation's tiago_gazebo.launch.py includes the robot's
spawn, bringup, navigation and MoveIt files so) is the include of the package's launch
file at that path: the file was a call not interpreted, its nodes unseen."""

from __future__ import annotations

from test_launch_ros2_python import run


def test_the_pal_include_is_an_include_of_the_package_s_file(write_tree) -> None:
    model, _ = run(write_tree, """
from launch_pal.include_utils import include_launch_py_description

def generate_launch_description():
    spawn = include_launch_py_description(
        'pkg', ['launch', 'part.launch.py'],
        launch_arguments={'robot': 'tiago'}.items())
    skipped = include_launch_py_description(
        'pkg', ['launch', 'part.launch.py'], condition=IfCondition('false'))
    return LaunchDescription([spawn, skipped])
""", extra={"src/pkg/launch/part.launch.py": HEADER_PART})
    assert [n.name for n in model.nodes] == ["/tiago_spawner"]
    assert "LAUNCH_PY_UNSUPPORTED" not in [d.code for d in model.diagnostics]


HEADER_PART = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='robot'),
        Node(package='spawner', executable='spawn',
             name=[LaunchConfiguration('robot'), '_spawner']),
    ])
"""


def test_pal_argument_helpers_read_and_declare_launch_arguments(write_tree) -> None:
    # TIAGo's launch files: read_launch_argument(name, context) in an OpaqueFunction and
    # get_robot_name('tiago') were calls not interpreted (14 + 4 LAUNCH_PY_UNSUPPORTED in
    # tiago_robot), every value built on them unknown
    model, _ = run(write_tree, """
from launch_pal.arg_utils import read_launch_argument
from launch_pal.robot_utils import get_robot_name

def setup(context, *args, **kwargs):
    robot = read_launch_argument('robot_name', context)
    return [Node(package='drive', executable='base', name=robot + '_base')]

def generate_launch_description():
    return LaunchDescription([get_robot_name('tiago'), OpaqueFunction(function=setup)])
""")
    assert [n.name for n in model.nodes] == ["/tiago_base"]
    assert "LAUNCH_PY_UNSUPPORTED" not in [d.code for d in model.diagnostics]
    model, _ = run(write_tree, """
from launch_pal.arg_utils import read_launch_argument
from launch_pal.robot_utils import get_robot_name

def setup(context, *args, **kwargs):
    return [Node(package='drive', executable='base',
                 name=read_launch_argument('robot_name', context) + '_base')]

def generate_launch_description():
    return LaunchDescription([get_robot_name(), OpaqueFunction(function=setup)])
""", args={"robot_name": "ari"})
    assert [n.name for n in model.nodes] == ["/ari_base"]


ROBOT_ARGUMENTS = """
from launch_pal.arg_utils import read_launch_argument
from launch_pal.robot_utils import get_robot_name, get_arm, get_end_effector, get_ft_sensor

def declare_args(context, *args, **kwargs):
    robot = read_launch_argument('robot_name', context)
    return [get_arm(robot), get_end_effector(robot), get_ft_sensor(robot)]

def setup(context, *args, **kwargs):
    suffix = '_'.join(read_launch_argument(name, context)
                      for name in ('arm', 'end_effector', 'ft_sensor'))
    return [Node(package='teleop', executable='joy', name='joy_' + suffix.replace('-', '_'))]

def generate_launch_description():
    return LaunchDescription([get_robot_name('{robot}'), OpaqueFunction(function=declare_args),
                              OpaqueFunction(function=setup)])
"""


def test_pal_robot_helpers_declare_their_argument_for_the_robot(write_tree) -> None:
    # TIAGo's joystick_teleop.launch.py: get_arm(robot), get_end_effector(robot),
    # get_ft_sensor(robot) were calls not interpreted (3 LAUNCH_PY_UNSUPPORTED per file in
    # tiago_robot) and the parameter file named after their values was not known
    model, _ = run(write_tree, ROBOT_ARGUMENTS.replace("{robot}", "tiago"))
    assert [n.name for n in model.nodes] == ["/joy_tiago_arm_pal_gripper_schunk_ft"]
    assert "LAUNCH_PY_UNSUPPORTED" not in [d.code for d in model.diagnostics]
    model, _ = run(write_tree, ROBOT_ARGUMENTS.replace("{robot}", "tiago"),
                   args={"end_effector": "pal-hey5"})
    assert [n.name for n in model.nodes] == ["/joy_tiago_arm_pal_hey5_schunk_ft"]


def test_a_robot_the_helper_does_not_know_is_said(write_tree) -> None:
    # launch_pal raises ValueError: PMB2 has no arm
    model, _ = run(write_tree, ROBOT_ARGUMENTS.replace("{robot}", "pmb2"))
    said = [d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert any("get_arm('pmb2') raises ValueError" in m for m in said), said
