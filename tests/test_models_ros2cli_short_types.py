"""A ros2cli verb takes a type written ``pkg/Name`` as ``pkg/msg/Name`` (a service's as
``pkg/srv/Name``): rosidl_runtime_py adds the namespace of the interface's kind, and the
topic is typed so on the wire. warehouse_bot's ``ros2 topic pub -t 3 /robot1/initialpose
geometry_msgs/PoseWithCovarianceStamped ...`` publishes the type amcl subscribes with;
kept as written, the two were a possible type mismatch."""

from __future__ import annotations

from haros_arch.launch.model import NodeDecl
from haros_arch.models.commands import command_node


def _call(args: str):
    node = command_node(NodeDecl("/p", "", "ros2", args=args))
    assert node is not None
    (call,) = node.calls
    return call.kind, call.name, call.type


def test_a_short_message_type_is_the_msg_one() -> None:
    assert _call("topic pub -t 3 --qos-reliability reliable /robot1/initialpose "
                 "geometry_msgs/PoseWithCovarianceStamped '{}'") == (
        "publish", "/robot1/initialpose", "geometry_msgs/msg/PoseWithCovarianceStamped")
    assert _call("topic echo /odom nav_msgs/Odometry") == (
        "subscribe", "/odom", "nav_msgs/msg/Odometry")
    # written in full, or a service's: as before
    assert _call("topic pub /cmd geometry_msgs/msg/Twist '{}'") == (
        "publish", "/cmd", "geometry_msgs/msg/Twist")
    assert _call("service call /reset std_srvs/Empty") == (
        "client", "/reset", "std_srvs/srv/Empty")
