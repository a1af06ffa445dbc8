"""The ROS 2 Python API as data: rclpy nodes, actions, QoS, tf2_ros, message_filters.

``NODE_METHODS`` are methods of ``rclpy.node.Node`` (called on ``self`` in a ``Node``
subclass, or on a node made by ``rclpy.create_node`` / ``Node(...)``), keyed by name.
``ROWS`` are functions and classes keyed by (top module, last name), as in ``rospy``.
Argument positions follow rclpy: ``create_publisher(msg_type, topic, qos_profile)``,
``create_subscription(msg_type, topic, callback, qos_profile)``,
``ActionServer(node, action_type, action_name, execute_callback)``.

QoS: an ``int`` is a depth with the default policies; ``QoSProfile(...)`` keywords
override ``DEFAULT_QOS``; ``PRESETS`` are rclpy's predefined profiles.
"""

from __future__ import annotations

from typing import Any

from ...model.source import LIFECYCLE_EVENTS, LIFECYCLE_SERVICES, CallKind
from .api import Arg, NodeName, PyFunction

NODE_METHODS: dict[str, PyFunction] = {
    "create_publisher": PyFunction(
        "publish", name=Arg(1, "topic"), type=Arg(0, "msg_type"), qos=Arg(2, "qos_profile")),
    "create_lifecycle_publisher": PyFunction(
        "publish", name=Arg(1, "topic"), type=Arg(0, "msg_type"), qos=Arg(2, "qos_profile")),
    "create_subscription": PyFunction(
        "subscribe", name=Arg(1, "topic"), type=Arg(0, "msg_type"),
        callback=Arg(2, "callback"), qos=Arg(3, "qos_profile")),
    "create_service": PyFunction(
        "server", name=Arg(1, "srv_name"), type=Arg(0, "srv_type"),
        callback=Arg(2, "callback")),
    "create_client": PyFunction("client", name=Arg(1, "srv_name"), type=Arg(0, "srv_type")),
    "declare_parameter": PyFunction("declare", value=Arg(1, "value")),
    "declare_parameters": PyFunction("declare", name=None, special="declare-parameters"),
    "get_parameter": PyFunction("read"),
    "get_parameter_or": PyFunction("read", value=Arg(1, "alternative_value")),
    "get_parameters": PyFunction("read", name=None, special="parameter-names"),
    # a dict of the parameters under "prefix." ({} when there are none, never an error):
    # an optional read of all of them (``PrimitiveCall.under``), as rclcpp's
    # get_parameters(prefix, map) is read
    "get_parameters_by_prefix": PyFunction("read", name=None, special="parameters-under"),
    "has_parameter": PyFunction("read", tests=True),
    "set_parameters": PyFunction("write", name=None, special="set-parameters"),
    "set_parameters_atomically": PyFunction("write", name=None, special="set-parameters"),
    "undeclare_parameter": PyFunction("write"),
    # AsyncParameterClient: sets the parameters a YAML file names, unknown statically
    "load_parameter_file": PyFunction("write", name=None, fixed_name="?"),
    # AsyncParameterClient only (parameters of another node)
    "delete_parameters": PyFunction("write", name=None, special="parameter-names"),
}

# the node a class of ROWS is made on: its first argument
NODE = Arg(0, "node")

ROWS: dict[tuple[str, str], PyFunction] = {
    ("rclpy", "ActionServer"): PyFunction(
        "action-server", owner=NODE, name=Arg(2, "action_name"), type=Arg(1, "action_type"),
        callback=Arg(3, "execute_callback")),
    ("rclpy", "ActionClient"): PyFunction(
        "action-client", owner=NODE, name=Arg(2, "action_name"), type=Arg(1, "action_type")),
    ("tf2_ros", "TransformBroadcaster"): PyFunction(
        "publish", owner=NODE, name=None, fixed_name="/tf",
        fixed_type="tf2_msgs/msg/TFMessage", fixed_qos="tf"),
    ("tf2_ros", "StaticTransformBroadcaster"): PyFunction(
        "publish", owner=NODE, name=None, fixed_name="/tf_static",
        fixed_type="tf2_msgs/msg/TFMessage", fixed_qos="tf_static"),
    # Buffer(cache_time=None, node=None): given a node, it serves tf2_frames on it
    ("tf2_ros", "Buffer"): PyFunction(
        "server", owner=Arg(1, "node"), name=None, fixed_name="tf2_frames",
        fixed_type="tf2_msgs/srv/FrameGraph", special="tf2-buffer-node"),
    # TransformListener(buffer, node)
    ("tf2_ros", "TransformListener"): PyFunction(
        "subscribe", owner=Arg(1, "node"), name=None, fixed_type="tf2_msgs/msg/TFMessage",
        special="tf-listener"),
    # message_filters.Subscriber(node, msg_type, topic, qos_profile=...)
    ("message_filters", "Subscriber"): PyFunction(
        "subscribe", owner=NODE, name=Arg(2, "topic"), type=Arg(1, "msg_type"),
        qos=Arg(3, "qos_profile")),
    # diagnostic_updater.Updater(node, period=1.0) publishes its status on /diagnostics
    # (as rclcpp's diagnostic_updater::Updater: extract/cpp/api.py)
    ("diagnostic_updater", "Updater"): PyFunction(
        "publish", owner=NODE, name=None, fixed_name="/diagnostics",
        fixed_type="diagnostic_msgs/msg/DiagnosticArray"),
}

