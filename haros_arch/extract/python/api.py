"""The shape of a row of the Python ROS API tables (``rospy``, ``rclpy``).

A row says which call is a ROS primitive and where its values are: each value is an
``Arg`` (the position and keyword it may be given by). Adding an API is adding rows to
``rospy.ROWS`` or ``rclpy.ROWS`` (functions and classes, keyed by their top module and
last name, so ``rospy.Publisher`` and ``rospy.topics.Publisher`` share one row) or to
``rclpy.NODE_METHODS`` (methods of an ``rclpy.node.Node``, keyed by method name).

``special`` names a handler in the visitor for calls that give several primitives or
none from one argument list (``declare_parameters``, ``set_parameters``,
``TransformListener``).
"""

from __future__ import annotations

from dataclasses import dataclass

from ...model.source import CallKind


@dataclass(frozen=True)
class Arg:
    """Where an argument is: its position (None when keyword-only) and its keyword."""

    index: int | None
    keyword: str | None = None


@dataclass(frozen=True)
class PyFunction:
    """How one Python function, class or method maps to a primitive call."""

    kind: CallKind
    name: Arg | None = Arg(0, "name")
    type: Arg | None = None
    queue: Arg | None = None
    latch: Arg | None = None
    qos: Arg | None = None
    callback: Arg | None = None
    # a parameter's value (default, or value set): its Python type is the call's type
    value: Arg | None = None
    fixed_name: str | None = None
    fixed_type: str | None = None
    fixed_latch: bool = False
    fixed_qos: str | None = None  # a QoS preset name, for tf2 broadcasters
    special: str | None = None
    search: bool = False  # the name is searched up the namespaces (rospy.search_param)
    # returns whether the parameter is set (rospy.has_param): a call whose result is a
    # condition handles its absence (``PrimitiveCall.tested``)
    tests: bool = False
    deletes: bool = False  # a parameter write that deletes it (rospy.delete_param)
    owner: Arg | None = None  # rclpy: the node the primitive is made on (``ActionServer(node``)


@dataclass(frozen=True)
class NodeName:
    """A call that names the node (``rospy.init_node``, ``rclpy.create_node``)."""

    name: Arg
    namespace: Arg | None = None
    anonymous: Arg | None = None
    logger_service: Arg | None = None  # rclpy: True gives the node its logger services
