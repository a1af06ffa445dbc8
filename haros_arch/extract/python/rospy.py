"""The ROS 1 Python API as data: rospy, rosparam, actionlib, tf / tf2_ros, message_filters.

Rows are keyed by (top module, last name): ``("rospy", "Publisher")`` serves
``rospy.Publisher``, ``rospy.topics.Publisher`` and ``from rospy import Publisher``.
Argument positions follow the rospy signatures, e.g.
``Publisher(name, data_class, subscriber_listener, tcp_nodelay, latch, headers,
queue_size)`` and ``Subscriber(name, data_class, callback, callback_args, queue_size)``.
"""

from __future__ import annotations

from ...model.source import RECONFIGURE_SERVICE
from .api import Arg, NodeName, PyFunction

_PARAM_NAME = Arg(0, "param_name")

ROWS: dict[tuple[str, str], PyFunction] = {
    # topics
    ("rospy", "Publisher"): PyFunction(
        "publish", type=Arg(1, "data_class"), queue=Arg(6, "queue_size"),
        latch=Arg(4, "latch")),
    ("rospy", "Subscriber"): PyFunction(
        "subscribe", type=Arg(1, "data_class"), queue=Arg(4, "queue_size"),
        callback=Arg(2, "callback")),
    ("rospy", "wait_for_message"): PyFunction(
        "subscribe", name=Arg(0, "topic"), type=Arg(1, "topic_type")),
    # services
    ("rospy", "Service"): PyFunction(
        "server", type=Arg(1, "service_class"), callback=Arg(2, "handler")),
    ("rospy", "ServiceProxy"): PyFunction("client", type=Arg(1, "service_class")),
    ("rospy", "wait_for_service"): PyFunction("client", name=Arg(0, "service")),
    # parameters
    ("rospy", "get_param"): PyFunction("read", name=_PARAM_NAME, value=Arg(1, "default")),
    ("rospy", "get_param_cached"): PyFunction(
        "read", name=_PARAM_NAME, value=Arg(1, "default")),
    ("rospy", "has_param"): PyFunction("read", name=_PARAM_NAME, tests=True),
    ("rospy", "search_param"): PyFunction("read", name=_PARAM_NAME, search=True),
    ("rospy", "set_param"): PyFunction(
        "write", name=_PARAM_NAME, value=Arg(1, "param_value")),
    ("rospy", "delete_param"): PyFunction("write", name=_PARAM_NAME, deletes=True),
    # rosparam's Python API (``import rosparam``): the master's parameter calls, the name
    # as given (relative to the process's namespace, as a node's own relative names are);
    # set_param parses its value as YAML text, so its type is not the argument's
    ("rosparam", "get_param"): PyFunction("read", name=Arg(0, "param")),
    ("rosparam", "set_param_raw"): PyFunction(
        "write", name=Arg(0, "param"), value=Arg(1, "value")),
    ("rosparam", "set_param"): PyFunction("write", name=Arg(0, "param")),
    ("rosparam", "delete_param"): PyFunction("write", name=Arg(0, "param"), deletes=True),
    # actions (actionlib; the action type is the spec's name without "Action")
    ("actionlib", "SimpleActionServer"): PyFunction(
        "action-server", type=Arg(1, "ActionSpec"), callback=Arg(2, "execute_cb")),
    ("actionlib", "ActionServer"): PyFunction(
        "action-server", name=Arg(0, "ns"), type=Arg(1, "ActionSpec"),
        callback=Arg(2, "goal_cb")),
    ("actionlib", "SimpleActionClient"): PyFunction(
        "action-client", name=Arg(0, "ns"), type=Arg(1, "ActionSpec")),
    ("actionlib", "ActionClient"): PyFunction(
        "action-client", name=Arg(0, "ns"), type=Arg(1, "ActionSpec")),
    # transforms
    ("tf2_ros", "TransformBroadcaster"): PyFunction(
        "publish", name=None, fixed_name="/tf", fixed_type="tf2_msgs/TFMessage"),
    ("tf2_ros", "StaticTransformBroadcaster"): PyFunction(
        "publish", name=None, fixed_name="/tf_static", fixed_type="tf2_msgs/TFMessage",
        fixed_latch=True),
    ("tf2_ros", "TransformListener"): PyFunction(
        "subscribe", name=None, fixed_type="tf2_msgs/TFMessage", special="tf-listener"),
    # tf2_ros.Buffer(cache_time=None, debug=True) serves ~tf2_frames unless debug=False
    ("tf2_ros", "Buffer"): PyFunction(
        "server", name=None, fixed_name="~tf2_frames", fixed_type="tf2_msgs/FrameGraph",
        special="tf2-buffer"),
    ("tf", "TransformBroadcaster"): PyFunction(
        "publish", name=None, fixed_name="/tf", fixed_type="tf2_msgs/TFMessage"),
    ("tf", "TransformListener"): PyFunction(
        "subscribe", name=None, fixed_type="tf2_msgs/TFMessage", special="tf-listener"),
    # message_filters.Subscriber(name, data_class, ...)
    ("message_filters", "Subscriber"): PyFunction("subscribe", type=Arg(1, "data_class")),
    # smach_ros (noetic-devel): ROS states, the action server wrapper and the
    # introspection server, named and typed as actionlib and rospy are
    ("smach_ros", "SimpleActionState"): PyFunction(
        "action-client", name=Arg(0, "action_name"), type=Arg(1, "action_spec")),
    ("smach_ros", "ServiceState"): PyFunction(
        "client", name=Arg(0, "service_name"), type=Arg(1, "service_spec")),
    ("smach_ros", "MonitorState"): PyFunction(
        "subscribe", name=Arg(0, "topic"), type=Arg(1, "msg_type")),
    ("smach_ros", "ActionServerWrapper"): PyFunction(
        "action-server", name=Arg(0, "server_name"), type=Arg(1, "action_spec")),
    # IntrospectionServer(server_name, state, path): <server>/smach/container_init,
    # container_structure and container_status
    ("smach_ros", "IntrospectionServer"): PyFunction(
        "subscribe", name=Arg(0, "server_name"),
        fixed_type="smach_msgs/SmachContainerInitialStatusCmd", special="smach-introspection"),
    # dynamic_reconfigure.server.Server(type, callback, namespace=""): in "~" (or the
    # namespace given), a read of each parameter of the config (its package's
    # cfg/*.cfg), two latched topics and its service
    ("dynamic_reconfigure", "Server"): PyFunction(
        "server", name=None, fixed_type=RECONFIGURE_SERVICE[1],
        callback=Arg(1, "callback"), special="reconfigure-server"),
    # dynamic_reconfigure.client.Client(name, ...): the server's service and topics
    ("dynamic_reconfigure", "Client"): PyFunction(
        "client", fixed_type=RECONFIGURE_SERVICE[1],
        special="reconfigure-client"),
    # bondpy.Bond(topic, id, ...): the bond's heartbeat on the topic given, of bond's
    # Status, both ways (bondpy.py; as bondcpp's)
    ("bondpy", "Bond"): PyFunction(
        "publish", name=Arg(0, "topic"), fixed_type="bond/Status", special="bond"),
    # interactive_markers.InteractiveMarkerServer(topic_ns, server_id="", q_size=100)
    # (noetic-devel interactive_marker_server.py): ``topic_ns + "/update_full"``
    # (latched) and ``topic_ns + "/update"``, queues of 100, and a subscription to
    # ``topic_ns + "/feedback"`` with the queue ``q_size``, as roscpp's server has them
    ("interactive_markers", "InteractiveMarkerServer"): PyFunction(
        "publish", name=Arg(0, "topic_ns"), queue=Arg(2, "q_size"),
        fixed_type="visualization_msgs/InteractiveMarkerUpdate",
        special="interactive-marker-server"),
    # diagnostic_updater.Updater() publishes its status on /diagnostics (as roscpp's)
    ("diagnostic_updater", "Updater"): PyFunction(
        "publish", name=None, fixed_name="/diagnostics",
        fixed_type="diagnostic_msgs/DiagnosticArray"),
}

NODE_NAMES: dict[tuple[str, str], NodeName] = {
    ("rospy", "init_node"): NodeName(Arg(0, "name"), anonymous=Arg(2, "anonymous")),
}
