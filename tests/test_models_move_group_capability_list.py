"""jazzy moveit_ros_move_group's ``list_move_group_capabilities`` makes no ROS call:
its ``main`` (moveit_ros/move_group/src/list_capabilities.cpp:41-56 at the pinned
moveit2 4d841063) builds a ``pluginlib::ClassLoader`` of the capabilities, prints their
declared classes and returns, with no ``rclcpp::init`` and no node. The shipped model
gave it the calls of the libraries it links (the planning scene monitor's
subscriptions, MoveItCpp's and the robot model loader's reads: 129 calls); rebuilt at
the same commit it has none, and ``move_group`` keeps its own interface."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

LAUNCH = """\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='moveit_ros_move_group', executable='{executable}',
             name='{executable}'),
    ])
"""


def _graph(write_tree, executable: str):
    root = write_tree({
        "src/arm/package.xml": package_xml("arm", "ament_python"),
        "src/arm/launch/arm.launch.py": LAUNCH.format(executable=executable),
        "project.yaml": ("project: p\nworkspace: src\ndistro: jazzy\n"
                         "configurations:\n  c: [arm/launch/arm.launch.py]\n"),
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    (node,) = [n for n in config.nodes if n.name == f"/{executable}"]
    return config, node


def test_the_capability_list_program_makes_no_call(write_tree) -> None:
    config, node = _graph(write_tree, "list_move_group_capabilities")
    assert node.node is not None  # the model's program
    assert not node.node.calls
    assert not [link for link in config.links if link.node is node]


def test_move_group_keeps_its_interface(write_tree) -> None:  # a guard
    config, node = _graph(write_tree, "move_group")
    names = {link.resource.name for link in config.links if link.node is node}
    # the planning scene monitor's subscriptions (the override's names) and the
    # trajectory execution manager's controller manager parameter
    assert {"/move_group/joint_states", "/move_group/planning_scene"} <= names or (
        "/joint_states" in names)
    assert "moveit_controller_manager" in {c.name for c in node.node.calls}
