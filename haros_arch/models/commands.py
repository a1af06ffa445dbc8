"""Nodes whose interface is their command line: ``rostopic pub`` / ``ros2 topic pub``,
``rostopic echo``, ``hz``, ``delay`` and ``bw`` / ``ros2 topic echo``, ``hz``, ``bw``
and ``delay``,
``rosservice call`` / ``ros2 service call``, dynamic_reconfigure's ``dynparam``,
ROS 1 topic_tools' ``relay``, ``mux``, ``demux``, ``throttle`` and ``drop``, ROS 1
controller_manager's ``spawner`` and gazebo_ros' ``spawn_model``.

A launch file that starts ``<node pkg="rostopic" type="rostopic" args="pub /initialpose
geometry_msgs/PoseWithCovarianceStamped '{...}'"/>`` runs a publisher of that topic and
type; its instance gets a node made from its arguments. The options are read as the
tools read them (rostopic's optparse and ros2topic's argparse): options may come
anywhere, and those that take a value take the next word.

Facts from the tools' sources: rostopic pub creates ``rospy.Publisher(topic, type,
latch=latch, queue_size=100)`` with ``latch = rate is None or --latch``
(ros_comm ``tools/rostopic/src/rostopic/__init__.py``, ``_rostopic_cmd_pub`` and
``create_publisher``). rosservice call (``tools/rosservice/src/rosservice/__init__.py``,
``_rosservice_cmd_call``, noetic-devel) takes the flags ``-v``, ``--nostr``, ``--noarr``
and ``--wait`` (which waits for the service), then the service, resolved in the node's
namespace (``script_resolve_name``), and YAML arguments; it calls it through
``rospy.ServiceProxy`` with the type the master gives. For ros2 topic pub the QoS is
what its ``--qos-*`` options say (unknown, ``None``, when they say nothing: its defaults
changed between releases). ros2 service call (ros2cli ``ros2service/verb/call.py``)
takes the service and its type, both required, optional YAML values or ``--stdin``, and
``-r`` / ``--rate`` with a value; ``requester`` makes the node
``_ros2cli_requester_<package>_<Service>`` of the type's words and a client of the
service with that type. ros2 lifecycle set (ros2cli ``ros2lifecycle/verb/set.py`` and
``api/__init__.py``) takes the node's name and the transition; when a running node has
that full name it calls ``<node>/get_available_transitions`` and ``<node>/change_state``
(else it prints "Node not found" and calls nothing).

topic_tools (ros_comm ``tools/topic_tools/src``, noetic-devel): ``relay IN [OUT]``
subscribes IN and advertises OUT (default ``IN_relay``), reading ``~unreliable``,
``~lazy``, ``~stealth`` (relay.cpp:146-183); ``mux OUT IN...`` advertises OUT and the
latched ``mux/selected``, subscribes every IN, serves ``OUT_select`` and
``mux/select|add|list|delete`` (mux.cpp:291-380), those five on ``NodeHandle
mux_nh("mux")``, whose namespace a ``mux:=NAME`` remap moves; ``demux IN OUT...`` the other
way round under ``demux/`` (demux.cpp:247-295); ``throttle messages IN RATE [OUT]`` and ``throttle
bytes IN RATE WINDOW [OUT]`` (default ``IN_throttle``, throttle.cpp:181-246); ``drop IN X
Y [OUT]`` (default ``IN_drop``, drop.cpp:65-90). Their messages are of any type
(``ShapeShifter``): the calls have none.

dynamic_reconfigure's ``dynparam`` (``scripts/dynparam`` and ``src/dynamic_reconfigure/
client.py``, noetic-devel): ``set NODE PARAM VALUE`` / ``set NODE YAML``, ``load NODE
FILE``, ``set_from_parameters NODE``, ``get NODE`` and ``dump NODE FILE`` each build a
``Client(NODE)``, which makes a proxy of ``NODE/set_parameters`` (dynamic_reconfigure
``Reconfigure``) and subscribes ``NODE/parameter_updates`` (``Config``) and
``NODE/parameter_descriptions`` (``ConfigDescription``); ``set_from_parameters`` reads
``rospy.get_param("~")``, the values it copies. Options: ``-t`` / ``--timeout`` with a
value; ``set`` takes a word of a dash and a digit as a value.

controller_manager's ROS 1 ``spawner`` (ros_control ``controller_manager/scripts/spawner``,
noetic-devel): the services are NS + ``controller_manager/load_controller``,
``switch_controller`` and ``unload_controller`` with NS the ``--namespace`` argument
(default empty, a ``/`` added, lines 95-117), called through rospy.ServiceProxy (lines
59-62, 124-137); ``--wait-for TOPIC`` subscribes TOPIC (std_msgs/Bool, line 160); it reads
``/use_sim_time`` with the default False (line 140).

controller_manager's ROS 2 ``spawner`` (ros2_control ``controller_manager/controller_manager/
spawner.py`` and ``controller_manager_services.py``, humble 2.x and jazzy 4.x alike):
the node is ``Node("spawner_" + <first controller>)`` in the launch namespace; the
manager is ``-c`` / ``--controller-manager`` (default ``controller_manager``), a relative
name put in ``--namespace`` when given, else in the node's namespace. For the controllers
it calls the manager's ``list_controllers`` (is the controller loaded), ``load_controller``,
``configure_controller`` unless ``--load-only``, ``switch_controller`` unless
``--load-only``, ``--inactive`` or ``--stopped``, ``switch_controller`` and
``unload_controller`` with ``-u`` / ``--unload-on-kill``, and the manager's
``set_parameters`` (rcl_interfaces ``SetParameters``, ros2param's ``call_set_parameters``)
when it sets a controller's ``type`` (``-t``), parameter file (``-p``, ``--params-file``)
or ROS arguments (``--controller-ros-args``). An interface model of the script (its
names built from ``sys.argv``) knows none of these: the arguments decide over it.

gazebo_ros' ROS 1 ``spawn_model`` (gazebo_ros_pkgs noetic-devel ``gazebo_ros/scripts/
spawn_model`` and ``src/gazebo_ros/gazebo_interface.py``): argparse options with one dash;
``-param P`` reads the description from the parameter P (``rospy.get_param(P)``, no
default, line 132), ``-urdf`` / ``-sdf`` call ``G/spawn_urdf_model`` / ``G/spawn_sdf_model``
(gazebo_msgs ``SpawnModel``) with G the ``-gazebo_namespace`` (default ``/gazebo``),
``-wait M`` subscribes ``G/model_states`` (``ModelStates``, line 102), ``-J NAME VALUE``
calls ``G/set_model_configuration``, ``-unpause`` ``G/unpause_physics`` (std_srvs
``Empty``) and ``-b`` ``G/delete_model`` on shutdown (lines 185-230). Its interface model
reads ``?`` (the parameter the options name), so in every simulation the spawner could
read any parameter: the arguments decide over it too.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..extract.python.rclpy import PRESETS
from ..launch.model import NodeDecl, shell_words
from ..launch.ros2.naming import split_arguments
from ..model.source import RECONFIGURE_SERVICE, RECONFIGURE_TOPICS, CallKind, Node, PrimitiveCall
from ..model.values import UNKNOWN_MARK

ROS1_VALUE_OPTIONS = {"-r", "--rate", "-f", "--file"}
ROS2_VALUE_OPTIONS = {"-r", "--rate", "-p", "--print", "-t", "--times", "-w",
                      "--wait-matching-subscriptions", "-n", "--node-name",
                      "--qos-profile", "--qos-depth", "--qos-history",
                      "--qos-reliability", "--qos-durability", "--max-wait-time-secs",
                      "--keep-alive", "--yaml-file"}
# the private parameters each topic_tools node reads, with their type and the value the
# tool keeps when the parameter is not set: every one is read by ``getParam(name, var)``
# into a variable that holds a value before it (or ``param<T>(name, var, default)``), so
# none fails when unset (ros_comm noetic-devel: relay.cpp:167-173, mux.cpp:52-56,314-315,
# 331-333,370-371 (an unset or empty ``initial_topic`` selects the first input),
# throttle.cpp:58-61,197-202)
TOPIC_TOOLS_READS: dict[str, dict[str, tuple[str, Any]]] = {
    "relay": {"~unreliable": ("bool", False), "~lazy": ("bool", False),
              "~stealth": ("bool", False)},
    "mux": {"~lazy": ("bool", False), "~latch": ("bool", False),
            "~initial_topic": ("str", ""), "~wait_publisher_initialization": ("bool", False),
            "~wait_publisher_second": ("double", 0.1)},
    "demux": {},
    "throttle": {"~wall_clock": ("bool", False), "~unreliable": ("bool", False),
                 "~lazy": ("bool", False), "~force_latch": ("bool", True)},
    "drop": {}}
ROS2_QOS = {"--qos-depth": "depth", "--qos-history": "history",
            "--qos-reliability": "reliability", "--qos-durability": "durability"}


def command_node(decl: NodeDecl) -> Node | None:
    """The node a ``rostopic pub`` / ``ros2 topic pub`` declaration runs, from its
    arguments; None for any other declaration (or one whose arguments name no topic)."""
    words = _words(decl.args)
    if (decl.package, decl.executable) == ("rostopic", "rostopic"):
        return _rostopic(decl, words)
    if (decl.package, decl.executable) == ("rosservice", "rosservice"):
        return _rosservice(decl, words)
    if decl.executable == "ros2" and words[:2] == ["topic", "pub"]:
        return _ros2_topic(decl, words[1:])
    if decl.executable == "ros2" and words[:1] == ["topic"] and words[1:2] and (
            words[1] in ROS2_TOPIC_WATCHERS):
        return _ros2_topic_watch(decl, words[1], words[2:])
    if decl.executable == "ros2" and words[:2] == ["service", "call"]:
        return _ros2_service(decl, words[2:])
    if decl.executable == "ros2" and words[:2] == ["lifecycle", "set"]:
        return _ros2_lifecycle_set(decl, words[2:])
    if decl.executable == "ros2" and words[:2] == ["control", "load_controller"]:
        return _ros2_control_load(decl)
    if decl.package == "topic_tools" and decl.ros_version == 1:
        return _topic_tools(decl, words)
    if (decl.package, decl.executable) == ("dynamic_reconfigure", "dynparam") and (
            decl.ros_version == 1):
        return _dynparam(decl, words)
    if (decl.package, decl.executable) == ("controller_manager", "spawner") and (
            decl.ros_version == 1):
        return _spawner(decl, words)
    if (decl.package, decl.executable) == ("gazebo_ros", "spawn_model") and (
            decl.ros_version == 1):
        return _gazebo_spawner(decl, words)
    if by_arguments(decl):
        return _ros2_spawner(decl, program_words(decl.args))
    return None


def by_arguments(decl: NodeDecl) -> bool:
    """Whether the declaration's arguments say its interface better than its code or
    interface model can (the ROS 2 controller spawner, whose names come from
    ``sys.argv``): the node from ``command_node`` is taken first."""
    # (``spawner.py``, the Foxy name, is no executable of later releases: the model
    # says so, MODEL_NODE_MISSING, and that stands)
    return (decl.ros_version == 2 and (decl.package, decl.executable) == (
        "controller_manager", "spawner")) or (decl.ros_version == 1 and (
            decl.package, decl.executable) == ("gazebo_ros", "spawn_model"))


ROS2_SPAWNER_VALUES = {"-c", "--controller-manager", "-p", "--param-file", "-n",
                       "--namespace", "-t", "--controller-type",
                       "--controller-manager-timeout", "--switch-timeout",
                       "--service-call-timeout", "--controller-ros-args", "--params-file"}
_SETS_PARAMETERS = ("-t", "--controller-type", "-p", "--param-file",
                    "--controller-ros-args", "--params-file")


def _ros2_spawner(decl: NodeDecl, words: list[str]) -> Node | None:
    """A ROS 2 controller spawner from its arguments (see the module's docstring)."""
    positional, values, flags = split_options(words, ROS2_SPAWNER_VALUES)
    controllers = [w for w in positional if w != "--controller"]
    if not controllers or any("?" in w for w in controllers):
        return None  # argparse refuses it, or the controllers are not known
    manager = values.get("-c", values.get("--controller-manager", "controller_manager"))
    namespace = values.get("-n", values.get("--namespace", ""))
    if "?" in manager or "?" in namespace:
        return None
    if not manager.startswith("/") and namespace.strip("/"):
        manager = f"/{namespace.strip('/')}/{manager}"
    verbs = ["list_controllers", "load_controller"]
    if not flags & {"--load-only"}:
        verbs.append("configure_controller")
        if not flags & {"--inactive", "--stopped"}:
            verbs.append("switch_controller")
    if flags & {"-u", "--unload-on-kill"}:
        verbs += ["switch_controller", "unload_controller"]
    calls = [PrimitiveCall("client", f"{manager}/{verb}", _SPAWNER_TYPES[verb],
                           location=decl.location, origin="arguments")
             for verb in dict.fromkeys(verbs)]
    if any(option in values for option in _SETS_PARAMETERS):
        calls.append(PrimitiveCall("client", f"{manager}/set_parameters",
                                   "rcl_interfaces/srv/SetParameters",
                                   location=decl.location, origin="arguments"))
    node = _node(decl, "controller_manager", calls[0], "python")
    node.calls = calls
    node.rosname = f"spawner_{controllers[0]}"
    return node


# ``ros2 control load_controller``'s options that take a value (ros2controlcli's
# ``add_controller_mgr_parsers`` and ros2cli's direct node's ``--spin-time``)
CLI_LOAD_VALUES = {"-c", "--controller-manager", "--set-state", "--spin-time"}


@dataclass(frozen=True)
class CliLoad:
    """What ``ros2 control load_controller [options] NAME [PARAM_FILE]`` asks of the
    controller manager: load NAME (after setting its parameters from PARAM_FILE), then
    with ``--set-state`` configure it, and with ``--set-state active`` activate it."""

    controller: str
    param_file: str | None
    manager: str  # as given: relative ones are in the process's namespace
    state: str | None


def cli_load(decl: NodeDecl) -> CliLoad | None:
    """The load a ``ros2 control load_controller`` declaration asks for, read as its
    argparse reads the words (ros2_control's ros2controlcli ``verb/load_controller.py``:
    the controller's name, an optional parameter file (Jazzy on), ``--set-state``
    ``inactive`` / ``configured`` / ``active``, ``-c`` the manager, default
    ``controller_manager`` or ``/controller_manager`` by release, one node either way
    for a process in the root namespace); None for another declaration, or one whose
    words are not known or that argparse refuses."""
    words = _words(decl.args)
    if decl.executable != "ros2" or words[:2] != ["control", "load_controller"]:
        return None
    rest = words[2:]
    if "--ros-args" in rest:
        rest = rest[:rest.index("--ros-args")]
    positional, values, _flags = split_options(rest, CLI_LOAD_VALUES)
    if not 1 <= len(positional) <= 2 or any(UNKNOWN_MARK in w for w in positional):
        return None
    manager = values.get("-c", values.get("--controller-manager", "controller_manager"))
    if UNKNOWN_MARK in manager:
        return None
    return CliLoad(positional[0], positional[1] if len(positional) > 1 else None,
                   manager, values.get("--set-state"))


def _ros2_control_load(decl: NodeDecl) -> Node | None:
    """The DirectNode of ``ros2 control load_controller``: the manager's services it
    calls (``list_controllers``, ``set_parameters`` for a parameter file, then
    ``load_controller``, ``configure_controller`` with ``--set-state``,
    ``switch_controller`` with ``--set-state active``)."""
    load = cli_load(decl)
    if load is None:
        return None
    manager = load.manager if load.manager.startswith("/") else (
        f"{decl.namespace.rstrip('/')}/{load.manager}")
    verbs = ["list_controllers", "load_controller"]
    if load.state:
        verbs.append("configure_controller")
    if load.state == "active":
        verbs.append("switch_controller")
    calls = [PrimitiveCall("client", f"{manager}/{verb}", _SPAWNER_TYPES[verb],
                           location=decl.location, origin="arguments") for verb in verbs]
    if load.param_file:
        calls.append(PrimitiveCall("client", f"{manager}/set_parameters",
                                   "rcl_interfaces/srv/SetParameters",
                                   location=decl.location, origin="arguments"))
    node = _node(decl, "ros2controlcli", calls[0], "python")
    node.calls = calls
    return node


_SPAWNER_TYPES = {verb: "controller_manager_msgs/srv/" + "".join(
    part.capitalize() for part in verb.split("_"))
    for verb in ("list_controllers", "load_controller", "configure_controller",
                 "switch_controller", "unload_controller")}


def program_words(args: str) -> list[str]:
    """The words a ROS 2 program's own parser sees: those outside ``--ros-args ...
    [--]``, which rclpy's ``remove_ros_args`` takes away."""
    return split_arguments(shell_words(args))[0]


_SPAWNER_VALUES = {"--wait-for", "--namespace", "--timeout", "--shutdown-timeout"}


def refused(decl: NodeDecl) -> str | None:
    """Why a program whose command line is read here refuses the one it is given and
    exits before it starts a node, when its arguments, all known, say so: a ROS 1
    spawner names no controller (``parse_args`` runs before ``init_node``, and its
    ``controllers`` argument is ``nargs='+'``); else None."""
    if (decl.package, decl.executable) != ("controller_manager", "spawner") or (
            decl.ros_version != 1 or UNKNOWN_MARK in decl.args):
        return None
    positional, _values, _flags = split_options(_words(decl.args), _SPAWNER_VALUES)
    if positional:
        return None
    return "its arguments name no controller, which argparse requires"


def _spawner(decl: NodeDecl, words: list[str]) -> Node | None:
    """A ROS 1 controller spawner from its arguments (see the module's docstring)."""
    positional, values, _flags = split_options(words, _SPAWNER_VALUES)
    if not positional:  # argparse refuses it: no controller named
        why = refused(decl)
        if why is None:
            return None  # arguments not known: its interface model
        node = Node("controller_manager", decl.executable, "executable", "python",
                    location=decl.location)
        node.model = f"the arguments of controller_manager spawner: {why}; it exits"
        node.completeness = "model"
        return node
    namespace = values.get("--namespace", "")
    if namespace and not namespace.endswith("/"):
        namespace += "/"
    calls = [PrimitiveCall("client", f"{namespace}controller_manager/{verb}_controller",
                           f"controller_manager_msgs/{verb.capitalize()}Controller",
                           location=decl.location, origin="arguments")
             for verb in ("load", "switch", "unload")]
    if values.get("--wait-for"):
        calls.append(PrimitiveCall("subscribe", values["--wait-for"], "std_msgs/Bool",
                                   location=decl.location, origin="arguments"))
    calls.append(PrimitiveCall("read", "/use_sim_time", "bool", location=decl.location,
                               origin="arguments", has_default=True, default=False))
    node = _node(decl, "controller_manager", calls[0], "python")
    node.calls = calls
    return node


GAZEBO_SPAWNER_VALUES = {"-file", "-param", "-database", "-model", "-reference_frame",
                         "-gazebo_namespace", "-robot_namespace", "-wait", "-x", "-y", "-z",
                         "-R", "-P", "-Y"}


def _gazebo_spawner(decl: NodeDecl, words: list[str]) -> Node | None:
    """gazebo_ros' ROS 1 ``spawn_model`` from its arguments (see the module's docstring);
    None when they are not known or argparse refuses them (neither ``-urdf`` nor
    ``-sdf``): its interface model stands."""
    joints: list[str] = []
    rest: list[str] = []
    index = 0
    while index < len(words):  # -J NAME VALUE: two values
        if words[index] == "-J":
            joints.extend(words[index + 1:index + 3])
            index += 3
            continue
        rest.append(words[index])
        index += 1
    positional, values, flags = split_options(rest, GAZEBO_SPAWNER_VALUES)
    if positional or any("?" in word for word in words) or not flags & {"-urdf", "-sdf"}:
        return None
    gazebo = values.get("-gazebo_namespace", "/gazebo").rstrip("/")
    calls: list[tuple[CallKind, str, str | None]] = []
    if "-wait" in values:
        calls.append(("subscribe", f"{gazebo}/model_states", "gazebo_msgs/ModelStates"))
    if "-param" in values:
        calls.append(("read", values["-param"], "str"))
    kind = "urdf" if "-urdf" in flags else "sdf"
    calls.append(("client", f"{gazebo}/spawn_{kind}_model", "gazebo_msgs/SpawnModel"))
    if joints:
        calls.append(("client", f"{gazebo}/set_model_configuration",
                      "gazebo_msgs/SetModelConfiguration"))
    if "-unpause" in flags:
        calls.append(("client", f"{gazebo}/unpause_physics", "std_srvs/Empty"))
    if "-b" in flags:
        calls.append(("client", f"{gazebo}/delete_model", "gazebo_msgs/DeleteModel"))
    made = [PrimitiveCall(kind_, name, type_, queue_size=1 if kind_ == "subscribe" else None,
                          location=decl.location, origin="arguments")
            for kind_, name, type_ in calls]
    node = _node(decl, "gazebo_ros", made[0], "python")
    node.calls = made
    return node


def _topic_tools(decl: NodeDecl, words: list[str]) -> Node | None:
    """A ROS 1 topic_tools node from its arguments (see the module's docstring)."""
    tool, args = decl.executable, [w for w in words if not w.startswith("__")]
    calls: list[tuple[CallKind, str, str | None]] = []  # (kind, name, type)
    on_handle: list[tuple[CallKind, str, str | None]] = []  # of those, made on mux_nh
    params = TOPIC_TOOLS_READS.get(tool)
    if params is None:
        return None
    if tool == "relay" and 1 <= len(args) <= 2:
        calls = [("subscribe", args[0], None),
                 ("publish", args[1] if len(args) > 1 else args[0] + "_relay", None)]
    elif tool in ("mux", "demux") and len(args) >= 2:
        one: CallKind = "publish" if tool == "mux" else "subscribe"
        many: CallKind = "subscribe" if tool == "mux" else "publish"
        calls = [(one, args[0], None), *((many, name, None) for name in args[1:])]
        kind = tool.capitalize()
        on_handle = [("publish", f"{tool}/selected", "std_msgs/String"),
                     *(("server", f"{tool}/{verb}", f"topic_tools/{kind}{verb.capitalize()}")
                       for verb in ("select", "add", "list", "delete"))]
        calls += on_handle
        if tool == "mux":
            calls.append(("server", args[0] + "_select", "topic_tools/MuxSelect"))
    elif tool == "throttle" and len(args) >= 3 and args[0] in ("messages", "bytes"):
        out = 3 if args[0] == "messages" else 4
        calls = [("subscribe", args[1], None), ("publish", args[out] if len(args) > out
                                               else args[1] + "_throttle", None)]
    elif tool == "drop" and len(args) in (3, 4):
        calls = [("subscribe", args[0], None),
                 ("publish", args[3] if len(args) == 4 else args[0] + "_drop", None)]
    if not calls:
        return None
    # mux and demux make ``selected`` and their services on ``NodeHandle mux_nh("mux")``
    # (``demux_nh("demux")``): roscpp remaps that namespace first, so ``mux:=base_mux``
    # moves all five (``graph.build._handle_name``)
    made = [PrimitiveCall(kind, name, type_, queue_size=None if kind == "server" else (
        1 if name.endswith("/selected") else 10), latch=name.endswith("/selected"),
        location=decl.location, origin="arguments",
        handle_namespace=tool if (kind, name, type_) in on_handle else None)
        for kind, name, type_ in calls]
    made += [PrimitiveCall("read", name, type_, location=decl.location, origin="arguments",
                           has_default=True, default=default)
             for name, (type_, default) in params.items()]
    node = _node(decl, "topic_tools", made[0], "cpp")
    node.calls = made
    return node


def _words(args: str) -> list[str]:
    return [w for w in shell_words(args) if ":=" not in w and w != "--ros-args"]


def split_options(words: list[str], value_options: set[str]
                  ) -> tuple[list[str], dict[str, str], set[str]]:
    """Positional words, options with values and flags, as optparse / argparse split them."""
    positional: list[str] = []
    values: dict[str, str] = {}
    flags: set[str] = set()
    index = 0
    while index < len(words):
        word = words[index]
        if word.startswith("--") and "=" in word:
            key, _, value = word.partition("=")
            values[key] = value
        elif word in value_options and index + 1 < len(words):
            values[word] = words[index + 1]
            index += 1
        elif word.startswith("-") and len(word) > 1:
            flags.add(word)
        else:
            positional.append(word)
        index += 1
    return positional, values, flags


# rostopic's verbs that subscribe to the topics they name, with their options that take
# a value and the parameter each reads after ``init_node`` (see ``_rostopic_watch``)
ROSTOPIC_WATCHERS: dict[str, tuple[set[str], str | None]] = {
    "echo": ({"-b", "--bag", "-w", "--filter", "-n"}, "/use_sim_time"),
    "hz": ({"-w", "--window", "--filter"}, "use_sim_time"),
    "delay": ({"-w", "--window"}, "use_sim_time"),
    "bw": ({"-w", "--window"}, None)}


def _rostopic(decl: NodeDecl, words: list[str]) -> Node | None:
    if words and words[0] in ROSTOPIC_WATCHERS:
        return _rostopic_watch(decl, words[0], words[1:])
    if not words or words[0] != "pub":
        return None
    positional, values, flags = split_options(words[1:], ROS1_VALUE_OPTIONS)
    if not positional:
        return None
    rate = values.get("-r", values.get("--rate"))
    latch = rate is None or bool(flags & {"-l", "--latch"})
    type_ = positional[1] if len(positional) > 1 else None
    call = PrimitiveCall("publish", positional[0], type_, queue_size=100, latch=latch,
                         location=decl.location, origin="arguments")
    return _node(decl, "rostopic", call, "python")


def _rostopic_watch(decl: NodeDecl, verb: str, words: list[str]) -> Node | None:
    """``rostopic echo|hz|delay|bw [options] TOPIC...`` (ros_comm noetic-devel
    ``tools/rostopic/src/rostopic/__init__.py``, ``_rostopic_cmd_<verb>``): a subscriber
    of each topic, which ``script_resolve_name`` puts in the node's namespace, with the
    type its publishers have (looked up when it runs: any here), and no bounded queue.
    ``hz`` takes several topics, the others one; ``echo -b BAG`` reads a bag file and
    subscribes to nothing. ``echo`` then reads ``/use_sim_time`` and ``hz`` and ``delay``
    ``use_sim_time``, each with the default False. A name may go on into a field of the
    message (``echo /odom/pose/pose``), and rostopic then subscribes to the longest
    part of it that is a published topic when it runs (``_get_topic_type``, for each
    verb): the call says so (``name_field``), and the graph, which knows the topics,
    chooses. None when optparse or argparse refuses the words, or they are not known."""
    values_of, parameter = ROSTOPIC_WATCHERS[verb]
    if any(UNKNOWN_MARK in word for word in words):
        return None
    positional, values, _flags = split_options(
        [word for word in words if not word.startswith("__")], values_of)
    if not positional or (verb != "hz" and len(positional) > 1):
        return None
    calls: list[PrimitiveCall] = []
    if verb != "echo" or not (values.get("-b") or values.get("--bag")):
        calls = [PrimitiveCall("subscribe", topic, None, location=decl.location,
                               origin="arguments", name_field=True) for topic in positional]
        if parameter is not None:
            calls.append(PrimitiveCall("read", parameter, "bool", location=decl.location,
                                       origin="arguments", has_default=True, default=False))
    node = Node("rostopic", decl.executable, "executable", "python", calls=calls,
                location=decl.location)
    node.model = f"the arguments of rostopic {verb}"
    node.completeness = "model"
    return node


def _rosservice(decl: NodeDecl, words: list[str]) -> Node | None:
    """``rosservice call [-v] [--wait] SERVICE [ARGS...]``: a client of SERVICE (the
    other verbs only look at the master). Its type is the one the server has, looked up
    when it runs (``get_service_class_by_name``): not known here."""
    if not words or words[0] != "call":
        return None
    positional, _values, _flags = split_options(words[1:], set())
    if not positional:
        return None  # optparse refuses it: "service must be specified"
    call = PrimitiveCall("client", positional[0], None, location=decl.location,
                         origin="arguments")
    return _node(decl, "rosservice", call, "python")


# dynparam's verbs that make a dynamic_reconfigure client of the node they name, and how
# many words each takes after its options (the node, then a file or values)
_DYNPARAM_VERBS = {"set": (2, 3), "set_from_parameters": (1, 1), "get": (1, 1),
                   "load": (2, 2), "dump": (2, 2)}


def _dynparam(decl: NodeDecl, words: list[str]) -> Node | None:
    """dynamic_reconfigure's ``dynparam VERB [-t T] NODE ...``: a client of NODE's
    reconfigure server (``dynamic_reconfigure.client.Client(NODE)``: the service
    ``NODE/set_parameters`` and the topics ``NODE/parameter_descriptions`` and
    ``NODE/parameter_updates``, NODE resolved in the node's namespace); with
    ``set_from_parameters`` it also reads its private namespace whole (the values it
    copies, ``rospy.get_param("~")``). ``list`` asks the master only. None when the
    verb or the words are not known, or optparse refuses them."""
    if not words or words[0] not in _DYNPARAM_VERBS or any("?" in w for w in words):
        return None
    low, high = _DYNPARAM_VERBS[words[0]]
    if words[0] == "set":  # a word starting with "-" and a digit is a value
        positional = [w for w in words[1:] if not w.startswith("-") or w[1:2].isdigit()]
    else:
        positional, _values, _flags = split_options(words[1:], {"-t", "--timeout"})
    if not low <= len(positional) <= high:
        return None
    server = positional[0].rstrip("/")
    service, kind = RECONFIGURE_SERVICE
    calls = [PrimitiveCall("client", f"{server}/{service}", kind, location=decl.location,
                           origin="arguments"),
             *(PrimitiveCall("subscribe", f"{server}/{topic}", type_, location=decl.location,
                             origin="arguments") for topic, type_ in RECONFIGURE_TOPICS)]
    if words[0] == "set_from_parameters":
        calls.append(PrimitiveCall("read", "~", None, location=decl.location,
                                   origin="arguments"))
    node = _node(decl, "dynamic_reconfigure", calls[0], "python")
    node.calls = calls
    return node


def _qos_options(values: dict[str, str]) -> dict[str, Any] | None:
    """The QoS a ros2topic verb's ``--qos-*`` options say (None when they say nothing)."""
    return {key: int(values[option]) if values[option].isdigit()
            else values[option].replace("-", "_")
            for option, key in ROS2_QOS.items() if option in values} or None


def _interface(written: str, kind: str) -> str:
    """The type a ros2cli verb takes ``written`` for: ``pkg/Name`` is ``pkg/<kind>/Name``
    (rosidl_runtime_py's ``get_message`` / ``get_service`` add the namespace of the
    kind), the rest as written. warehouse_bot's ``ros2 topic pub /robot1/initialpose
    geometry_msgs/PoseWithCovarianceStamped ...`` publishes
    geometry_msgs/msg/PoseWithCovarianceStamped, the type amcl subscribes with."""
    parts = written.split("/")
    return f"{parts[0]}/{kind}/{parts[1]}" if len(parts) == 2 else written


def _ros2_topic(decl: NodeDecl, words: list[str]) -> Node | None:
    positional, values, _flags = split_options(words[1:], ROS2_VALUE_OPTIONS)
    if not positional:
        return None
    type_ = _interface(positional[1], "msg") if len(positional) > 1 else None
    call = PrimitiveCall("publish", positional[0], type_, qos=_qos_options(values),
                         location=decl.location,
                         origin="arguments")
    return _node(decl, decl.package or "ros2topic", call, "python")


# ros2topic's verbs that subscribe to the topics they name (ros2cli
# ``ros2topic/ros2topic/verb/<verb>.py``), with their options that take a value
_ROS2_QOS_VALUES = {"--qos-profile", "--qos-depth", "--qos-history", "--qos-reliability",
                    "--qos-durability", "--qos-liveliness",
                    "--qos-liveliness-lease-duration-seconds"}
ROS2_TOPIC_WATCHERS: dict[str, set[str]] = {
    "echo": {*_ROS2_QOS_VALUES, "--field", "--truncate-length", "-l", "--filter",
             "--timeout", "--spin-time"},
    "hz": {"--window", "-w", "--filter", "--spin-time"},
    "bw": {"--window", "-w", "--spin-time"},
    "delay": {"--window", "-w", "--spin-time"}}


def _ros2_topic_watch(decl: NodeDecl, verb: str, words: list[str]) -> Node | None:
    """``ros2 topic echo|hz|bw|delay [options] TOPIC...``: a subscriber of each topic.
    ``echo TOPIC [TYPE]`` subscribes with the type given, else its publishers' (looked
    up when it runs), and with the QoS its ``--qos-*`` options say, else one chosen from
    its publishers' when it runs (unknown here); ``hz`` (several topics from Jazzy on),
    ``bw`` and ``delay`` subscribe with ``qos_profile_sensor_data``. None when argparse
    would refuse the words, or they are not known."""
    if any(UNKNOWN_MARK in word for word in words):
        return None
    positional, values, _flags = split_options(words, ROS2_TOPIC_WATCHERS[verb])
    most = {"echo": 2, "hz": None}.get(verb, 1)
    if not positional or (most is not None and len(positional) > most):
        return None
    if verb == "echo":
        type_ = _interface(positional[1], "msg") if len(positional) > 1 else None
        calls = [PrimitiveCall("subscribe", positional[0], type_, qos=_qos_options(values),
                               location=decl.location, origin="arguments")]
    else:
        calls = [PrimitiveCall("subscribe", topic, None,
                               qos=dict(PRESETS["qos_profile_sensor_data"]),
                               location=decl.location, origin="arguments")
                 for topic in positional]
    node = Node(decl.package or "ros2topic", decl.executable, "executable", "python",
                calls=calls, location=decl.location)
    node.model = f"the arguments of ros2 topic {verb}"
    node.completeness = "model"
    return node


def _ros2_service(decl: NodeDecl, words: list[str]) -> Node | None:
    """``ros2 service call SERVICE TYPE [VALUES] [--stdin] [-r RATE]``: a client of
    SERVICE of TYPE (``pkg/Name`` is ``pkg/srv/Name``, as the verb imports it); None
    when argparse would refuse the words (the two are required)."""
    positional, _values, _flags = split_options(words, {"-r", "--rate"})
    if len(positional) < 2:
        return None
    call = PrimitiveCall("client", positional[0], _interface(positional[1], "srv"),
                         location=decl.location,
                         origin="arguments")
    return _node(decl, decl.package or "ros2service", call, "python")


# ros2lifecycle's ``set`` options that take a value (ros2cli's NodeStrategy arguments)
_LIFECYCLE_VALUES = {"--spin-time"}


def _ros2_lifecycle_set(decl: NodeDecl, words: list[str]) -> Node | None:
    """``ros2 lifecycle set NODE TRANSITION``: when NODE is a running node's full name,
    a client of ``NODE/get_available_transitions`` (lifecycle_msgs GetAvailableTransitions)
    and of ``NODE/change_state`` (ChangeState); None when argparse would refuse the
    words (both are required)."""
    positional, _values, _flags = split_options(words, _LIFECYCLE_VALUES)
    if len(positional) < 2:
        return None
    node = positional[0] if positional[0].startswith("/") else "/" + positional[0]
    calls = [PrimitiveCall("client", f"{node.rstrip('/')}/{service}",
                           f"lifecycle_msgs/srv/{kind}", location=decl.location,
                           origin="arguments")
             for service, kind in (("get_available_transitions", "GetAvailableTransitions"),
                                   ("change_state", "ChangeState"))]
    made = _node(decl, decl.package or "ros2lifecycle", calls[0], "python")
    made.calls = calls
    return made


def _node(decl: NodeDecl, package: str, call: PrimitiveCall, language: Any) -> Node:
    node = Node(package, decl.executable, "executable", language, calls=[call],
                location=decl.location)
    node.model = f"the arguments of {decl.package or 'ros2'} {decl.executable}"
    node.completeness = "model"
    return node
