"""The source side of the model: packages, their runnable nodes and the ROS calls in them."""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from typing import Any, ClassVar, Literal

from .conditions import Condition
from .location import NOWHERE, Location
from .values import UNKNOWN_MARK

BuildType = Literal["catkin", "ament_cmake", "ament_python", "cmake", "unknown"]
NodeKind = Literal["executable", "nodelet", "component", "plugin", "script"]
Language = Literal["cpp", "python"]
# How much of a node's interface is known (DESIGN.md, "Completeness"): "complete" (its
# sources read clean), "partial" (calls may be missing: parse errors, plugin names left;
# ``completeness_reasons`` says why), "model" (from an interface model), "unknown" (no
# source and no model). Checks that claim something is absent trust only "complete" and
# "model" nodes.
Completeness = Literal["complete", "partial", "model", "unknown"]
KNOWN_COMPLETENESS = ("complete", "model")

# The kinds of primitive calls; the same words are used for graph links.
CALL_KINDS = (
    "publish", "subscribe", "server", "client", "action-server", "action-client",
    "read", "write", "declare",
)
# ``PrimitiveCall.loads`` of a read whose parameter's value names the one class a
# pluginlib ClassLoader of the node's code creates (``extract.cpp.api.PLUGINLIB``),
# followed by ``:`` and the loader's base class when known (``pluginlib:karto::ScanSolver``)
PLUGINLIB_CLASS = "pluginlib"


def is_class_load(loads: str | None) -> bool:
    """Whether ``PrimitiveCall.loads`` marks a read naming the one class a pluginlib
    ClassLoader creates (``PLUGINLIB_CLASS``)."""
    return loads is not None and loads.partition(":")[0] == PLUGINLIB_CLASS


def class_load_base(loads: str | None) -> str | None:
    """The base class such a load's ClassLoader loads, when known."""
    return loads.partition(":")[2] or None if is_class_load(loads) else None  # type: ignore[union-attr]


CallKind = Literal[
    "publish", "subscribe", "server", "client", "action-server", "action-client",
    "read", "write", "declare",
]

# ``PrimitiveCall.handle_origin``: a ROS 1 call made on a nodelet's own handle
# (``getNodeHandle()``, ``getPrivateNodeHandle()``, their MT twins), or on one the code
# constructs (``ros::NodeHandle nh("~")``), which roscpp makes in the process's node; a
# ROS 2 call made on a node a library makes with default options (tf2_ros'
# ``TransformListener(buffer)``), which takes the process's global arguments only: the
# launch's namespace and remaps, not the namespace or arguments the code gives its node
HANDLE_ORIGINS = ("nodelet", "process")
NODELET_HANDLE, PROCESS_HANDLE = HANDLE_ORIGINS

# a ROS 1 dynamic_reconfigure server's service and its two latched topics, below the
# server's namespace (dynamic_reconfigure's server.h and server.py); a client (client.py,
# dynparam) calls the service and subscribes to the topics
RECONFIGURE_SERVICE = ("set_parameters", "dynamic_reconfigure/Reconfigure")
RECONFIGURE_TOPICS: tuple[tuple[str, str], ...] = (
    ("parameter_descriptions", "dynamic_reconfigure/ConfigDescription"),
    ("parameter_updates", "dynamic_reconfigure/Config"))

# what a ROS 2 managed (lifecycle) node makes by itself, under its own name, in rclcpp
# (rclcpp_lifecycle's LifecycleNode) and rclpy (rclpy.lifecycle's Node) alike: its
# transitions' topic, and its state machine's services
LIFECYCLE_EVENTS = ("transition_event", "lifecycle_msgs/msg/TransitionEvent")
LIFECYCLE_SERVICES: tuple[tuple[str, str], ...] = tuple(
    (name, f"lifecycle_msgs/srv/{kind}") for name, kind in (
        ("change_state", "ChangeState"), ("get_state", "GetState"),
        ("get_available_states", "GetAvailableStates"),
        ("get_available_transitions", "GetAvailableTransitions"),
        ("get_transition_graph", "GetAvailableTransitions")))


# ``PrimitiveCall.name_each`` of a call named by a numbered family of parameters
NUMBERED = "#"
# ``PrimitiveCall.name_each`` of a call named by each word of a string parameter (costmap_2d's
# ``observation_sources``, read word by word with ``while (stream >> source)``)
WORDS = " "
# the start of a ``PrimitiveCall.name_each`` (``name_param`` None) of a call named by each
# object a loop walks in a container of the node's plugins, by what a method of the object
# returns: LOADED, the qualified name of the function that gives the container, a space,
# that of the method (navigation2's Costmap2DROS, ``for (auto & layer :
# *layered_costmap_->getPlugins())``, a publisher on ``layer->getName()``: "@nav2_costmap_2d::
# LayeredCostmap::getPlugins nav2_costmap_2d::Layer::getName"); the graph makes the call
# once per plugin the host row says is kept there (``hosts.Slot.kept``); then, after a
# space, the class the loop tests the object is of before the call (``if (auto
# costmap_layer = std::dynamic_pointer_cast<CostmapLayer>(layer))``), if it does
LOADED = "@"


