"""A ROS 2 launch argument declared that nothing of the whole launch reads by name is
said where it is declared: LAUNCH_ARG_MISSPELT (warning) when a configuration of a near
name is read where nothing has set it (raspimouse_slam_navigation_ros2 e71c388's
pc_navigation.launch.py declared ``use_sim_tim`` (default True) and read
``LaunchConfiguration('use_sim_time', default='False')``, so nav2 and rviz2 ran on wall
time), else LAUNCH_ARG_UNUSED (info). An argument read by an included file, or only
under a condition that does not hold, is used; nothing is said when a part of the launch
is not seen (an include of a file not read), nor when the name is written elsewhere in
the files performed, where an action not interpreted may read it (slam_toolbox's
``EmitEvent(ChangeState(...), condition=IfCondition(autostart))``)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

TOP = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    use_sim_time = LaunchConfiguration('use_sim_time', default='False')
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_tim', default_value='True'),
        DeclareLaunchArgument('robot', default_value='mouse'),
        DeclareLaunchArgument('rviz', default_value='false'),
        DeclareLaunchArgument('rviz_file', default_value='view.rviz'),
        DeclareLaunchArgument('leftover', default_value='1'),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(
            get_package_share_directory(INCLUDED), 'launch', 'inner.launch.py'))),
        Node(package='rviz2', executable='rviz2', condition=IfCondition(
             LaunchConfiguration('rviz')), arguments=['-d', LaunchConfiguration('rviz_file')],
             parameters=[{'use_sim_time': use_sim_time}]),
    ])
"""

INNER = """
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='talker', name=LaunchConfiguration('robot')),
    ])
"""


# the included file declares the name the top file reads, as navigation2's bringup
# declares use_sim_time: too late for the top file's read, which takes its default
DECLARING = INNER.replace(
    "from launch import LaunchDescription",
    "from launch import LaunchDescription\nfrom launch.actions import DeclareLaunchArgument"
).replace(
    "    return LaunchDescription([", """    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        Node(package='demo', executable='listener', parameters=[
             {'use_sim_time': LaunchConfiguration('use_sim_time')}]),""")


# ... and the top file hands it the configuration it reads, as pc_navigation.launch.py
# hands navigation2's bringup its use_sim_time
HANDING = TOP.replace("'launch', 'inner.launch.py')))",
                      "'launch', 'inner.launch.py')),\n"
                      "            launch_arguments={'use_sim_time': use_sim_time}.items())")


def _said(write_tree, included: str, inner: str = INNER, top: str = TOP
          ) -> list[tuple[str, int]]:
    root = write_tree({"src/demo/package.xml": package_xml("demo", "ament_python"),
                       "src/demo/launch/top.launch.py": top.replace("INCLUDED",
                                                                    repr(included)),
                       "src/demo/launch/inner.launch.py": inner})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/demo/launch/top.launch.py"), ws, {}, {})
    return [(d.code, d.severity, d.message, d.location.line) for d in model.diagnostics
            if d.code in ("LAUNCH_ARG_UNUSED", "LAUNCH_ARG_MISSPELT")]


def test_declared_argument_nothing_reads_is_said(write_tree) -> None:
    assert _said(write_tree, "demo") == [
        ("LAUNCH_ARG_MISSPELT", "warning", "launch argument use_sim_tim is declared but "
         "nothing in the launch reads it, and a configuration of a near name is read where "
         "nothing has set it: use_sim_time", 14),
        ("LAUNCH_ARG_UNUSED", "info", "launch argument leftover is declared but nothing in "
         "the launch reads it: its value changes nothing", 18)]


def test_a_near_name_an_include_declares_after_the_read_is_still_misspelt(
        write_tree) -> None:
    said = _said(write_tree, "demo", DECLARING, HANDING)
    assert [(code, line) for code, _, _, line in said] == [
        ("LAUNCH_ARG_MISSPELT", 14), ("LAUNCH_ARG_UNUSED", 18)]


def test_not_said_when_an_include_is_not_read(write_tree) -> None:
    assert _said(write_tree, "not_here") == []


LIFECYCLE = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, EmitEvent
from launch.conditions import IfCondition
from launch.events import matches_action
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import LifecycleNode
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def generate_launch_description():
    autostart = LaunchConfiguration('autostart')
    node = LifecycleNode(package='demo', executable='talker', name='talker', namespace='')
    configure = EmitEvent(
        event=ChangeState(lifecycle_node_matcher=matches_action(node),
                          transition_id=Transition.TRANSITION_CONFIGURE),
        condition=IfCondition(autostart))
    return LaunchDescription([
        DeclareLaunchArgument('autostart', default_value='true'),
        DeclareLaunchArgument('spare', default_value='true'),
        node, configure])
"""


def test_not_said_of_a_name_written_where_an_action_not_interpreted_may_read_it(
        write_tree) -> None:
    root = write_tree({"src/demo/package.xml": package_xml("demo", "ament_python"),
                       "src/demo/launch/life.launch.py": LIFECYCLE})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/demo/launch/life.launch.py"), ws, {}, {})
    assert [(d.code, d.message) for d in model.diagnostics
            if d.code.startswith("LAUNCH_ARG_")] == [
        ("LAUNCH_ARG_UNUSED", "launch argument spare is declared but nothing in the launch "
         "reads it: its value changes nothing")]