_LOGGER = Arg(None, "enable_logger_service")
NODE_NAMES: dict[tuple[str, str], NodeName] = {
    ("rclpy", "create_node"): NodeName(
        Arg(0, "node_name"), namespace=Arg(None, "namespace"), logger_service=_LOGGER),
    ("rclpy", "Node"): NodeName(
        Arg(0, "node_name"), namespace=Arg(None, "namespace"), logger_service=_LOGGER),
    ("rclpy", "LifecycleNode"): NodeName(
        Arg(0, "node_name"), namespace=Arg(None, "namespace"), logger_service=_LOGGER),
}

# the services a node made with ``enable_logger_service=True`` serves
LOGGER_SERVICES = (
    ("~get_logger_levels", "rcl_interfaces/srv/GetLoggerLevels"),
    ("~set_logger_levels", "rcl_interfaces/srv/SetLoggerLevels"),
)

# AsyncParameterClient(node, remote_node_name): its get/set_parameters name that node's
PARAMETER_CLIENT = Arg(1, "remote_node_name")

# rclpy's managed node (``rclpy.lifecycle.Node``, also exported as ``LifecycleNode``)
# publishes its transitions and serves its state machine under its own name, as
# rclcpp_lifecycle's does (``model.source.LIFECYCLE_SERVICES``)
LIFECYCLE_MODULE = "rclpy.lifecycle"
LIFECYCLE_CALLS: tuple[tuple[CallKind, str, str], ...] = (
    ("publish", f"~/{LIFECYCLE_EVENTS[0]}", LIFECYCLE_EVENTS[1]),
    *(("server", f"~/{name}", kind) for name, kind in LIFECYCLE_SERVICES),
)

# classes whose subclasses are nodes: (top module, last name)
NODE_CLASSES = frozenset({("rclpy", "Node"), ("rclpy", "LifecycleNode")})

DEFAULT_QOS: dict[str, Any] = {
    "depth": 10, "history": "keep_last", "reliability": "reliable", "durability": "volatile"}

PRESETS: dict[str, dict[str, Any]] = {
    "qos_profile_default": dict(DEFAULT_QOS),
    "qos_profile_system_default": {
        "depth": None, "history": "system_default", "reliability": "system_default",
        "durability": "system_default"},
    "qos_profile_sensor_data": {
        "depth": 5, "history": "keep_last", "reliability": "best_effort",
        "durability": "volatile"},
    "qos_profile_services_default": dict(DEFAULT_QOS),
    "qos_profile_parameters": {**DEFAULT_QOS, "depth": 1000},
    "qos_profile_parameter_events": {**DEFAULT_QOS, "depth": 1000},
    "qos_profile_action_status_default": {
        "depth": 1, "history": "keep_last", "reliability": "reliable",
        "durability": "transient_local"},
    "qos_profile_best_available": {
        "depth": 10, "history": "keep_last", "reliability": "best_available",
        "durability": "best_available"},
    # tf2_ros broadcasters
    "tf": {**DEFAULT_QOS, "depth": 100},
    "tf_static": {**DEFAULT_QOS, "depth": 1, "durability": "transient_local"},
}

# QoSPresetProfiles.<NAME>.value
PRESET_ENUM: dict[str, str] = {
    "DEFAULT": "qos_profile_default",
    "SYSTEM_DEFAULT": "qos_profile_system_default",
    "SENSOR_DATA": "qos_profile_sensor_data",
    "SERVICES_DEFAULT": "qos_profile_services_default",
    "PARAMETERS": "qos_profile_parameters",
    "PARAMETER_EVENTS": "qos_profile_parameter_events",
    "ACTION_STATUS_DEFAULT": "qos_profile_action_status_default",
    "BEST_AVAILABLE": "qos_profile_best_available",
}

# QoSProfile keywords that take a policy, and the policy words they accept
POLICIES: dict[str, tuple[str, ...]] = {
    "history": ("keep_last", "keep_all", "system_default", "unknown"),
    "reliability": ("reliable", "best_effort", "best_available", "system_default", "unknown"),
    "durability": ("volatile", "transient_local", "best_available", "system_default",
                   "unknown"),
}