def loaded_mark(container: str, method: str, cast: str | None = None) -> str:
    """``PrimitiveCall.name_each`` of a call named by ``method`` of each object of the
    container ``container`` gives (``LOADED``), of class ``cast`` only when given."""
    return f"{LOADED}{container} {method}" + (f" {cast}" if cast else "")


# the start of a ``PrimitiveCall.name_each`` of a call named by each value of a counting
# loop whose bound is an integer parameter (``name_param``), its ``?`` the loop variable
# as decimal text: COUNTED, the first value, and "=" when the last is the bound itself
# (``i <= n``); ego-planner's ``for (int i = 0; i < waypoint_num_; i++)
# nh.param("fsm/waypoint" + to_string(i) + "_x", ...)`` is "<0" on ``fsm/waypoint_num``.
# A name made of the variable plus a constant (denso_robot_control's ``ss << "joint_" <<
# i + 1``) ends with that constant, signed: "<0+1"
COUNTED = "<"


def counted_mark(start: int, inclusive: bool, shift: int = 0, length: bool = False) -> str:
    """``PrimitiveCall.name_each`` of a counting loop from ``start`` (``COUNTED``), up to
    its bound, that value too when ``inclusive`` (``i <= n``); the name holds the
    variable plus ``shift``. With ``length`` the bound is the number of elements of a
    list parameter (``range(len(p))``), not an integer parameter's value (``#``)."""
    return (f"{COUNTED}{start}{'=' if inclusive else ''}"
            + (f"{shift:+d}" if shift else "") + ("#" if length else ""))


def counted_turns(each: str, bound: object, limit: int) -> range | None:
    """The values a name made of a counting loop's variable (``COUNTED``) holds, one per
    turn, for the bound ``bound`` (the variable's, shifted as the mark says); None when
    ``each`` is no such mark, the bound is no integer, or there are more than
    ``limit``; a mark of a list's length (``#``) counts the elements of the list
    ``bound``."""
    match = _COUNTED_MARK.fullmatch(each[len(COUNTED):]) if each.startswith(COUNTED) else None
    if match is not None and match.group(4):
        bound = len(bound) if isinstance(bound, list) else None
    if match is None or isinstance(bound, bool) or not isinstance(bound, int):
        return None
    start, shift = int(match.group(1)), int(match.group(3) or 0)
    turns = range(start + shift, (bound + 1 if match.group(2) else bound) + shift)
    return turns if len(turns) <= limit else None


def counts_length(each: str) -> bool:
    """Whether ``each`` is the mark of a counting loop up to a list's length (``#``)."""
    return each.startswith(COUNTED) and each.endswith("#")


# what follows ``COUNTED`` in a mark: the first value, "=", the shift, "#" (``counted_mark``)
_COUNTED_MARK = re.compile(r"(\d+)(=?)([+-]\d+)?(#?)")
# the start of a ``PrimitiveCall.name_param`` that is no ROS parameter but a child element
# of a Gazebo classic plugin's SDF (``sdf:topicName``), which robot.attach fills in from
# the robot description
SDF_ELEMENT = "sdf:"
# the start of a ``PrimitiveCall.name_param`` that is no ROS parameter but the value of
# the process's ``key:=value`` command-line word that roscpp's ``ros::getROSArg(argc,
# argv, "key")`` returns (``ros_arg:robot``); the graph takes it from the words
# roslaunch gives the instance (its ``args`` and remaps)
ROS_ARGUMENT = "ros_arg:"
# the third element of a ``PrimitiveCall.name_more`` entry whose value continues the
# ``?`` of the parameter before it rather than filling a ``?`` of its own (ros_kortex's
# ``m_prefix + m_arm_name``: one run of the name, two parameters' values joined)
JOINED = "+"

@dataclass(frozen=True)
class Dependency:
    """A dependency declared in package.xml; ``condition`` as written, if any, and
    whether it holds in the environment the workspace was read with (``active``; True
    when there is none or it cannot be decided)."""

    name: str
    kind: str = "depend"
    condition: str | None = None
    active: bool = field(default=True, metadata={"optional": True})


@dataclass(frozen=True)
class Plugin:
    """A plugin description exported by a package (``<export><nodelet plugin=.../>``)."""

    kind: str
    file: str


