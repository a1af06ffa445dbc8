"""jazzy ``move_group`` loads the class its ``moveit_controller_manager`` names
(trajectory_execution_manager.cpp:127-128 at moveit2 4d841063); every MoveIt 2
configuration names ``moveit_simple_controller_manager/MoveItSimpleControllerManager``,
which no ROS 2 model had (PLUGIN_NOT_FOUND, move_group partial for it). Its
``initialize`` (moveit_simple_controller_manager.cpp:102-247) makes, per entry of
``moveit_simple_controller_manager.controller_names``, a FollowJointTrajectory,
GripperCommand or ParallelGripperCommand action client (by its ``type``), named
``<controller>/<action_ns>``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

LAUNCH = """\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='moveit_ros_move_group', executable='move_group',
             parameters=[{
                 'moveit_controller_manager':
                     'moveit_simple_controller_manager/MoveItSimpleControllerManager',
                 'moveit_simple_controller_manager.controller_names': ['arm_controller'],
                 'moveit_simple_controller_manager.arm_controller.type':
                     'FollowJointTrajectory',
                 'moveit_simple_controller_manager.arm_controller.action_ns':
                     'follow_joint_trajectory',
                 'moveit_simple_controller_manager.arm_controller.joints': ['j1'],
             }]),
    ])
"""


def test_jazzy_move_group_loads_the_simple_controller_manager(write_tree) -> None:
    """(fails on main: PLUGIN_NOT_FOUND, no action client)"""
    root = write_tree({
        "src/arm/package.xml": package_xml("arm", "ament_python"),
        "src/arm/launch/arm.launch.py": LAUNCH,
        "project.yaml": ("project: p\nworkspace: src\ndistro: jazzy\n"
                         "configurations:\n  c: [arm/launch/arm.launch.py]\n"),
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    assert not [d for d in config.diagnostics if d.code == "PLUGIN_NOT_FOUND"]
    (node,) = [n for n in config.nodes if n.name == "/move_group"]
    clients = sorted(link.call.type for link in config.links
                     if link.node is node and link.kind == "action-client"
                     and link.call is not None)
    assert clients == ["control_msgs/action/FollowJointTrajectory",
                       "control_msgs/action/GripperCommand",
                       "control_msgs/action/ParallelGripperCommand"]
    # their names come from controller_names and each entry's action_ns, which the
    # model cannot tell apart (makeParameterName's fold): unknown, never invented
    names = {link.resource.name for link in config.links
             if link.node is node and link.kind == "action-client"}
    assert names and all("?" in name for name in names)
    assert not any("MoveItSimpleControllerManager" in reason
                   for reason in (node.node.completeness_reasons if node.node else []))
