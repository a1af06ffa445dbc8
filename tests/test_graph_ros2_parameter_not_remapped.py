"""ROS 2 remap rules rename topics and services (and the node's name and namespace),
never a parameter: lbr_fri_ros2_stack starts humble's ``ros2_control_node`` with
``remappings=[("~/robot_description", "robot_description")]`` for the description topic
its manager subscribes to; the manager's read of its own ``robot_description``
parameter was remapped with it, to ``/lbr/robot_description``, a parameter of no node.
A ROS 1 parameter is remapped, as roscpp resolves it with the remappings."""

from __future__ import annotations

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl
from haros_arch.model import Configuration, Node
from haros_arch.model.source import PrimitiveCall
from haros_arch.workspace import Workspace


def _names(version: int) -> dict[str, str]:
    calls = [PrimitiveCall("read", "robot_description" if version == 2
                           else "~robot_description", "str"),
             PrimitiveCall("subscribe", "~/robot_description" if version == 2
                           else "~robot_description", "std_msgs/String")]
    node = Node("controller_manager", "ros2_control_node", calls=calls)
    remap = ("~/robot_description" if version == 2 else "~robot_description",
             "robot_description")
    config = build(Configuration("c"), LaunchModel(nodes=[NodeDecl(
        "/lbr/controller_manager", "controller_manager", "ros2_control_node",
        namespace="/lbr", remaps=[remap], ros_version=version)]), Workspace(root="/nowhere"),
        {node.name: node})
    return {link.kind: link.rosname.full for link in config.links
            if link.kind in ("read", "subscribe")}


def test_a_ros2_parameter_read_is_not_remapped() -> None:
    assert _names(2) == {"read": "/lbr/controller_manager/robot_description",
                         "subscribe": "/lbr/robot_description"}


def test_a_ros1_parameter_read_is_remapped() -> None:
    assert _names(1) == {"read": "/lbr/robot_description",
                         "subscribe": "/lbr/robot_description"}