@dataclass
class PrimitiveCall:
    """One call to a ROS primitive in a node's source.

    ``name`` is relative to the node with the handle's namespace applied (``~frame_id``,
    ``motors/status``, ``/robot/x``) and ``?`` for parts unknown statically.
    """

    kind: CallKind
    name: str
    type: str | None = None
    queue_size: int | None = None
    qos: dict[str, Any] | None = None
    latch: bool = False
    callback: str | None = None
    conditions: tuple[Condition, ...] = ()
    location: Location = NOWHERE
    # a name that is the value of a parameter: ``nh.param("topic", t, "scan")`` then
    # ``subscribe(t, ...)`` gives name "?", name_param "topic", name_default "scan"
    name_param: str | None = None
    name_default: str | None = None
    origin: str = "source"  # "source", or "hint" when a project-file hint made it
    # parameter reads: whether the code gives a default, and the default when known
    has_default: bool = False
    default: Any = None
    # searchParam / search_param: the name is looked up in the enclosing namespaces
    searched: bool = False
    # a parameter read whose result (whether the parameter is there) the code tests:
    # ``if (nh.getParam("x", v))``, ``!has_parameter("x")``; it handles the absence
    tested: bool = field(default=False, metadata={"optional": True})
    # ROS 2: a read of every parameter the node has under ``name``, a prefix with its
    # ``.`` (``gains.``: ``gains.P``, ``gains.I.max``; not ``gains`` itself, so its own
    # parameter): rclpy's ``get_parameters_by_prefix("gains")``, rclcpp's
    # ``get_parameters("gains", map)``. The graph reads it as ROS 1 reads a namespace
    # whole (``graph.build._namespace_values``): what the configuration sets under the
    # prefix is read as part of it
    under: bool = field(default=False, metadata={"optional": True})
    # ROS 2: a read of every parameter the node has (under a prefix, ``under``, or all of
    # them, ``~``: rclpy's ``get_parameters_by_prefix``, rclcpp's ``get_parameters(prefix,
    # map)`` and ``list_parameters``) made on a node that does not declare the overrides
    # it is given (``automatically_declare_parameters_from_overrides``, false by default in
    # rclpy and rclcpp): it gets only the parameters the node declares, not every one the
    # configuration sets (``graph.build._namespace_values``). The extractor marks such
    # reads and clears the mark where the node's code may declare its overrides
    # (``extract.overrides``)
    declared_only: bool = field(default=False, metadata={"optional": True})
    # ROS 1: a namespace read whole (``getParam("", dict)``) whose value the code uses for
    # its keys alone (``for (auto& pair : dict)`` naming only ``pair.first``, and
    # ``getType()`` / ``size()`` / ``valid()``): mavros' distance_sensor iterates the
    # sensors' names and reads each one's parameters by name. What is set under it is
    # not read as part of it (``graph.build._namespace_values``)
    keys_only: bool = field(default=False, metadata={"optional": True})
    # ROS 1: a read of a member of a struct parameter (an ``XmlRpcValue``) that the code
    # was handed (``config_node["child_frame_id"]`` in a constructor given each member
    # of ``~rigid_bodies`` read whole: ``~rigid_bodies/?/child_frame_id``), or of the
    # member whole. Where what is handed is no parameter's value (its name's first run
    # unknown once the node's files are joined), the read is none (``links.resolve``)
    struct_member: bool = field(default=False, metadata={"optional": True})
    # ROS 1: the namespace of the NodeHandle the call is made on, as written (``input``,
    # ``~``, ``/robot``), when ``name`` was joined to it; roscpp remaps that namespace
    # before it resolves the name in it, so the graph resolves it first
    handle_namespace: str | None = None
    # ROS 1 ros_control: made on the root handle a controller manager gives a controller's
    # ``init(hw, root_nh, controller_nh)``, its own namespace: a relative name is the
    # manager's (``plugins.attach.ros1_controllers``), not the controller's
    root_handle: bool = field(default=False, metadata={"optional": True})
    # ROS 1: where the handle the call is made on comes from (``HANDLE_ORIGINS``):
    # ``nodelet``, a nodelet's own handle, in the nodelet's namespace with the remaps it
    # was loaded with; ``process``, a handle the code constructs, which is the process's
    # node's: in a nodelet manager, the manager's namespace, private name and remaps
    # (laser_filters before 7c18194 advertised on a member ``ros::NodeHandle nh;``). None:
    # not known (a handle another file gives, handles of both kinds), or no handle; the
    # graph then places the call as the node's own, as before this field was read.
    # ROS 2: ``process`` alone, a node a library makes with default options (tf2_ros'
    # ``TransformListener(buffer)``): the launch's namespace and remaps for the process
    handle_origin: str | None = field(default=None, metadata={"optional": True})
    # made on its host by a plugin the host loads because it loads every class it finds
    # (ROS 1 mavros' plugins, ``hosts.Slot`` EXPORTED), of an installed package's model:
    # what it subscribes is input the host offers (``NodeInstance.offered``)
    offered: bool = field(default=False, metadata={"optional": True})
    # parameter writes that delete the parameter (rospy.delete_param, ros::param::del,
    # NodeHandle::deleteParam)
    deletes: bool = False
    # the name the code gives the ROS node this call is made on, when its executable
    # creates several (``Node.rosnames``); None: the executable's one node
    node_name: str | None = field(default=None, metadata={"optional": True})
    # a name taken from each element of a list parameter (twist_mux's ``~topics``: one
    # subscription per ``topics[i].topic``): ``name_param`` is the list, ``name_each``
    # the element's field (``.``: the element itself); the graph makes one call per
    # element the launch file gives. ``#``: a numbered family of parameters instead
    # (robot_localization's ``imu0``, ``imu1``, ...: ``name_param`` "imu"), one call per
    # parameter set, from 0 up to the first one not set, as the code reads them. ``WORDS``
    # (a space): each whitespace-separated word of a string parameter
    name_each: str | None = field(default=None, metadata={"optional": True})
    # ROS 1 rostopic's echo, hz, delay and bw: the name may go on into a field of the
    # message (``rostopic echo /odom/pose/pose``); the subscription is of the topic
    # whose name is the longest part of it that is published, when no topic is named
    # whole (``graph.build._field_watchers``)
    name_field: bool = field(default=False, metadata={"optional": True})
    # a parameter write whose value is the process's K-th command-line argument, counted
    # as rclcpp counts what ``init_and_remove_ros_arguments`` leaves (0: the program; 1:
    # the first argument): topic_tools' relay sets ``input_topic`` from ``args.at(1)``.
    # The graph takes the value from the arguments the launch file gives the instance
    program_arg: int | None = field(default=None, metadata={"optional": True})
    # a name whose one ``?`` is the process's K-th command-line argument, counted as
    # ``program_arg`` is, and from the end when negative (-1: roscpp's ``argv[argc - 1]``
    # after ``ros::init``, which has taken roslaunch's ``:=`` words off): kinova's
    # ``"/" + robot_name + "_driver/..."`` with ``robot_name = argv[argc - 1]``. The graph
    # takes the value from the arguments the launch file gives the instance
    name_arg: int | None = field(default=None, metadata={"optional": True})
    # the name's one ``?`` is the node's own name without its namespace (rclcpp's
    # ``get_name()`` inside a name: nav2's costmap serves ``"get_cost_" + get_name()``):
    # the graph puts the instance's name there. From a Python node, the name's first
    # ``?`` when nothing fills the others (rclpy's ``f"/{self.get_name()}/{key}"``)
    name_self: bool = field(default=False, metadata={"optional": True})
    # the name's one ``?`` is the node's fully qualified name (rospy's ``get_name()``
    # anywhere but at the start: ``"/debug" + rospy.get_name()``): the graph puts the
    # instance's name there, the name made canonical as rospy does (no ``//``)
    name_full: bool = field(default=False, metadata={"optional": True})
    # the name's one ``?`` begins it and is the topic of a publisher or subscription the
    # node made, resolved and remapped (rclcpp's ``get_topic_name()``: autoware_utils'
    # published-time publisher names ``<topic>/debug/published_time``): that topic's
    # name as the code wrote it, which the graph resolves and remaps in the instance
    name_below: str | None = field(default=None, metadata={"optional": True})
    # a name whose one ``?`` is the value of an option of the process's command line that
    # argparse parses (its flags, space separated: ``-l --limb``): intera_interface's
    # joint trajectory action server's ``--limb``, which names its topics. The graph takes
    # the value from the arguments the launch file gives the instance
    name_option: str | None = field(default=None, metadata={"optional": True})
    # the option's ``default=`` (a literal string), what argparse gives it when the
    # launch file's arguments, known statically, do not name it: gazebo_ros'
    # spawn_entity.py ``-gazebo_namespace``, default ``''``, so ``/spawn_entity``
    name_option_default: str | None = field(default=None, metadata={"optional": True})
    # the option is read by C's getopt / getopt_long, not argparse (pr2_ethercat's ``case
    # 'r': g_options.rosparam_ = optarg;``, flags ``-r --rosparam``): the options the
    # program takes, which tell getopt's words apart: its optstring (``hi:usx:r:``), then
    # each long option of the ``struct option`` table with getopt's ``:`` / ``::`` for a
    # required / optional argument (``rosparam:``), or ``--?`` when that table is not
    # read. The graph takes the value by getopt's rules (``conditions.getopt_option``)
    name_getopt: str | None = field(default=None, metadata={"optional": True})
    # with ``name_getopt``: the code sets the variable to a null pointer before getopt
    # reads the options (``g_options.xml_ = NULL;``), so where the instance's arguments
    # do not give the option the name is no string (``std::string`` of a null pointer
    # throws): the call reads, or makes, nothing there
    name_option_null: bool = field(default=False, metadata={"optional": True})
    # a name with several ``?``, each a parameter's value, in order: ``name_param`` (and
    # ``name_default``) fills the first, each [parameter, its default or None] here one
    # more (f1tenth_gym_ros' ``ego_namespace + '/' + get_parameter('ego_odom_topic')``:
    # name ``?/?``, name_param ``ego_namespace``, name_more ``[["ego_odom_topic", None]]``).
    # An entry [parameter, default, JOINED] continues the ``?`` before it: one ``?`` of
    # several values joined (``"/" + name + model + "/stop"``: name ``/?/stop``,
    # name_param ``name``, name_more ``[["model", None, "+"]]``), known when each is
    name_more: list[list[str | None]] | None = field(
        default=None, metadata={"optional": True})
    # a call made through image_transport (``plugins.hosts.TRANSPORTS``): ``*`` for a
    # publisher, which also publishes the topic of every transport plugin it loads; for
    # a subscriber the transport its code names (``raw``, ``compressed``), or ``?`` when
    # the node's ``image_transport`` parameter chooses it (TransportHints); a trailing
    # ``/``: the transport's topic is named from the base as written, not from the base
    # resolved and remapped (ROS 1 Subscriber); a trailing ``=``: the ROS 2 code gave it a
    # base it resolved and remapped itself, which the transport's topic is named below
    transport: str | None = field(default=None, metadata={"optional": True})
    # a subscriber's ``?`` transport: what gives it when the node's ``image_transport``
    # parameter does not (the default its TransportHints are made with: ROS 1
    # ``TransportHints("compressed")``, a string converted to them, ROS 2 ``TransportHints(
    # node, "compressed")``), or, with ``transport_fixed``, what the code passes as the
    # transport itself (ROS 2 ``create_subscription(node, base, cb, transport)``), which
    # no parameter of image_transport changes: the value of the parameter
    # ``transport_param`` (as the code names it), else of the program argument
    # ``transport_arg`` (counted as ``name_arg``), else ``transport_default`` (``?``: a
    # value not known); none of them: ``raw``
    transport_param: str | None = field(default=None, metadata={"optional": True})
    transport_arg: int | None = field(default=None, metadata={"optional": True})
    transport_default: str | None = field(default=None, metadata={"optional": True})
    transport_fixed: bool = field(default=False, metadata={"optional": True})
    # a parameter read: the member variable it stores the value in (``publish_`` of
    # ``nh.param("publish", publish_, false)`` or ``publish_ = declare_parameter(..)``),
    # when that is the member's only write in the file; a source condition over the
    # member is then decided per instance by the parameter's value (graph.conditions)
    variable: str | None = field(default=None, metadata={"optional": True})
    # ... and the constants the file's other code assigns that member as well
    # (robot_localization's ``useControl_ = false;`` when the control config is bad):
    # the condition is decided only when they agree with the parameter's value
    also: list[Any] | None = field(default=None, metadata={"optional": True})
    # rospy: the call gives no queue_size at all (not even through *args / **kwargs): a
    # Publisher then publishes synchronously, in the caller's thread (rospy warns), a
    # Subscriber queues without bound; a queue_size the parse cannot value is not this
    queue_size_missing: bool = field(default=False, metadata={"optional": True})
    # the camera_info topic of an image_transport camera publisher or subscriber: the
    # image topic's name as the code wrote it (the call at the same place). The info
    # topic is ``camera_info`` in the namespace of the image topic as resolved and, in
    # ROS 1, remapped (``resolveName``): remapping ``image`` to ``/cam/depth/image_raw``
    # moves the info topic to ``/cam/depth/camera_info``; ROS 2 only expands it
    camera_of: str | None = field(default=None, metadata={"optional": True})
    # in one translation unit's calls only (never in a node's): the USR of the
    # constructor whose body makes this call with a name from its own parameters, which
    # no call in that unit gives; the node makes it only if one of its files constructs
    # the class (``extract.cpp.links.resolve``)
    made_in: str | None = field(default=None, metadata={"optional": True})
    # in one translation unit's calls only (never in a node's): the USR of the
    # constructor whose body makes this call, when that unit constructs the class
    # nowhere; the node's call holds the source conditions every construction of the
    # class in the node's other files shares (``extract.cpp._built_under``)
    built_in: str | None = field(default=None, metadata={"optional": True})
    # in one translation unit's calls only (never in a node's): the USR of the free
    # function or method whose body makes this call; the node's call holds the source
    # conditions every call of that function in the node's files shares
    # (``extract.cpp.call_conditions``)
    called_in: str | None = field(default=None, metadata={"optional": True})
    # a name taken from a parameter whose default holds another parameter's value in place
    # of its one ``?`` (topic_tools' ROS 2 relay: ``output_topic`` defaults to
    # ``input_topic + "_relay"``, name_default "?_relay"): that other parameter's name, as
    # the code writes it; the graph fills in its value (launch value, else the value the
    # node's arguments give it, else its own default)
    default_param: str | None = field(default=None, metadata={"optional": True})
    # the name (``?``) is wholly the one string parameter of a virtual method that no
    # code of the node calls, nor a base method it overrides (``links.HOST_NAMED``),
    # written on the node itself (no handle namespace): the classes (qualified, separated
    # by spaces) that declare the methods it overrides. A host that loads the plugin by
    # one of them calls it with the plugin's name (nav2's TimedBehavior serves its action
    # under the ``name`` nav2_core::Behavior's ``configure`` is given); the host fills it
    # in (``plugins.attach``)
    host_named: str | None = field(default=None, metadata={"optional": True})
    # ROS 1: made on a handle whose namespace, wholly or as its first part, is a handle
    # parameter of a virtual method that no code of the node calls, nor a base method
    # it overrides (a plugin's ``initialize(ros::NodeHandle nh, ...)``, which its host
    # calls through the base class it loads it by): ``<base method USR>#<index>`` of
    # each method it overrides (directly or not), separated by spaces. The name's first
    # ``?`` is that handle's namespace, which the host's call gives
    # (``Node.handles_given``; ``plugins.attach``)
    host_handle: str | None = field(default=None, metadata={"optional": True})
    # in one translation unit's calls only (never in a node's): a name that is wholly a
    # member of a class that no function of the unit writes (topic_tools' ToolBaseNode
    # publishes on ``output_topic_``, which its subclass RelayNode sets in another
    # file): the member's USR; and a parameter read whose value the unit stores in a
    # member and nothing else there does: that member's USR. A node whose files do both
    # takes the name from that parameter (``extract.cpp._members_named``)
    name_member: str | None = field(default=None, metadata={"optional": True})
    # ``name`` with ``?`` for the run that is the name the node's class was constructed
    # with, read from a member every constructor of the class initialises with what it
    # hands its rclcpp node base as the node's name (nav2's ``Costmap2DROS::name_``, its
    # ``getName()``: ``"clear_entirely_" + costmap_.getName()`` is ``clear_entirely_?``);
    # ``name`` holds the value under the program's own construction. A node that a
    # host's code constructs (``plugins.hosts.Child``) takes its own name there
    name_built: str | None = field(default=None, metadata={"optional": True})
    stores: str | None = field(default=None, metadata={"optional": True})
    # the parameter this call reads or declares names the plugin classes the code loads
    # by pluginlib, of the export tag / base class given (``plugins.hosts.CHAINS``): a
    # filters FilterChain's ``configure`` (ROS 1 its list of {name, type, params}, ROS 2
    # ``<prefix>filter1.type``, then filter2, ...); the graph gives the instance the calls
    # of the classes its parameters name (``plugins.attach.chains``); or ``PLUGINLIB_CLASS``:
    # the parameter's value is the lookup name of the one class a pluginlib ClassLoader
    # of the code creates there, its default the code's
    loads: str | None = field(default=None, metadata={"optional": True})
    # a ``loads`` read's name made of the name the code gives the loaded class, in a
    # configuration (never in a node's calls): the element of a list parameter the graph
    # put for its ``?`` (nav2's ``<id>.plugin``), or the plugin name of a plugin's read
    # on its host (dwb's ``<plugin>.trajectory_generator_name``); the class's own ``?``
    # names are that name (``plugins.attach.chains``)
    loads_given: str | None = field(default=None, metadata={"optional": True})
    # ROS 1, a Gazebo classic plugin: the child element of its SDF (``sdf:robotNamespace``,
    # ``SDF_ELEMENT``) whose value is the one ``?`` of the handle's namespace
    # (``handle_namespace``), where the name's own part holds another (``name_param``);
    # or the elements, separated by spaces, that give each ``?`` of that namespace in
    # order (hector's sonar serves its dynamic_reconfigure on ``NodeHandle(*nh, topic_)``:
    # ``sdf:robotNamespace sdf:topicName``); robot.attach fills them from the robot
    # description
    namespace_param: str | None = field(default=None, metadata={"optional": True})
    # a ``read`` of no parameter but of the process's ``name:=value`` command-line word
    # (roscpp's ``ros::getROSArg(argc, argv, "name")``; ``name`` as written, matched
    # literally): it makes no link; a launch file's ``name:=value`` (which roscpp also
    # takes for a remap) is given to the node for it, so it is a remap the node uses
    argument: bool = field(default=False, metadata={"optional": True})
    # a ``read`` of no parameter but a name roscpp resolves and remaps for the code
    # (a NodeHandle's ``resolveName(name)``, ``ros::names::resolve(name)``), which the code
    # may make pieces of other names of: it makes no link; a launch file's remap of that
    # name is one the node uses (people's face_detector remaps ``camera``, ``rgb_ns`` and
    # ``image_topic``, each resolved and joined into one topic)
    resolved: bool = field(default=False, metadata={"optional": True})


