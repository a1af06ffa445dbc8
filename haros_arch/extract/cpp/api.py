"""The ROS C++ APIs as data: which calls are ROS primitives and where their values are.

Adding an API is adding rows. A row is keyed by the qualified name of the class or
namespace that declares the function and the function's name, as libclang sees the
declaration the call refers to (so the same row serves our stand-in headers and the
real ones). A constructor is keyed by its class and the class's own name
(``("tf2_ros::TransformBroadcaster", "TransformBroadcaster")``); it matches a variable
declaration, a ``new``, and ``std::make_shared<T>`` / ``make_unique`` / ``boost::make_shared``.

Type sources (``type_from``), tried in order until one gives a type:

- ``template``: the first explicit template argument of the call
  (``advertise<std_msgs::String>``);
- ``class``: the first template argument of the class the call constructs or is made
  on (``SimpleActionServer<pkg::DoAction>``, ``message_filters::Subscriber<M>``);
- ``callback``: the first parameter of the callback (``const std_msgs::String::ConstPtr&``);
- ``service-callback``: the first parameter of a service callback, a request type
  (``example::GetCounter::Request&`` or ``GetCounterRequest&``) named by its service;
- ``arg``: the type of the argument at ``type_arg`` (``ros::service::call(name, srv)``);
- ``value``: the C++ type of a parameter's value at ``type_arg``, as a parameter type
  (``double``, ``int``, ``str``, ``bool``);
- ``template-value``: the first explicit template argument as a parameter type
  (``nh.param<std::string>(...)``);
- ``type-name``: the string at ``type_arg`` names the type
  (``create_generic_publisher(topic, "std_msgs/msg/String", qos)``);
- ``result``: the parameter type of the value the call returns
  (``declare_parameter<double>("gain")``).

A message type that is a ``rclcpp::TypeAdapter<Custom, Ros>`` (or a custom type one
adapts) is its ROS message type (``call_types``).

``fixed_type`` is a ROS 1 type name used when none of those gives one (image_transport
topics are ``sensor_msgs/Image``); in a ROS 2 node it is written ``pkg/msg/Name``.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from ...model.source import (
    LIFECYCLE_EVENTS,
    LIFECYCLE_SERVICES,
    PLUGINLIB_CLASS,
    RECONFIGURE_SERVICE,
    RECONFIGURE_TOPICS,
    SDF_ELEMENT,
    CallKind,
)

# (kind, name relative to the call's name's namespace or global, or "" for the call's
# own name, ROS 1 type)
Sibling = tuple[CallKind, str, str]
# what a dynamic_reconfigure server publishes beside its service
_RECONFIGURE_TOPICS: tuple[Sibling, ...] = tuple(
    ("publish", topic, type_) for topic, type_ in RECONFIGURE_TOPICS)


@dataclass(frozen=True)
class RosFunction:
    """How one C++ function or constructor maps to a primitive call."""

    kind: CallKind
    name_arg: int = 0
    type_from: tuple[str, ...] = ()
    type_arg: int | None = None
    queue_arg: int | None = None
    latch_arg: int | None = None
    callback_arg: int | None = None
    qos_arg: int | None = None
    # where the namespace comes from: the object of a member call (on_handle), or the
    # argument at handle_arg; with optional_handle, argument 0 is a handle only when its
    # type is one, and the other indexes count from the argument after it
    on_handle: bool = True
    handle_arg: int | None = None
    optional_handle: bool = False
    # a name fixed by the API (tf's "/tf") instead of one read from an argument
    fixed_name: str | None = None
    # a map of every parameter (rclcpp's get_parameter_overrides()): no read where the
    # code only looks one name up in it (``.find(name)``, ``.count(name)``, ``[name]``)
    not_looked_up: bool = False
    # the fixed name is relative to the first argument that is a handle, else to this
    # namespace (dynamic_reconfigure's Server(nh) and Server(mutex, nh), whose handle
    # defaults to NodeHandle("~"))
    handle_default: str | None = None
    fixed_type: str | None = None
    latched: bool = False
    # the ROS action name of a type such as pkg::DoAction is pkg/Do
    action_type: bool = False
    # the default value of a parameter read, for parameter-valued names
    default_arg: int | None = None
    # the variable a parameter read writes its value into
    out_arg: int | None = None
    siblings: tuple[Sibling, ...] = ()
    # a dynamic_reconfigure server: it also reads and writes each parameter of its
    # config (the class's template argument, ``reconfigure``), beside its siblings
    reconfigure: bool = False
    # each of the following calls is made once per element of a list or map argument
    per_element: bool = False
    # overloads that take the name at another index: the first of these indexes whose
    # argument is a string is the name (rclcpp_action's node-interfaces overloads)
    name_candidates: tuple[int, ...] = ()
    # image_transport (``PrimitiveCall.transport``): ``*`` for a publisher, ``?`` for a
    # subscriber whose transport TransportHints read from the node's parameter (``?/``:
    # a ROS 1 Subscriber, which names its transport's topic from the base as written,
    # without resolveName), and the argument that names the transport when the code
    # writes it (ROS 2)
    transport: str | None = None
    transport_arg: int | None = None
    # searchParam: the name is looked up in the enclosing namespaces
    searched: bool = False
    # ROS 1 hasParam, ros::param::has: a read that asks whether the parameter is set,
    # not its value (a namespace so asked reads none of the values under it:
    # ``PrimitiveCall.keys_only``)
    presence: bool = False
    # deleteParam, ros::param::del: a parameter write that deletes it
    deletes: bool = False
    # the call's name is the name argument's then this (a parameter client's remote node
    # + "/get_parameters"); no name argument, or an empty one, is the node's own "~"
    name_suffix: str | None = None
    # the suffix is written after the name argument as it is, not joined as a name (a
    # parameter prefix "async_parameters." + "thread_priority")
    suffix_appended: bool = False
    # a parameter read the library makes with its own default (or only when the
    # parameter is set): has_default, as its siblings' reads
    library_default: bool = False
    # the method's name marks a line as a ROS call site for the recall check
    # (``recall.site_pattern``); not a name as common as realtime_tools' ``initialize``
    # (ros2_control's ``hardware.initialize(params)`` is no ROS call)
    call_site: bool = True
    # with no name argument (none of ``name_candidates`` a string) the call is not one:
    # pal_statistics' getRegistry(key) finds a registry made before, getRegistry(node,
    # topic) makes one
    name_required: bool = False
    # a name written empty makes no call: message_filters::Subscriber(nh, "", q) is a
    # filter its owner feeds through add(); it subscribes only to a topic not empty
    empty_is_none: bool = False
    # the same function as ROS 2's library makes the call, where it differs (a class
    # both have, by one name: camera_info_manager's CameraInfoManager)
    ros2: RosFunction | None = None
    # written before the name argument: a costmap layer's ``declareParameter(name, v)``
    # declares ``<the layer's name>.name``, the layer's name given at run time (``?.``)
    name_prefix: str | None = None
    # roscpp's ros::param::search(key, result) searches from the node's own name
    # (this_node::getName()) up: a relative key given so is first the node's private
    # one (``~key``); its three-argument form names the namespace to start from
    search_from_node: bool = False
    # the row describes our stand-in (of ``standin/fallback`` or ``standin/``: a library
    # installed, not in the workspace): a class of that name declared elsewhere makes no
    # such call (ROS 1 ros_control's ControllerManager: with controller_manager's sources
    # in the workspace its own code is read; ros2_control's is a node of its own;
    # rclcpp_components' ComponentManager)
    standin_only: bool = False
    # ROS 1's library makes no ROS call here, ROS 2's makes the call the row says (filters'
    # FilterBase::getParam: ROS 1 reads the filter's own ``params`` entry)
    ros2_only: bool = False
    # ``name_suffix`` is put after the name argument as a ROS 2 parameter prefix is
    # normalised (filters' ``normalize_param_prefix``): a ``.`` between them unless the
    # prefix is empty or ends with one
    prefix_normalised: bool = False
    # the parameter read or declared names plugin classes the call loads by pluginlib,
    # of this export tag (``PrimitiveCall.loads``)
    loads: str | None = None
    # no ROS call: a value the code reads that the node's host gives (a Gazebo classic
    # plugin's SDF element, ``_sdf->Get<std::string>("topicName")``); a name that holds
    # it takes ``name_prefix`` + its key as its ``name_param``, which the host fills in
    # (``robot.attach``)
    value_only: bool = False
    # a read of the process's ``name:=value`` command-line word, not of a parameter
    # (``PrimitiveCall.argument``); a name that holds it takes ``ROS_ARGUMENT`` + the
    # word's name as its ``name_param``
    argument: bool = False
    # a name roscpp resolves and remaps for the code, no call (``PrimitiveCall.resolved``)
    resolved: bool = False
    # ROS 2: given no node (every argument after the first a ``bool``: tf2_ros'
    # ``TransformListener(buffer)``, ``(buffer, spin_thread)``), the library makes a node
    # of its own with default options, which takes the process's global arguments only:
    # the call is that node's (``PrimitiveCall.handle_origin`` ``process``), not the node
    # of the code around it. ROS 1 (tf2_ros' and tf's listeners): given no handle, the
    # object subscribes on a ``ros::NodeHandle()`` it makes, roscpp's of the process (a
    # nodelet's manager's: ``handle_origin`` ``process``); given one, on that handle
    own_node: bool = False
    # ROS 1: a roscpp free function that takes no handle (ros::param::get / has / ...,
    # ros::service::call) resolves its name as ros::this_node does, the process's node:
    # in a nodelet, its manager's (``PrimitiveCall.handle_origin`` ``process``), so a
    # nodelet's ``ros::param::has("~database")`` asks the manager's private namespace
    # (jsk_robot 6f921c679's LightweightLogger), not the nodelet's
    process_names: bool = False
    # the name when the call gives none (no argument at ``name_arg``): sound_play's
    # ``SoundClient()`` advertises ``robotsound`` on a ``ros::NodeHandle()`` of its own
    # (the node's namespace), ``SoundClient(nh, topic)`` the topic given on ``nh``
    default_name: str | None = None


NODE_HANDLE = "ros::NodeHandle"

_PARAM_READ = RosFunction("read", type_from=("value",), type_arg=1, out_arg=1)
_PARAM_READ_DEFAULT = RosFunction(
    "read", type_from=("template-value", "value"), type_arg=1, out_arg=1, default_arg=2)
_PARAM_WRITE = RosFunction("write", type_from=("value",), type_arg=1)

ROSCPP: dict[tuple[str, str], RosFunction] = {
    # topics
    (NODE_HANDLE, "advertise"): RosFunction(
        "publish", type_from=("template",), queue_arg=1, latch_arg=2),
    (NODE_HANDLE, "subscribe"): RosFunction(
        "subscribe", type_from=("template", "callback"), queue_arg=1, callback_arg=2),
    ("ros::topic", "waitForMessage"): RosFunction(
        "subscribe", type_from=("template",), on_handle=False, handle_arg=1),
    # services
    (NODE_HANDLE, "advertiseService"): RosFunction(
        "server", type_from=("service-callback", "template"), callback_arg=1),
    (NODE_HANDLE, "serviceClient"): RosFunction("client", type_from=("template",)),
    ("ros::service", "createClient"): RosFunction(
        "client", type_from=("template",), on_handle=False, process_names=True),
    ("ros::service", "call"): RosFunction(
        "client", type_from=("arg",), type_arg=1, on_handle=False, process_names=True),
    # getROSArg(argc, argv, "robot"): the value of the program's ``robot:=...`` word
    ("ros", "getROSArg"): RosFunction("read", name_arg=2, on_handle=False,
                                      fixed_type="str", name_required=True, argument=True),
    # a name resolved and remapped for the code (``handle.resolveName(name)`` in the
    # handle's namespace, ``ros::names::resolve(name)`` in the node's): no call, but the
    # remap of that name is one the node uses
    (NODE_HANDLE, "resolveName"): RosFunction(
        "read", name_required=True, call_site=False, resolved=True),
    ("ros::names", "resolve"): RosFunction(
        "read", on_handle=False, name_required=True, call_site=False, resolved=True),
    # parameters through a NodeHandle
    (NODE_HANDLE, "getParam"): _PARAM_READ,
    (NODE_HANDLE, "getParamCached"): _PARAM_READ,
    (NODE_HANDLE, "param"): _PARAM_READ_DEFAULT,
    (NODE_HANDLE, "hasParam"): RosFunction("read", presence=True),
    (NODE_HANDLE, "searchParam"): RosFunction("read", searched=True),
    (NODE_HANDLE, "setParam"): _PARAM_WRITE,
    (NODE_HANDLE, "deleteParam"): RosFunction("write", deletes=True),
    # parameters through ros::param
    ("ros::param", "get"): RosFunction(
        "read", type_from=("value",), type_arg=1, out_arg=1, on_handle=False,
        process_names=True),
    ("ros::param", "getCached"): RosFunction(
        "read", type_from=("value",), type_arg=1, out_arg=1, on_handle=False,
        process_names=True),
    ("ros::param", "param"): RosFunction(
        "read", type_from=("template-value", "value"), type_arg=1, out_arg=1, default_arg=2,
        on_handle=False, process_names=True),
    ("ros::param", "has"): RosFunction("read", on_handle=False, presence=True,
                                       process_names=True),
    ("ros::param", "search"): RosFunction("read", on_handle=False, searched=True,
                                          search_from_node=True, process_names=True),
    ("ros::param", "set"): RosFunction("write", type_from=("value",), type_arg=1,
                                       on_handle=False, process_names=True),
    ("ros::param", "del"): RosFunction("write", on_handle=False, deletes=True,
                                       process_names=True),
}

_IMAGE = "sensor_msgs/Image"
_CAMERA_INFO: tuple[Sibling, ...] = (("publish", "camera_info", "sensor_msgs/CameraInfo"),)
_CAMERA_INFO_IN: tuple[Sibling, ...] = (
    ("subscribe", "camera_info", "sensor_msgs/CameraInfo"),)
_TF = "tf2_msgs/TFMessage"

# message_filters::Subscriber(nh, topic, queue) and its subscribe(...) make one subscription,
# none on an empty topic (ROS 1 and ROS 2 both test topic.empty())
_FILTER_SUBSCRIBER = RosFunction(
    "subscribe", type_from=("class",), on_handle=False, handle_arg=0, name_arg=1,
    queue_arg=2, qos_arg=2, empty_is_none=True)
# image_transport::SubscriberFilter, a message_filters source, and its subscribe(...):
# ROS 1 (it, base_topic, queue_size, hints) subscribes as ImageTransport::subscribe does,
# ROS 2 (node, base_topic, transport, qos, options) as create_subscription does
_IMAGE_FILTER_SUBSCRIBER = RosFunction(
    "subscribe", fixed_type=_IMAGE, on_handle=False, handle_arg=0, name_arg=1, queue_arg=2,
    transport="?/", ros2=RosFunction(
        "subscribe", fixed_type=_IMAGE, on_handle=False, handle_arg=0, name_arg=1,
        qos_arg=3, transport="?", transport_arg=2))
# ROS 1 realtime_tools::RealtimePublisher<M>(nh, topic, queue, latched) and its init(...)
_REALTIME_PUBLISHER = RosFunction(
    "publish", type_from=("class",), on_handle=False, handle_arg=0, name_arg=1,
    queue_arg=2, latch_arg=3)

# Libraries on top of roscpp / rclcpp: actionlib, image_transport, message_filters, tf2_ros


def _base_init(first: str, siblings: tuple[Sibling, ...]) -> RosFunction:
    """The row of a stand-in nodelet base's ``onInit()`` that a nodelet runs
    (``Base::onInit();``): it reads ``~first`` (as roscpp's ``ros::param``, named with
    ``~``) and makes ``siblings``, none at a call site of its own."""
    return RosFunction("read", fixed_name=first, fixed_type="bool", on_handle=False,
                       handle_default="~", call_site=False, library_default=True,
                       standin_only=True, siblings=siblings)


# nodelet_topic_tools' NodeletLazy::onInit() (nodelet_core c86c2cd0's nodelet_lazy.h): it
# reads ``~use_multithread_callback`` through ros::param, then ``~lazy`` and
# ``~verbose_connection`` on the private handle it makes
_LAZY_INIT: tuple[Sibling, ...] = (("read", "lazy", "bool"),
                                   ("read", "verbose_connection", "bool"))
LIBRARIES: dict[tuple[str, str], RosFunction] = {
    # interactive_markers: a server made for the namespace given (argument 0) publishes
    # its updates on ``<ns>/update`` and takes feedback on ``<ns>/feedback``; ROS 1 on a
    # NodeHandle of its own (the node's namespace) with the latched ``<ns>/update_full``
    # (interactive_marker_server.cpp, noetic-devel), ROS 2 on the node given, serving
    # ``<ns>/get_interactive_markers`` (humble on)
    ("interactive_markers::InteractiveMarkerServer", "InteractiveMarkerServer"): RosFunction(
        "publish", on_handle=False, name_suffix="/update", suffix_appended=True,
        fixed_type="visualization_msgs/InteractiveMarkerUpdate", siblings=(
            ("publish", "/update_full", "visualization_msgs/InteractiveMarkerInit"),
            ("subscribe", "/feedback", "visualization_msgs/InteractiveMarkerFeedback")),
        ros2=RosFunction(
            "publish", on_handle=False, name_suffix="/update", suffix_appended=True,
            fixed_type="visualization_msgs/msg/InteractiveMarkerUpdate", siblings=(
                ("subscribe", "/feedback", "visualization_msgs/msg/InteractiveMarkerFeedback"),
                ("server", "/get_interactive_markers",
                 "visualization_msgs/srv/GetInteractiveMarkers")))),
    # laser_proc (ROS 1): LaserTransport::advertiseLaser(nh, queue, ...) makes a
    # LaserPublisher that advertises, on that handle, the multi-echo scan ``echoes`` and
    # the single-echo ``first``, ``last`` and ``most_intense`` (LaserPublisher.cpp; echoes
    # only when its publish_echoes argument is true, its default): urg_node's echoes_pub_
    ("laser_proc::LaserTransport", "advertiseLaser"): RosFunction(
        "publish", fixed_name="echoes", fixed_type="sensor_msgs/MultiEchoLaserScan",
        on_handle=False, handle_default="", queue_arg=1, siblings=tuple(
            ("publish", name, "sensor_msgs/LaserScan")
            for name in ("first", "last", "most_intense"))),
    ("actionlib::SimpleActionServer", "SimpleActionServer"): RosFunction(
        "action-server", type_from=("class",), action_type=True, on_handle=False,
        optional_handle=True),
    ("actionlib::SimpleActionClient", "SimpleActionClient"): RosFunction(
        "action-client", type_from=("class",), action_type=True, on_handle=False,
        optional_handle=True),
    ("actionlib::ActionServer", "ActionServer"): RosFunction(
        "action-server", type_from=("class",), action_type=True, on_handle=False,
        handle_arg=0, name_arg=1),
    ("actionlib::ActionClient", "ActionClient"): RosFunction(
        "action-client", type_from=("class",), action_type=True, on_handle=False,
        optional_handle=True),
    ("rclcpp_action", "create_server"): RosFunction(
        "action-server", type_from=("template",), on_handle=False, name_arg=1,
        name_candidates=(1, 4)),
    ("rclcpp_action", "create_client"): RosFunction(
        "action-client", type_from=("template",), on_handle=False, name_arg=1,
        name_candidates=(1, 4)),
    ("image_transport::ImageTransport", "advertise"): RosFunction(
        "publish", fixed_type=_IMAGE, queue_arg=1, latch_arg=2, transport="*"),
    ("image_transport::ImageTransport", "subscribe"): RosFunction(
        "subscribe", fixed_type=_IMAGE, queue_arg=1, callback_arg=2, transport="?/"),
    ("image_transport::ImageTransport", "advertiseCamera"): RosFunction(
        "publish", fixed_type=_IMAGE, queue_arg=1, latch_arg=2, siblings=_CAMERA_INFO,
        transport="*"),
    ("image_transport::ImageTransport", "subscribeCamera"): RosFunction(
        "subscribe", fixed_type=_IMAGE, queue_arg=1, callback_arg=2, siblings=_CAMERA_INFO_IN,
        transport="?"),
    ("image_transport", "create_publisher"): RosFunction(
        "publish", fixed_type=_IMAGE, on_handle=False, handle_arg=0, name_arg=1,
        transport="*"),
    ("image_transport", "create_subscription"): RosFunction(
        "subscribe", fixed_type=_IMAGE, on_handle=False, handle_arg=0, name_arg=1,
        callback_arg=2, transport="?", transport_arg=3),
    ("image_transport", "create_camera_publisher"): RosFunction(
        "publish", fixed_type=_IMAGE, on_handle=False, handle_arg=0, name_arg=1,
        siblings=_CAMERA_INFO, transport="*"),
    ("image_transport", "create_camera_subscription"): RosFunction(
        "subscribe", fixed_type=_IMAGE, on_handle=False, handle_arg=0, name_arg=1,
        callback_arg=2, siblings=_CAMERA_INFO_IN, transport="?", transport_arg=3),
    # ROS 2's camera ends built from a node, as the two functions above (ROS 1's
    # constructors are ImageTransport's own)
    ("image_transport::CameraPublisher", "CameraPublisher"): RosFunction(
        "publish", fixed_type=_IMAGE, on_handle=False, handle_arg=0, name_arg=1,
        siblings=_CAMERA_INFO, transport="*"),
    ("image_transport::CameraSubscriber", "CameraSubscriber"): RosFunction(
        "subscribe", fixed_type=_IMAGE, on_handle=False, handle_arg=0, name_arg=1,
        callback_arg=2, siblings=_CAMERA_INFO_IN, transport="?", transport_arg=3),
    # nodelet_topic_tools::NodeletLazy's advertise<T>(nh, topic, queue, latch): a
    # publisher on that handle (pcl_ros' and jsk's nodelets publish through it)
    ("nodelet_topic_tools::NodeletLazy", "advertise"): RosFunction(
        "publish", type_from=("template",), on_handle=False, handle_arg=0, name_arg=1,
        queue_arg=2, latch_arg=3),
    # topic_tools' ShapeShifter::advertise(nh, topic, queue, latch): a relay's publisher
    # of the type it received (roscpp's any type), on that handle
    ("topic_tools::ShapeShifter", "advertise"): RosFunction(
        "publish", fixed_type="topic_tools/ShapeShifter", on_handle=False, handle_arg=0,
        name_arg=1, queue_arg=2, latch_arg=3),
    ("nodelet_topic_tools::NodeletLazy", "onInit"): _base_init(
        "use_multithread_callback", _LAZY_INIT),
    ("message_filters::Subscriber", "Subscriber"): _FILTER_SUBSCRIBER,
    ("message_filters::Subscriber", "subscribe"): _FILTER_SUBSCRIBER,
    ("image_transport::SubscriberFilter", "SubscriberFilter"): _IMAGE_FILTER_SUBSCRIBER,
    ("image_transport::SubscriberFilter", "subscribe"): _IMAGE_FILTER_SUBSCRIBER,
    # urdf::Model reads the robot description where searchParam finds it: on the handle
    # given, else in the node's namespace
    ("urdf::Model", "initParamWithNodeHandle"): RosFunction(
        "read", on_handle=False, handle_arg=1, searched=True),
    ("urdf::Model", "initParam"): RosFunction("read", on_handle=False, searched=True),
    # ROS 1 realtime_tools (ros_control's controllers): RealtimePublisher<M>(nh, topic,
    # queue, latched) and init(...) advertise the topic; ROS 2's takes a publisher made
    # before (one argument, no name: no call of its own)
    ("realtime_tools::RealtimePublisher", "RealtimePublisher"): _REALTIME_PUBLISHER,
    ("realtime_tools::RealtimePublisher", "init"): _REALTIME_PUBLISHER,
    ("tf2_ros::TransformBroadcaster", "TransformBroadcaster"): RosFunction(
        "publish", fixed_name="/tf", fixed_type=_TF, on_handle=False),
    ("tf2_ros::StaticTransformBroadcaster", "StaticTransformBroadcaster"): RosFunction(
        "publish", fixed_name="/tf_static", fixed_type=_TF, on_handle=False, latched=True),
    # without a node argument, on a node of its own (``own_node``; ROS 1: on a handle
    # it makes, the process's node's)
    ("tf2_ros::TransformListener", "TransformListener"): RosFunction(
        "subscribe", fixed_name="/tf", fixed_type=_TF, on_handle=False, own_node=True,
        siblings=(("subscribe", "/tf_static", _TF),)),
    # dynamic_reconfigure's server lives in the namespace of the handle it is given (a
    # controller's own controller_nh), by default the node's private one
    ("dynamic_reconfigure::Server", "Server"): RosFunction(
        "server", fixed_name=RECONFIGURE_SERVICE[0], fixed_type=RECONFIGURE_SERVICE[1],
        on_handle=False, handle_default="~", reconfigure=True, siblings=_RECONFIGURE_TOPICS),
    # camera_info_manager (image_common): the calibration service, in ROS 1 in the
    # namespace of the handle given, in ROS 2 the node's own (as from Jazzy on, the
    # rclcpp the stand-ins are: Humble's is relative, "set_camera_info")
    ("camera_info_manager::CameraInfoManager", "CameraInfoManager"): RosFunction(
        "server", fixed_name="set_camera_info", fixed_type="sensor_msgs/SetCameraInfo",
        on_handle=False, handle_default="", ros2=RosFunction(
            "server", fixed_name="~/set_camera_info",
            fixed_type="sensor_msgs/srv/SetCameraInfo", on_handle=False)),
    # diagnostic_updater: ROS 1 reads its period from the private handle; ROS 2 declares
    # it (and, from Iron on, whether names are fully qualified) on the node
    ("diagnostic_updater::Updater", "Updater"): RosFunction(
        "publish", fixed_name="/diagnostics", fixed_type="diagnostic_msgs/DiagnosticArray",
        on_handle=False, siblings=(("read", "~diagnostic_period", "double"),),
        ros2=RosFunction(
            "publish", fixed_name="/diagnostics",
            fixed_type="diagnostic_msgs/msg/DiagnosticArray", on_handle=False,
            siblings=(("declare", "diagnostic_updater.period", "double"),
                      ("declare", "diagnostic_updater.use_fqn", "bool")))),
    # ROS 1 ros_control: the manager a hardware node builds serves the manager's
    # services under ``controller_manager/`` in the namespace of the handle given (by
    # default the node's), where the spawners load controllers into it
    ("controller_manager::ControllerManager", "ControllerManager"): RosFunction(
        "server", fixed_name="controller_manager/load_controller",
        fixed_type="controller_manager_msgs/LoadController", on_handle=False,
        handle_default="", standin_only=True, siblings=tuple(
            ("server", name, f"controller_manager_msgs/{kind}") for name, kind in (
                ("list_controllers", "ListControllers"),
                ("list_controller_types", "ListControllerTypes"),
                ("unload_controller", "UnloadController"),
                ("switch_controller", "SwitchController"),
                ("reload_controller_libraries", "ReloadControllerLibraries")))),
    # bondcpp: a bond exchanges its heartbeat on the topic given (argument 0), of bond's
    # Status, both ways (the sibling named "" is the call's own name); ROS 1 on a
    # NodeHandle of its own (the node's namespace), ROS 2 on the node given
    ("bond::Bond", "Bond"): RosFunction(
        "publish", fixed_type="bond/Status", on_handle=False,
        siblings=(("subscribe", "", "bond/Status"),), ros2=RosFunction(
            "publish", fixed_type="bond/msg/Status", on_handle=False,
            siblings=(("subscribe", "", "bond/msg/Status"),))),
    # realtime_tools (jazzy on): AsyncFunctionHandlerParams::initialize(node, prefix)
    # reads the handler's settings under the prefix (argument 1), each only when the node
    # has it (``has_parameter``), else the struct's default
    ("realtime_tools::AsyncFunctionHandlerParams", "initialize"): RosFunction(
        "read", name_arg=1, on_handle=False, name_suffix="thread_priority",
        suffix_appended=True, library_default=True, fixed_type="int", call_site=False,
        siblings=(("read", "cpu_affinity", "int[]"), ("read", "scheduling_policy", "str"),
                  ("read", "execution_rate", "int"),
                  ("read", "wait_until_initial_trigger", "bool"),
                  ("read", "print_warnings", "bool"))),
    ("tf::TransformBroadcaster", "TransformBroadcaster"): RosFunction(
        "publish", fixed_name="/tf", fixed_type=_TF, on_handle=False),
    # on the handle given, else on one it makes (``own_node``: ROS 1's process's node)
    ("tf::TransformListener", "TransformListener"): RosFunction(
        "subscribe", fixed_name="/tf", fixed_type=_TF, on_handle=False, own_node=True,
        siblings=(("subscribe", "/tf_static", _TF),)),
    # both read tf_prefix with searchParam on a NodeHandle("~") (tf/transform_listener.h)
    ("tf::TransformListener", "resolve"): RosFunction(
        "read", fixed_name="~tf_prefix", on_handle=False, searched=True),
    ("tf", "remap"): RosFunction("read", fixed_name="~tf_prefix", on_handle=False,
                                 searched=True),
    # getPrefixParam(nh) searches tf_prefix from the handle given
    ("tf", "getPrefixParam"): RosFunction("read", fixed_name="tf_prefix", on_handle=False,
                                          handle_default="", searched=True),
}

# rclcpp parameter clients: the services of the remote node they are made for (argument
# 1, 2 or 4 by overload: after the node, the executor and node, or four node interfaces),
# and the parameter events they may subscribe to.
_PARAMETER_SERVICES: tuple[Sibling, ...] = tuple(
    ("client", name, f"rcl_interfaces/srv/{kind}") for name, kind in (
        ("get_parameter_types", "GetParameterTypes"), ("set_parameters", "SetParameters"),
        ("set_parameters_atomically", "SetParametersAtomically"),
        ("describe_parameters", "DescribeParameters"), ("list_parameters", "ListParameters")))
_PARAMETER_CLIENT = RosFunction(
    "client", name_arg=1, name_candidates=(1, 2, 4), on_handle=False,
    name_suffix="get_parameters", fixed_type="rcl_interfaces/srv/GetParameters",
    siblings=_PARAMETER_SERVICES)
_PARAMETER_EVENTS = RosFunction(
    "subscribe", fixed_name="/parameter_events",
    fixed_type="rcl_interfaces/msg/ParameterEvent", on_handle=False)
# pal_statistics: the registry made for a node's topic T (argument 1 of the node overloads,
# 4 of getOrCreateRegistry's interfaces one, 5 of getRegistry's) publishes the statistics
# on T/full, their names on T/names and their values on T/values
_PAL_STATISTICS: tuple[Sibling, ...] = tuple(
    ("publish", part, f"pal_statistics_msgs/msg/{kind}") for part, kind in (
        ("names", "StatisticsNames"), ("values", "StatisticsValues")))
_PAL_REGISTRY = RosFunction(
    "publish", name_arg=1, name_candidates=(1, 4), on_handle=False, name_suffix="full",
    name_required=True, fixed_type="pal_statistics_msgs/msg/Statistics",
    siblings=_PAL_STATISTICS)
RCLCPP_LIBRARIES: dict[tuple[str, str], RosFunction] = {
    ("pal_statistics", "getOrCreateRegistry"): _PAL_REGISTRY,
    ("pal_statistics", "getRegistry"): dataclasses.replace(_PAL_REGISTRY,
                                                           name_candidates=(1, 5)),
    # rclcpp::create_publisher<M>(node, topic, qos, options), as nav2's factories call it
    ("rclcpp", "create_publisher"): RosFunction(
        "publish", type_from=("template",), on_handle=False, name_arg=1, qos_arg=2),
    # (node, topic, qos, callback, ...) or (parameters, topics, topic, qos, callback, ...):
    # the name is the first string of arguments 1 and 2
    ("rclcpp", "create_subscription"): RosFunction(
        "subscribe", type_from=("template", "callback"), on_handle=False, name_arg=1,
        qos_arg=2, callback_arg=3, name_candidates=(1, 2)),
    # (node_base, node_services, name, callback, qos, group), as nav2's ServiceServer
    ("rclcpp", "create_service"): RosFunction(
        "server", type_from=("template",), on_handle=False, name_arg=2),
    # (node_base, node_graph, node_services, name, qos, group)
    ("rclcpp", "create_client"): RosFunction(
        "client", type_from=("template",), on_handle=False, name_arg=3),
    # rclcpp_components' container, built as the base of a class of the workspace
    # (ros2_canopen's DeviceContainer): its constructor serves the container's services
    # on the node (rclcpp_components' component_manager.cpp, a library the node links,
    # whose code is not read with it; with rclcpp_components' sources in the workspace,
    # its own headers and code are read instead)
    ("rclcpp_components::ComponentManager", "ComponentManager"): RosFunction(
        "server", fixed_name="~/_container/load_node",
        fixed_type="composition_interfaces/srv/LoadNode", on_handle=False,
        standin_only=True, siblings=(
            ("server", "~/_container/unload_node", "composition_interfaces/srv/UnloadNode"),
            ("server", "~/_container/list_nodes", "composition_interfaces/srv/ListNodes"))),
    ("rclcpp::AsyncParametersClient", "AsyncParametersClient"): _PARAMETER_CLIENT,
    ("rclcpp::SyncParametersClient", "SyncParametersClient"): _PARAMETER_CLIENT,
    ("rclcpp::AsyncParametersClient", "on_parameter_event"): _PARAMETER_EVENTS,
    ("rclcpp::SyncParametersClient", "on_parameter_event"): _PARAMETER_EVENTS,
    ("rclcpp::ParameterEventHandler", "ParameterEventHandler"): _PARAMETER_EVENTS,
}

# Calls that construct their template argument with the arguments they are given.
FACTORIES = frozenset({("std", "make_shared"), ("std", "make_unique"),
                       ("boost", "make_shared"), ("std", "allocate_shared")})

# Functions that name the node: (scope, function) -> the index of the name argument, for
# each number of written arguments (ros::init(argc, argv, name) and ros::init(remaps, name)).
NODE_NAME: dict[tuple[str, str], dict[int, int]] = {
    ("ros", "init"): {2: 1, 3: 2, 4: 2},
}

# nodelet::Loader's load(name, type, remappings, argv): a nodelet made in this process
# (``CallFinder._nodelet_load``)
NODELET_LOAD = ("nodelet::Loader", "load")

# Classes whose objects are node handles, and functions that return a handle in a fixed
# namespace: (scope, function) -> namespace.
HANDLE_CLASSES = frozenset({NODE_HANDLE, "image_transport::ImageTransport"})
# what tells an image_transport subscriber its transport (``visitor._hints_default``)
IMAGE_HINTS = "image_transport::TransportHints"
HANDLE_FACTORIES: dict[tuple[str, str], str] = {
    ("nodelet::Nodelet", "getNodeHandle"): "",
    ("nodelet::Nodelet", "getMTNodeHandle"): "",
    ("nodelet::Nodelet", "getPrivateNodeHandle"): "~",
    ("nodelet::Nodelet", "getMTPrivateNodeHandle"): "~",
}

# members of a library's base class that hold handles its own code sets: (class, member)
# -> namespace (nodelet_topic_tools::NodeletLazy::onInit() sets nh_ and pnh_ to the
# nodelet's node handle and private node handle)
HANDLE_MEMBERS: dict[tuple[str, str], str] = {
    ("nodelet_topic_tools::NodeletLazy", "nh_"): "",
    ("nodelet_topic_tools::NodeletLazy", "pnh_"): "~",
}

# rclcpp: the same rows for a Node and a LifecycleNode. QoS is the argument at qos_arg:
# a depth, an rclcpp::QoS expression or an rmw_qos_profile_t (see ``qos``).
_RCLCPP_NODE: dict[str, RosFunction] = {
    "create_publisher": RosFunction("publish", type_from=("template",), qos_arg=1),
    "create_subscription": RosFunction(
        "subscribe", type_from=("template", "callback"), qos_arg=1, callback_arg=2),
    "create_service": RosFunction(
        "server", type_from=("template", "service-callback"), callback_arg=1),
    "create_client": RosFunction("client", type_from=("template",)),
    "create_generic_publisher": RosFunction(
        "publish", type_from=("type-name",), type_arg=1, qos_arg=2),
    "create_generic_subscription": RosFunction(
        "subscribe", type_from=("type-name",), type_arg=1, qos_arg=2),
    "declare_parameter": RosFunction(
        "declare", type_from=("template-value", "value", "result"), type_arg=1,
        default_arg=1, on_handle=False),
    # declare_parameters(namespace, map): the map's values are the defaults
    "declare_parameters": RosFunction(
        "declare", type_from=("template-value",), default_arg=1, on_handle=False,
        per_element=True),
    "get_parameter": RosFunction(
        "read", type_from=("value",), type_arg=1, out_arg=1, on_handle=False),
    "get_parameter_or": RosFunction(
        "read", type_from=("value",), type_arg=1, out_arg=1, default_arg=2, on_handle=False),
    "get_parameters": RosFunction("read", on_handle=False, per_element=True),
    "has_parameter": RosFunction("read", on_handle=False),
    # list_parameters({prefix, ...}, depth): the names the node has under each prefix,
    # which the code then reads by them (Autoware's dummy_diag_publisher lists
    # ``required_diags`` and reads ``<name>.is_active``): each prefix's namespace, read
    # whole as get_parameters(prefix, map) reads it
    "list_parameters": RosFunction("read", on_handle=False, per_element=True),
    "set_parameter": RosFunction("write", on_handle=False),
    "set_parameters": RosFunction("write", on_handle=False, per_element=True),
    "set_parameters_atomically": RosFunction("write", on_handle=False, per_element=True),
    "undeclare_parameter": RosFunction("write", on_handle=False),
}
RCLCPP_NODES = ("rclcpp::Node", "rclcpp_lifecycle::LifecycleNode")
# ros2_control: a controller's ``auto_declare<T>(name, default)`` declares the parameter on
# the controller's node (or reads it, declared already), as declare_parameter does
# Autoware's polling subscriber (autoware_utils, autoware_utils_rclcpp): built with the
# node, the topic and a QoS (``sub_{this, "~/input/odometry"}``), or through its static
# ``create_subscription(this, topic, qos)``; the message is the class's argument
_POLLING_SUBSCRIBER = RosFunction(
    "subscribe", type_from=("class",), on_handle=False, name_arg=1, qos_arg=2)
# and its ``get_or_declare_parameter<T>(node, name)``: declared (typed T, no default)
# unless declared already, then read
_GET_OR_DECLARE = RosFunction(
    "declare", type_from=("template-value", "result"), on_handle=False, name_arg=1)
# and three node utilities of the same library (``standin/fallback/autoware_utils/
# haros_node_utilities.h``): the logger level configurator's service on the node it is
# built with, the diagnostics interface's status publisher, and the transform
# listener's tf2 listener (read as tf2_ros' own: the node listens to /tf, /tf_static)
_LOGGER_LEVEL_CONFIGURE = RosFunction(
    "server", fixed_name="~/config_logger", fixed_type="logging_demo/srv/ConfigLogger",
    on_handle=False, handle_arg=0, standin_only=True)
_DIAGNOSTICS_INTERFACE = RosFunction(
    "publish", fixed_name="/diagnostics", fixed_type="diagnostic_msgs/msg/DiagnosticArray",
    on_handle=False, handle_arg=0, standin_only=True)
_AUTOWARE_TF_LISTENER = RosFunction(
    "subscribe", fixed_name="/tf", fixed_type=_TF, on_handle=False, standin_only=True,
    siblings=(("subscribe", "/tf_static", _TF),))
AUTOWARE: dict[tuple[str, str], RosFunction] = {
    **{(f"{scope}::TransformListener", "TransformListener"): _AUTOWARE_TF_LISTENER
       for scope in ("autoware_utils", "autoware_utils_tf")},
    **{(f"{scope}::BasicLoggerLevelConfigure", "BasicLoggerLevelConfigure"):
       _LOGGER_LEVEL_CONFIGURE for scope in ("autoware_utils", "autoware_utils_logging")},
    **{(f"{scope}::BasicDiagnosticsInterface", "BasicDiagnosticsInterface"):
       _DIAGNOSTICS_INTERFACE for scope in ("autoware_utils", "autoware_utils_diagnostics")},
    **{(f"{scope}::InterProcessPollingSubscriber", name): _POLLING_SUBSCRIBER
       for scope in ("autoware_utils", "autoware_utils_rclcpp")
       for name in ("InterProcessPollingSubscriber", "create_subscription")},
    **{(scope, "get_or_declare_parameter"): _GET_OR_DECLARE
       for scope in ("autoware_utils", "autoware_utils_rclcpp")}}
ROS2_CONTROL: dict[tuple[str, str], RosFunction] = {
    ("controller_interface::ControllerInterfaceBase", "auto_declare"):
        _RCLCPP_NODE["declare_parameter"],
}
# navigation2's libraries as their stand-ins (``standin/fallback``: nav2 installed, not in
# the workspace) describe them; with their sources in the workspace, their own code is
# read instead (``standin_only``). ``declare_parameter_if_not_declared(node, name, value)``
# (nav2_util: Humble, Jazzy; nav2: Kilted and later) declares the parameter on the node
# given unless it is declared already, as declare_parameter does; a value that is a
# ParameterType declares it typed, without a default.
_NAV2_DECLARE = dataclasses.replace(
    _RCLCPP_NODE["declare_parameter"], name_arg=1, type_arg=2, default_arg=2,
    standin_only=True)
# ``get_plugin_type_param(node, plugin)``: declares ``<plugin>.plugin``, a string without
# default (it throws when the parameter is not set), and reads it
_NAV2_PLUGIN_TYPE = RosFunction(
    "declare", fixed_type="str", on_handle=False, name_arg=1, name_suffix=".plugin",
    suffix_appended=True, standin_only=True)
# the Kilted lifecycle node's factories: topic first, QoS after the callback
_NAV2_NODE = "nav2::LifecycleNode"
NAV2: dict[tuple[str, str], RosFunction] = {
    **{(scope, "declare_parameter_if_not_declared"): _NAV2_DECLARE
       for scope in ("nav2_util", "nav2")},
    **{(scope, "get_plugin_type_param"): _NAV2_PLUGIN_TYPE for scope in ("nav2_util", "nav2")},
    # declare_or_get_parameter(node, name, default or ParameterType): declared unless it
    # is already, then read (the stand-ins declare only these node-first overloads)
    **{(scope, "declare_or_get_parameter"): _NAV2_DECLARE for scope in ("nav2_util", "nav2")},
    # Humble's and Jazzy's lifecycle node: add_parameter(name, default, ...) declares it
    ("nav2_util::LifecycleNode", "add_parameter"): dataclasses.replace(
        _RCLCPP_NODE["declare_parameter"], standin_only=True),
    # a Humble or Jazzy costmap layer's declareParameter(name, value): on the layer's
    # node, under the layer's name (Layer::getFullName: ``<name_>.<name>``)
    ("nav2_costmap_2d::Layer", "declareParameter"): dataclasses.replace(
        _RCLCPP_NODE["declare_parameter"], name_prefix="?.", standin_only=True),
    (_NAV2_NODE, "declare_or_get_parameter"): dataclasses.replace(
        _RCLCPP_NODE["declare_parameter"], standin_only=True),
    (_NAV2_NODE, "create_publisher"): RosFunction(
        "publish", type_from=("template",), qos_arg=1, standin_only=True),
    (_NAV2_NODE, "create_subscription"): RosFunction(
        "subscribe", type_from=("template", "callback"), callback_arg=1, qos_arg=2,
        standin_only=True),
    (_NAV2_NODE, "create_service"): RosFunction(
        "server", type_from=("template", "service-callback"), callback_arg=1,
        standin_only=True),
    (_NAV2_NODE, "create_client"): RosFunction(
        "client", type_from=("template",), standin_only=True),
    (_NAV2_NODE, "create_action_server"): RosFunction(
        "action-server", type_from=("template",), standin_only=True),
    (_NAV2_NODE, "create_action_client"): RosFunction(
        "action-client", type_from=("template",), standin_only=True),
    # createBond(): a bond with the lifecycle manager on topic bond (bondcpp's Bond)
    **{(f"{scope}::LifecycleNode", "createBond"): RosFunction(
        "publish", fixed_name="bond", fixed_type="bond/msg/Status", on_handle=False,
        standin_only=True, siblings=(("subscribe", "", "bond/msg/Status"),))
       for scope in ("nav2_util", "nav2")},
    # nav2_costmap_2d's FootprintSubscriber(node, topic, tf, ...): the robot's footprint
    # (Humble to Kilted alike; its CostmapSubscriber subscribes to topic_updates too
    # from Jazzy on, so it stays HAROS_UNREAD)
    ("nav2_costmap_2d::FootprintSubscriber", "FootprintSubscriber"): RosFunction(
        "subscribe", fixed_type="geometry_msgs/msg/PolygonStamped", on_handle=False,
        name_arg=1, standin_only=True),
    # Humble's and Jazzy's ServiceClient<S>(name, node[, use_internal_executor]): a client
    # of S on the node (Kilted's nav2::ServiceClient is made by the lifecycle node's
    # create_client, a row above)
    ("nav2_util::ServiceClient", "ServiceClient"): RosFunction(
        "client", type_from=("class",), on_handle=False, name_arg=0, standin_only=True),
    # SimpleActionServer<A>(node, name, execute, ...) serves A on the node
    # (nav2_util's also from four node interfaces, the name after them)
    **{(f"{scope}::SimpleActionServer", "SimpleActionServer"): RosFunction(
        "action-server", type_from=("class",), on_handle=False, name_arg=1,
        name_candidates=(1, 4), standin_only=True) for scope in ("nav2_util", "nav2")},
}
# the ROS package filters (noetic-devel, ros2), as its stand-in (``standin/fallback``:
# installed, not in the workspace) describes it. FilterChain<T>::configure loads the
# filter classes (pluginlib, export tag ``filters``, base filters::FilterBase<T>) its
# parameters name: ROS 1 ``configure(name, nh = NodeHandle())`` reads the list ``name``
# ({name, type, params} entries) on the handle given, by default in the node's namespace
# (each filter reads its ``params`` from its entry: no ROS call; not set, the chain is
# empty: a read with the library's default); ROS 2
# ``configure(prefix, logging, parameters)`` declares and reads ``<prefix>.filter1.name``
# and ``.type``, then filter2, ... up to the first not set, and a filter's
# ``getParam(name, value)`` declares ``<prefix>.filterN.params.<name>`` with its type's
# default (``?.`` until the chain names the filter). MultiChannelFilterChain's take the
# number of channels first.
# jsk_common's jsk_topic_tools as its stand-in (``standin/fallback/jsk_topic_tools``:
# installed, not in the workspace) describes it (jsk_common bfa8d0db): a nodelet's
# ``ConnectionBasedNodelet::onInit()`` reads three private parameters (and
# ``~use_multithread_callback`` through ros::param); ``DiagnosticNodelet::onInit()`` runs
# it, then reads ``~vital_rate``, ``~use_warn`` and ``/diagnostic_nodelet/use_warn`` and
# publishes diagnostics on ``/diagnostics`` through its updater. ``readVectorParameter(nh,
# name, result)`` reads ``name`` on the handle given, typed by ``result``. Its
# ``advertise<T>(nh, topic, queue[, latch])``, ``advertiseImage(nh, topic, queue)`` and
# ``advertiseCamera(nh, topic, queue)`` advertise on the handle given (an image through
# image_transport), having read ``latch`` there.
_JSK_CONNECTION: tuple[Sibling, ...] = (
    ("read", "verbose_connection", "bool"), ("read", "no_warn_on_init_post_process", "bool"),
    ("read", "use_multithread_callback", "bool"))
_JSK_LATCH: tuple[Sibling, ...] = (("read", "latch", "bool"),)
JSK: dict[tuple[str, str], RosFunction] = {
    ("jsk_topic_tools::ConnectionBasedNodelet", "onInit"): _base_init(
        "always_subscribe", _JSK_CONNECTION),
    ("jsk_topic_tools::DiagnosticNodelet", "onInit"): _base_init(
        "always_subscribe", (*_JSK_CONNECTION, ("read", "vital_rate", "double"),
                             ("read", "use_warn", "bool"),
                             ("read", "/diagnostic_nodelet/use_warn", "bool"),
                             ("publish", "/diagnostics", "diagnostic_msgs/DiagnosticArray"))),
    ("jsk_topic_tools::ConnectionBasedNodelet", "advertise"): RosFunction(
        "publish", type_from=("template",), name_arg=1, queue_arg=2, latch_arg=3,
        on_handle=False, handle_arg=0, library_default=True, standin_only=True,
        siblings=_JSK_LATCH),
    ("jsk_topic_tools::ConnectionBasedNodelet", "advertiseImage"): RosFunction(
        "publish", fixed_type=_IMAGE, name_arg=1, name_candidates=(1, 2), queue_arg=2,
        on_handle=False, handle_arg=0, transport="*", library_default=True,
        standin_only=True, siblings=_JSK_LATCH),
    ("jsk_topic_tools::ConnectionBasedNodelet", "advertiseCamera"): RosFunction(
        "publish", fixed_type=_IMAGE, name_arg=1, name_candidates=(1, 2), queue_arg=2,
        on_handle=False, handle_arg=0, transport="*", library_default=True,
        standin_only=True, siblings=(*_CAMERA_INFO, *_JSK_LATCH)),
    # (it reads the parameter only when it is set: an optional read)
    ("jsk_topic_tools", "readVectorParameter"): RosFunction(
        "read", name_arg=1, type_from=("value",), type_arg=2, out_arg=2, on_handle=False,
        handle_arg=0, name_required=True, library_default=True, standin_only=True),
}
# rpg_vikit's params_helper.h (its stand-in, ``standin/fallback/vikit``): ``getParam<T>(name,
# default)`` is ``ros::param::get(name, v)`` with that default, ``getParam<T>(name)``
# without one, ``hasParam(name)`` ``ros::param::has``
VIKIT: dict[tuple[str, str], RosFunction] = {
    ("vk", "getParam"): RosFunction(
        "read", type_from=("template-value", "value", "result"), type_arg=1, default_arg=1,
        on_handle=False, name_required=True, standin_only=True),
    ("vk", "hasParam"): RosFunction(
        "read", on_handle=False, presence=True, name_required=True, standin_only=True),
}
# PickNik's rosparam_shortcuts (``standin/fallback/rosparam_shortcuts``, melodic-devel and
# ros2 77b69f6): ROS 1's ``get(parent_name, nh, name, value)`` reads ``name`` on ``nh``
# (hasParam, then getParam) and returns false when it is not set, no default; ROS 2's
# ``get(node, name, value)`` declares it with the value's type and no default, then reads
# it. (``shutdownIfError`` makes a count of failed gets required: ``tested.EXITS``.)
ROSPARAM_SHORTCUTS: dict[tuple[str, str], RosFunction] = {
    ("rosparam_shortcuts", "get"): RosFunction(
        "read", type_from=("value",), type_arg=3, out_arg=3, on_handle=False, handle_arg=1,
        name_arg=2, name_required=True, standin_only=True, ros2=RosFunction(
            "declare", type_from=("value",), type_arg=2, on_handle=False, handle_arg=0,
            name_arg=1, name_required=True, standin_only=True)),
}
# perception_pcl's PCLNodelet::onInit() (2f70209f's pcl_nodelet.h) runs NodeletLazy's
# (``_LAZY_INIT``) and reads four private parameters more
PCL_ROS: dict[tuple[str, str], RosFunction] = {
    ("pcl_ros::PCLNodelet", "onInit"): _base_init(
        "use_multithread_callback", (*_LAZY_INIT, ("read", "max_queue_size", "int"),
                                     ("read", "use_indices", "bool"),
                                     ("read", "latched_indices", "bool"),
                                     ("read", "approximate_sync", "bool"))),
}
FILTERS_TAG = "filters"


def _filter_chain(name_arg: int) -> RosFunction:
    return RosFunction(
        "read", name_arg=name_arg, on_handle=False, handle_arg=name_arg + 1,
        name_required=True, library_default=True, standin_only=True, call_site=False,
        loads=FILTERS_TAG, ros2=RosFunction(
            "declare", name_arg=name_arg, on_handle=False, name_suffix="filter1.type",
            suffix_appended=True, prefix_normalised=True, fixed_type="str",
            name_required=True, library_default=True, standin_only=True, call_site=False,
            loads=FILTERS_TAG,
            siblings=(
                ("read", "filter1.type", "str"), ("declare", "filter1.name", "str"),
                ("read", "filter1.name", "str"))))


FILTERS: dict[tuple[str, str], RosFunction] = {
    ("filters::FilterChain", "configure"): _filter_chain(0),
    ("filters::MultiChannelFilterChain", "configure"): _filter_chain(1),
    ("filters::FilterBase", "getParam"): RosFunction(
        "declare", type_from=("value",), type_arg=1, out_arg=1, on_handle=False,
        name_prefix="?.", library_default=True, standin_only=True, ros2_only=True),
}
# pluginlib's ClassLoader<Base> (ROS 1 and 2 alike) creating an instance of the class
# whose lookup name it is given: where that name is the value of a parameter the node
# reads (slam_toolbox's ``createSharedInstance(solver_plugin)``, ``solver_plugin`` read
# from the parameter of that name with the default ``solver_plugins::CeresSolver``), the
# call is a read of that parameter marked ``loads`` (``PLUGINLIB_CLASS``): the graph
# loads the class its value (or the default) names into the node
# (``plugins.attach.chains``). A name written in the code, or not known, makes no call:
# the node stays partial for the load (``CPP_PLUGINS_LOADED``)
_CLASS_LOAD = RosFunction("read", on_handle=False, call_site=False, standin_only=True,
                          loads=PLUGINLIB_CLASS)
PLUGINLIB: dict[tuple[str, str], RosFunction] = {
    ("pluginlib::ClassLoader", method): _CLASS_LOAD for method in (
        "createSharedInstance", "createUniqueInstance", "createUnmanagedInstance",
        "createInstance", "createClassInstance")}
# ROS 1 control_toolbox's Pid (noetic-devel pid.cpp): init(nh) reads the gains from the
# handle's namespace, ``p`` required (init fails without it), the others with defaults,
# and starts a dynamic_reconfigure server there whose config (cfg/Parameters.cfg) it
# reads as every server does (no write said, as for the servers above); initParam(prefix)
# does the same in NodeHandle(prefix). Not said: ``<ns>/state``, the PidState publisher
# init makes only when ``publish_state`` is true.
_PID_CONFIG: tuple[Sibling, ...] = (
    ("read", "i", "double"), ("read", "d", "double"), ("read", "i_clamp_min", "double"),
    ("read", "i_clamp_max", "double"), ("read", "antiwindup", "bool"))
_PID_SIBLINGS: tuple[Sibling, ...] = (
    *_PID_CONFIG, ("read", "i_clamp", "double"), ("read", "publish_state", "bool"),
    ("server", *RECONFIGURE_SERVICE), *_RECONFIGURE_TOPICS)
CONTROL_TOOLBOX: dict[tuple[str, str], RosFunction] = {
    ("control_toolbox::Pid", "init"): RosFunction(
        "read", fixed_name="p", fixed_type="double", on_handle=False, handle_default="",
        standin_only=True, siblings=_PID_SIBLINGS),
    ("control_toolbox::Pid", "initParam"): RosFunction(
        "read", name_arg=0, name_suffix="p", fixed_type="double", on_handle=False,
        name_required=True, standin_only=True, siblings=_PID_SIBLINGS),
    ("control_toolbox::Pid", "initDynamicReconfig"): RosFunction(
        "server", fixed_name=RECONFIGURE_SERVICE[0], fixed_type=RECONFIGURE_SERVICE[1],
        on_handle=False, handle_default="", standin_only=True,
        siblings=(*_RECONFIGURE_TOPICS, ("read", "p", "double"), *_PID_CONFIG)),
}
# ROS 1 sound_play's C++ client (audio_common sound_play.h): built with a handle and a
# topic it advertises sound_play/SoundRequest there (queue 5), built with none on
# ``robotsound`` of ``ros::NodeHandle()``; the stand-in, ``fallback/sound_play``, is read
# where the workspace has not the package (JUSTINA's and bender's speech nodes)
SOUND_PLAY: dict[tuple[str, str], RosFunction] = {
    ("sound_play::SoundClient", "SoundClient"): RosFunction(
        "publish", name_arg=0, optional_handle=True, on_handle=False,
        fixed_type="sound_play/SoundRequest", default_name="robotsound",
        standin_only=True),
}
# ROS 1 ros_control's joint_limits_rosparam.h (ros_control 136adb6): getJointLimits(joint,
# nh, limits) reads, under ``joint_limits/<joint>`` of the handle given, each limit's
# ``has_*`` flag and its value (getParam, so no default: the limits given stay as they
# are); getSoftJointLimits(joint, nh, soft) reads the four soft limits. The overload that
# takes a URDF joint reads none (no name argument: no call). Not said: the hasParam of
# the joint's namespace each function asks first.
_JOINT_LIMITS: tuple[Sibling, ...] = (
    ("read", "min_position", "double"), ("read", "max_position", "double"),
    ("read", "angle_wraparound", "bool"), ("read", "has_velocity_limits", "bool"),
    ("read", "max_velocity", "double"), ("read", "has_acceleration_limits", "bool"),
    ("read", "max_acceleration", "double"), ("read", "has_jerk_limits", "bool"),
    ("read", "max_jerk", "double"), ("read", "has_effort_limits", "bool"),
    ("read", "max_effort", "double"))
JOINT_LIMITS_INTERFACE: dict[tuple[str, str], RosFunction] = {
    ("joint_limits_interface", "getJointLimits"): RosFunction(
        "read", name_arg=0, name_prefix="joint_limits/", name_suffix="has_position_limits",
        fixed_type="bool", on_handle=False, handle_arg=1, name_required=True,
        library_default=True, standin_only=True, siblings=_JOINT_LIMITS),
    ("joint_limits_interface", "getSoftJointLimits"): RosFunction(
        "read", name_arg=0, name_prefix="joint_limits/", name_suffix="k_position",
        fixed_type="double", on_handle=False, handle_arg=1, name_required=True,
        library_default=True, standin_only=True, siblings=tuple(
            ("read", name, "double")
            for name in ("k_velocity", "soft_lower_limit", "soft_upper_limit"))),
}
# SDFormat's Element: what a Gazebo classic plugin reads of its <plugin> element's
# children (``Get<T>("key")``, ``GetElement("key")->Get<T>()``, ``->GetValue()->
# GetAsString()``): no call, a value the description gives (``SDF_ELEMENT`` + the key)
SDF_CLASS = "sdf::Element"
_SDF_VALUE = RosFunction("read", on_handle=False, name_required=True, call_site=False,
                         value_only=True, name_prefix=SDF_ELEMENT)
SDF: dict[tuple[str, str], RosFunction] = {
    (SDF_CLASS, method): _SDF_VALUE for method in ("Get", "GetElement", "FindElement")}
# ROS 1 gazebo_plugins' GazeboRos helper (gazebo_ros_utils.h): ``getParameter<T>(value,
# "tag", default)`` sets ``value`` to the <plugin> element's child ``tag``, the default
# where it is absent (``getParameterBoolean`` the same for a flag)
GAZEBO_ROS_HELPER = "gazebo::GazeboRos"
_SDF_HELPER_VALUE = RosFunction(
    "read", on_handle=False, name_arg=1, out_arg=0, default_arg=2, name_required=True,
    call_site=False, value_only=True, name_prefix=SDF_ELEMENT)
SDF.update({(GAZEBO_ROS_HELPER, method): _SDF_HELPER_VALUE
            for method in ("getParameter", "getParameterBoolean")})
# a node's parameters interface (node->get_node_parameters_interface()) has the same
# parameter methods: slam_toolbox keeps one and declares through it
RCLCPP_PARAMETERS_INTERFACE = "rclcpp::node_interfaces::NodeParametersInterface"
_INTERFACE_METHODS = ("declare_parameter", "undeclare_parameter", "has_parameter",
                      "get_parameter", "get_parameters", "list_parameters", "set_parameters",
                      "set_parameters_atomically")
RCLCPP: dict[tuple[str, str], RosFunction] = {
    **{(cls, name): row for cls in RCLCPP_NODES for name, row in _RCLCPP_NODE.items()},
    **{(RCLCPP_PARAMETERS_INTERFACE, name): _RCLCPP_NODE[name] for name in _INTERFACE_METHODS},
    # get_parameters_by_prefix(prefix, map): what the node has under the prefix, as the
    # node's get_parameters(prefix, map) that calls it
    (RCLCPP_PARAMETERS_INTERFACE, "get_parameters_by_prefix"): _RCLCPP_NODE["get_parameters"],
    # every parameter the node is given (launch values and overrides), read whole:
    # mrpt_pf_localization turns them all into its YAML configuration
    # (not where one name is looked up in it: navigation2's declare_or_get_parameter
    # asks ``get_parameter_overrides().find(name)`` whether the launch gave that one)
    (RCLCPP_PARAMETERS_INTERFACE, "get_parameter_overrides"): RosFunction(
        "read", fixed_name="~", on_handle=False, not_looked_up=True),
    # the options a node is built with set its parameters before any launch value is
    # taken (topic_tools' relay: ``append_parameter_override("input_topic", args.at(1))``
    # in its main, from the command line): a write of the parameter
    ("rclcpp::NodeOptions", "append_parameter_override"): RosFunction(
        "write", type_from=("value",), type_arg=1, on_handle=False),
}
RCLCPP_PARAMETER = "rclcpp::Parameter"  # set_parameter(rclcpp::Parameter("name", value))

# rclcpp::Node("name", "ns", options) and its derived classes' ": Node("name")", and
# std::make_shared<rclcpp::Node>("name"): the argument indexes of name and namespace.
RCLCPP_NODE_NAME: dict[tuple[str, str], tuple[int, int]] = {
    ("rclcpp::Node", "Node"): (0, 1),
    ("rclcpp_lifecycle::LifecycleNode", "LifecycleNode"): (0, 1),
    ("rclcpp::Node", "make_shared"): (0, 1),
}
# What a node class's constructor creates by itself: rclcpp_lifecycle's LifecycleNode
# publishes its transitions and serves its state machine under the node's own name.
_LIFECYCLE = RosFunction(
    "publish", fixed_name=f"~{LIFECYCLE_EVENTS[0]}", fixed_type=LIFECYCLE_EVENTS[1],
    on_handle=False, siblings=tuple(
        ("server", f"~{name}", kind) for name, kind in LIFECYCLE_SERVICES))
# navigation2's lifecycle node (its stand-in: nav2 installed) is rclcpp_lifecycle's, and
# its constructor declares and reads bond_heartbeat_period and autostart_node, and
# declares and sets bond's global /bond_disable_heartbeat_timeout (nav2_util's
# lifecycle_node.cpp, nav2_ros_common's lifecycle_node.hpp)
_NAV2_LIFECYCLE_PARAMETERS = RosFunction(
    "declare", fixed_name="bond_heartbeat_period", fixed_type="double", on_handle=False,
    library_default=True, call_site=False, siblings=(
        ("read", "bond_heartbeat_period", "double"), ("declare", "autostart_node", "bool"),
        ("read", "autostart_node", "bool"),
        ("declare", "/bond_disable_heartbeat_timeout", "bool"),
        ("write", "/bond_disable_heartbeat_timeout", "bool")))
# ros2_control's manager (its stand-in: a node of the workspace that makes one, as
# ros2_control_node does) serves these under its own name, Humble and Jazzy alike; the
# rest it makes is not described (the stand-in's class is HAROS_UNREAD: partial)
# (``CONTROLLER_MANAGER_SERVICES``: also the services of the manager a ros2_control
# Gazebo plugin starts, ``robot.attach``)
CONTROLLER_MANAGER_SERVICES: tuple[tuple[str, str], ...] = tuple(
    (f"~{name}", f"controller_manager_msgs/srv/{kind}") for name, kind in (
        ("load_controller", "LoadController"),
        ("list_controllers", "ListControllers"),
        ("list_controller_types", "ListControllerTypes"),
        ("configure_controller", "ConfigureController"),
        ("reload_controller_libraries", "ReloadControllerLibraries"),
        ("switch_controller", "SwitchController"),
        ("unload_controller", "UnloadController"),
        ("list_hardware_components", "ListHardwareComponents"),
        ("list_hardware_interfaces", "ListHardwareInterfaces"),
        ("set_hardware_component_state", "SetHardwareComponentState")))
_CONTROLLER_MANAGER_2 = RosFunction(
    "server", fixed_name=CONTROLLER_MANAGER_SERVICES[0][0],
    fixed_type=CONTROLLER_MANAGER_SERVICES[0][1], on_handle=False,
    call_site=False, siblings=tuple(
        ("server", name, kind) for name, kind in CONTROLLER_MANAGER_SERVICES[1:]))
# rclcpp_cascade_lifecycle's node (its stand-in: the package not in the workspace) is a
# lifecycle node whose constructor also publishes and subscribes to the activations
# (transient local) and states of the cascade (rclcpp_cascade_lifecycle.cpp)
_CASCADE = "cascade_lifecycle_msgs/msg/"
_CASCADE_LIFECYCLE = RosFunction(
    "publish", fixed_name="cascade_lifecycle_activations", fixed_type=f"{_CASCADE}Activation",
    on_handle=False, siblings=(
        ("publish", "cascade_lifecycle_states", f"{_CASCADE}State"),
        ("subscribe", "cascade_lifecycle_activations", f"{_CASCADE}Activation"),
        ("subscribe", "cascade_lifecycle_states", f"{_CASCADE}State")))
IMPLICIT: dict[tuple[str, str], tuple[RosFunction, ...]] = {
    ("rclcpp_lifecycle::LifecycleNode", "LifecycleNode"): (_LIFECYCLE,),
    ("rclcpp_cascade_lifecycle::CascadeLifecycleNode", "CascadeLifecycleNode"): (
        _LIFECYCLE, _CASCADE_LIFECYCLE),
    ("controller_manager::ControllerManager", "ControllerManager"): (_CONTROLLER_MANAGER_2,),
    **{(f"{scope}::LifecycleNode", "LifecycleNode"): (_LIFECYCLE, _NAV2_LIFECYCLE_PARAMETERS)
       for scope in ("nav2_util", "nav2")},
}
# node classes of our stand-ins (``standin_only``): named as rclcpp's, with what
# ``IMPLICIT`` says they make, only where the class is the stand-in's (with navigation2's
# sources in the workspace, its own constructor is read)
# (by the names of the parameters of the constructor called that take them: a class with
# several constructors takes the name at different places)
STANDIN_NODE_NAME: dict[tuple[str, str], tuple[str, str]] = {
    **{(f"{scope}::LifecycleNode", "LifecycleNode"): ("node_name", "ns")
       for scope in ("nav2_util", "nav2")},
    ("rclcpp_cascade_lifecycle::CascadeLifecycleNode", "CascadeLifecycleNode"): (
        "node_name", "namespace_"),
    # ros2_control's manager: ControllerManager([resource_manager,] executor, [urdf,
    # activate_all_hw_components,] manager_node_name, node_namespace)
    ("controller_manager::ControllerManager", "ControllerManager"): (
        "manager_node_name", "node_namespace")}
# the constructor argument that, given as false, makes none of them
# (``LifecycleNode(name, ns, options, false)``: enable_communication_interface; the
# controllers of ros2_control make their nodes so, controller_interface_base.cpp:77)
IMPLICIT_SWITCH: dict[tuple[str, str], int] = {
    ("rclcpp_lifecycle::LifecycleNode", "LifecycleNode"): 3,
}
# (class, method) -> the argument that names the sub-namespace
RCLCPP_SUB_NODE: dict[tuple[str, str], int] = {("rclcpp::Node", "create_sub_node"): 0}

# Calls clang could not resolve (made on an object of a class it does not know, or of
# one an error made invalid), matched by the function's name alone: rclcpp's node
# methods and rclcpp_action's functions in ROS 2 code, a NodeHandle's in ROS 1 code.
# free functions called with a node of a template parameter, whose call is the row's only
# where the name was looked up to the row's own function, not to another of that name:
# Autoware's helper (its VehicleInfoUtils(NodeT & node) constructor template declares the
# vehicle's parameters with it)
UNRESOLVED_FREE: dict[str, RosFunction] = {"get_or_declare_parameter": _GET_OR_DECLARE}
UNRESOLVED_ROS2: dict[str, RosFunction] = {
    **_RCLCPP_NODE,
    "create_server": LIBRARIES[("rclcpp_action", "create_server")],
    # nav2's helpers called with a node of a template parameter (only where one of the
    # functions the name may be is the stand-in's: ``standin_only``)
    "declare_parameter_if_not_declared": _NAV2_DECLARE,
    "get_plugin_type_param": _NAV2_PLUGIN_TYPE,
    "declare_or_get_parameter": _NAV2_DECLARE,
    **UNRESOLVED_FREE,
}
# rclcpp_action's free functions where the unresolved call names that namespace
# (``rclcpp_action::create_client<T>(node, getActionName())`` in a class template,
# MoveIt's ActionBasedControllerHandle): its row, not the node method of that name (a
# service client named by the node argument)
UNRESOLVED_ACTION: dict[str, RosFunction] = {
    name: LIBRARIES[("rclcpp_action", name)] for name in ("create_server", "create_client")}
UNRESOLVED_ROS1: dict[str, RosFunction] = {
    name: row for (owner, name), row in ROSCPP.items() if owner == NODE_HANDLE}

# the top namespaces of the rows whose API only ROS 1 has (roscpp, tf, actionlib,
# nodelet_topic_tools, dynamic_reconfigure): ROS 2 code cannot call them, so their names
# are no call site there (``recall.site_pattern``)
ROS1_ONLY = frozenset({"ros", "tf", "actionlib", "nodelet", "nodelet_topic_tools",
                       "dynamic_reconfigure"})
# and those whose API only ROS 2 has (rclcpp and its libraries, nav2's, Autoware's): ROS 1
# code cannot call them, so a ROS 1 unit's ``renderer.set_parameters(w, h)`` (ORK's
# renderer) is no call site of rclcpp's ``Node::set_parameters``
ROS2_ONLY = frozenset({"rclcpp", "rclcpp_action", "rclcpp_components", "rclcpp_lifecycle",
                       "nav2", "nav2_costmap_2d", "nav2_util", "autoware_utils",
                       "autoware_utils_diagnostics", "autoware_utils_logging",
                       "autoware_utils_rclcpp", "autoware_utils_tf"})
ALL: dict[tuple[str, str], RosFunction] = {**ROSCPP, **LIBRARIES, **RCLCPP,
                                            **RCLCPP_LIBRARIES, **ROS2_CONTROL, **AUTOWARE,
                                            **NAV2, **FILTERS, **SDF, **CONTROL_TOOLBOX,
                                            **SOUND_PLAY, **JOINT_LIMITS_INTERFACE,
                                            **PLUGINLIB, **JSK,
                                            **VIKIT, **PCL_ROS, **ROSPARAM_SHORTCUTS}

# ``nh.subscribe(ops)`` / ``nh.advertise(ops)`` / ``nh.advertiseService(ops)``: the call is
# made there (its handle, location and conditions), with the name, queue and type of the
# row that filled ``ops``
_SUBSCRIBE_OPTIONS = RosFunction(
    "subscribe", type_from=("template", "callback"), queue_arg=1, callback_arg=2)
_ADVERTISE_OPTIONS = RosFunction("publish", type_from=("template",), queue_arg=1)
_SERVICE_OPTIONS = RosFunction(
    "server", type_from=("service-callback", "template"), callback_arg=1)
OPTIONS: dict[tuple[str, str], RosFunction] = {
    ("ros::SubscribeOptions", "init"): _SUBSCRIBE_OPTIONS,
    ("ros::SubscribeOptions", "initByFullCallbackType"): _SUBSCRIBE_OPTIONS,
    ("ros::SubscribeOptions", "create"): _SUBSCRIBE_OPTIONS,
    ("ros::AdvertiseOptions", "init"): _ADVERTISE_OPTIONS,
    ("ros::AdvertiseOptions", "create"): _ADVERTISE_OPTIONS,
    ("ros::AdvertiseServiceOptions", "init"): _SERVICE_OPTIONS,
    ("ros::AdvertiseServiceOptions", "create"): _SERVICE_OPTIONS,
    # the options built by roscpp's constructor of a topic, queue, md5sum and datatype
    # (the type's name, as text: a ShapeShifter's ``msg->getDataType()`` is not known)
    ("ros::SubscribeOptions", "SubscribeOptions"): RosFunction(
        "subscribe", type_from=("type-name",), type_arg=3, queue_arg=1),
    ("ros::AdvertiseOptions", "AdvertiseOptions"): RosFunction(
        "publish", type_from=("type-name",), type_arg=3, queue_arg=1),
}
OPTION_CLASSES = frozenset(owner for owner, _ in OPTIONS)