def declared_defaults(calls: list[PrimitiveCall]) -> list[PrimitiveCall]:
    """The calls, where one takes its name from a parameter whose default it does not
    know, with the default a declaration of that parameter gives when the default holds a
    third parameter's value (topic_tools' relay: relay_node.cpp declares ``output_topic``
    with ``input_topic_ + "_relay"``, tool_base_node.cpp publishes on the member)."""
    held = {(c.name, c.node_name): (c.name_default, c.default_param) for c in calls
            if c.kind == "declare" and c.default_param is not None}
    if not held:
        return calls
    return [replace(c, name_default=found[0], default_param=found[1])
            if c.name_param is not None and c.name_default is None and c.kind != "declare"
            and (found := held.get((c.name_param, c.node_name))) is not None else c
            for c in calls]


def wire_call(action: PrimitiveCall, kind: CallKind, name: str, type_: str | None,
              conditions: tuple[Condition, ...]) -> PrimitiveCall:
    """One topic or service call that an action call stands for on the wire (the
    action's ``goal`` topic, ``_action/send_goal`` service, ...): the action call's place
    and facts under the wire's kind, full name and type, with ``origin`` "action"."""
    return replace(action, kind=kind, name=name, type=type_, queue_size=None, qos=None,
                   latch=False, callback=None, name_param=None, name_default=None,
                   default_param=None, origin="action", conditions=conditions)


@dataclass
class SourceFile:
    path: str
    package: str
    language: Language


@dataclass(eq=False)
class Node:
    """A build target that can run: executable, nodelet/component/plugin class or script."""

    package: str
    executable: str
    kind: NodeKind = "executable"
    language: Language = "cpp"
    sources: list[str] = field(default_factory=list)
    calls: list[PrimitiveCall] = field(default_factory=list)
    # the node name the source gives itself (ros::init, rclcpp::Node, rospy.init_node)
    rosname: str | None = None
    conditions: tuple[Condition, ...] = ()
    location: Location = NOWHERE
    # ROS 2: one process may create several nodes (two rclpy Node subclasses added to one
    # executor, create_node twice): their names in order, each call's ``node_name`` one of
    # them; empty when the executable creates one node (``rosname``)
    rosnames: list[str] = field(default_factory=list, metadata={"optional": True})
    completeness: Completeness = "complete"
    # why calls may be missing (the first few reasons, each with its file:line)
    completeness_reasons: list[str] = field(default_factory=list,
                                            metadata={"optional": True})
    # the interface model this node was taken from (``haros_arch.models``), e.g.
    # "noetic/amcl 1.17.3 ros-planning/navigation@0123abcd"; None: from its source
    model: str | None = field(default=None, metadata={"optional": True})
    # a nodelet or plugin class: its C++ type (``executable`` is its pluginlib lookup
    # name, ``pkg/Name`` or the type itself)
    plugin_class: str | None = field(default=None, metadata={"optional": True})
    # a plugin class: the base class its plugin description names (``base_class_type``),
    # by which a host that loads every exported class of a base finds it (mavros)
    plugin_base: str | None = field(default=None, metadata={"optional": True})
    # a plugin class that only a pluginlib ClassLoader in the code of its package (or of
    # one it depends on) may load (``plugins.classes.loaded_bases``): extracted only
    # once a node extracted reads a parameter naming a class of its base to load
    # (``extract.extract_nodes``); one still deferred then is no node of the model
    deferred: bool = field(default=False, metadata={"optional": True})
    # an interface model's node: the other names releases install its executable under
    # (cartographer_ros' occupancy_grid_node is cartographer_occupancy_grid_node in the
    # humble and jazzy releases); a launched executable of one of these names takes it
    aliases: list[str] = field(default_factory=list, metadata={"optional": True})
    # where the code creates plugin instances by name (pluginlib), ``file:line`` each:
    # their calls are not in the code; an instance is partial unless the graph attaches
    # its plugins (a host of ``plugins.hosts``)
    plugin_loads: list[str] = field(default_factory=list, metadata={"optional": True})
    # the nodelets the program runs in its own process under its own node name
    # (``nodelet::Loader``'s ``load(ros::this_node::getName(), "pkg/Name", ...)``), by
    # lookup name: each instance makes their calls too (``graph.build``)
    nodelets: list[str] = field(default_factory=list, metadata={"optional": True})
    # ROS 1: the namespaces of the handles the code passes to virtual methods it calls
    # through a base class (a host's ``plugin->initialize(nh, nhp, ...)``), as
    # ``<method USR>#<index>`` -> the namespaces (``?`` for one not known): a plugin's
    # call made on such a parameter (``PrimitiveCall.host_handle``) is made there
    handles_given: dict[str, list[str]] = field(default_factory=dict,
                                                metadata={"optional": True})
    # ROS 2: the ``__ns`` / ``__node`` rules (``__ns:=/x``) of the node's own arguments,
    # by its name (``rosname`` or one of ``rosnames``, which they are already applied
    # to): the ``NodeOptions().arguments({"--ros-args", "-r", "__ns:=/x"})`` its code
    # builds it with. rcl reads a node's own rules before the process's, so the
    # namespace or name they set holds whatever the launch file gives (``graph``)
    local_rules: dict[str, list[str]] = field(default_factory=dict,
                                              metadata={"optional": True})
    # a Python program: where it starts, the function a console_scripts entry point
    # names (``main`` of ``pkg.module:main``), "" for a script Python runs whole; None
    # when not known. The calls of a module function no code it reaches calls or names
    # are not the node's (``extract.python``)
    entry: str | None = field(default=None, metadata={"optional": True})

    # the node's name (``pkg/exec``, ``pkg/Class``) first, as DESIGN's JSON contract says
    JSON_HEAD: ClassVar[dict[str, Any]] = {"name": lambda node: node.name}
    JSON_VIEWS: ClassVar[dict[str, str]] = {}

    @property
    def is_complete(self) -> bool:
        """Every call of the node is known: its sources read clean, or a model gave it."""
        return self.completeness in KNOWN_COMPLETENESS

    def mark_partial(self, reason: str, limit: int = 5) -> None:
        """Calls may be missing for ``reason``; keeps the first ``limit`` reasons. A
        node whole from an interface model (``model``) is partial too."""
        if self.completeness in ("complete", "model"):
            self.completeness = "partial"
        if len(self.completeness_reasons) < limit and reason not in self.completeness_reasons:
            self.completeness_reasons.append(reason)

    @property
    def name(self) -> str:
        return f"{self.package}/{self.executable}"

    def __repr__(self) -> str:
        return f"Node({self.name})"

    def calls_of(self, rosname: str | None, apart: bool = False) -> list[PrimitiveCall]:
        """The calls of the ROS node ``rosname`` of this executable (one of ``rosnames``):
        its own, and, for the first, the calls no node could be told for, unless
        ``apart``: then those are ``?``'s, the process's node not known (``unplaced``).
        None: all."""
        if rosname is None or not self.rosnames:
            return list(self.calls)
        if rosname == UNKNOWN_MARK:
            return [c for c in self.calls if c.node_name not in self.rosnames]
        first = rosname == self.rosnames[0] and not apart
        return [c for c in self.calls if c.node_name == rosname
                or (first and c.node_name not in self.rosnames)]

    @property
    def unplaced(self) -> bool:
        """Whether some call of a process of several nodes is made on a node the
        extractor could not tell (its ``node_name`` none of ``rosnames``)."""
        return len(self.rosnames) >= 2 and any(
            c.node_name not in self.rosnames for c in self.calls)


@dataclass(eq=False)
class Package:
    name: str
    path: str
    build_type: BuildType = "unknown"
    version: str = ""
    format: int = 1
    dependencies: list[Dependency] = field(default_factory=list)
    plugins: list[Plugin] = field(default_factory=list)
    nodes: list[Node] = field(default_factory=list)
    location: Location = NOWHERE
    # absolute folder on disk; not part of the JSON model
    root: str = field(default="", metadata={"json": False})
    # the build type under each ROS version ("1", "2") when package.xml chooses it by
    # $ROS_VERSION and the run gives none (ros-bridge's catkin for ROS 1, ament_python
    # for ROS 2), with the line of its first build_type; empty otherwise
    builds_by_version: dict[str, BuildType] = field(default_factory=dict,
                                                    metadata={"json": False})
    builds_at: int = field(default=0, metadata={"json": False})
    # then, the ROS version ("1", "2") whose build makes each executable of ``nodes``
    # (its Python code is read with that version's ROS_VERSION)
    node_versions: dict[str, str] = field(default_factory=dict, metadata={"json": False})
    # a package CMake builds under both ROS versions so (catkin for ROS 1, ament_cmake for
    # ROS 2): each version -> the executables of ``nodes`` its build makes from other
    # sources, as it makes them (``cmake.version_nodes``); a launch file of that version
    # starts those (``pipeline.built_for``)
    version_nodes: dict[str, dict[str, Node]] = field(default_factory=dict,
                                                      metadata={"json": False})

    def __repr__(self) -> str:
        return f"Package({self.name})"

    def node(self, executable: str) -> Node | None:
        for node in self.nodes:
            if node.executable == executable:
                return node
        return None


def name_runs(call: PrimitiveCall, first: str | None,
              values: list[str | None]) -> list[str | None]:
    """The values of a call's ``?``, in order, from ``first`` (``name_param``'s value)
    and ``values`` (each ``name_more`` entry's): a JOINED entry's value joined to the
    run before it, which is None (unknown) unless every value of it is known."""
    runs: list[str | None] = [first]
    for entry, value in zip(call.name_more or [], values, strict=True):
        if len(entry) > 2 and entry[2] == JOINED:
            runs[-1] = None if runs[-1] is None or value is None else runs[-1] + value
        else:
            runs.append(value)
    return runs
