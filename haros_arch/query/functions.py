"""The functions a query may call. Each is a plain function of query values.

Functions that do work proportional to their input charge the evaluator's step budget
through ``charge``, so they cannot be used to escape the limits.
"""

from __future__ import annotations

import posixpath
import re
from collections import deque
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

from .. import manifest
from ..model import rosname
from ..model.conditions import Condition, after_exit, exclusive, same_conditions
from ..model.conditions import undecided as undecided_of
from ..model.runtime import Configuration, Link, NodeInstance, Parameter, Resource
from ..model.source import Package
from ..model.values import UNKNOWN_MARK
from ..plugins.hosts import TRANSPORTS
from .absence import (
    distance,
    meeting,
    reads_dropped,
    same_setting,
    same_setting_elsewhere,
    similar_to,
    unknown_users,
)
from .access import readers_of
from .errors import QueryLimitError, QueryTypeError

Charge = Callable[[int], None]


@dataclass(frozen=True)
class Function:
    """A whitelisted function: its name, arity bounds and implementation."""

    name: str
    impl: Callable[..., Any]
    min_args: int = 1
    max_args: int = 1
    charged: bool = False  # impl takes ``charge`` as its first argument

    def __repr__(self) -> str:
        return f"<function {self.name}>"


def _items(value: Any) -> list[Any]:
    if isinstance(value, str) or not isinstance(value, list | tuple | set | frozenset | dict):
        raise QueryTypeError(f"expected a collection, got {type(value).__name__}")
    return list(value)


def _len(charge: Charge, value: Any) -> int:
    if isinstance(value, str | list | tuple | set | frozenset | dict):
        return len(value)
    raise QueryTypeError(f"len() of {type(value).__name__}")


def _aggregate(name: str, impl: Callable[..., Any]) -> Callable[..., Any]:
    def run(charge: Charge, *args: Any) -> Any:
        items = _items(args[0]) if len(args) == 1 else list(args)
        charge(len(items))
        try:
            return impl(items)
        except (TypeError, ValueError) as err:
            raise QueryTypeError(f"{name}(): {err}") from None
    return run


def _abs(charge: Charge, value: Any) -> Any:
    if isinstance(value, int | float):
        return abs(value)
    raise QueryTypeError(f"abs() of {type(value).__name__}")


def is_rosglobal(charge: Charge, name: Any) -> bool:
    return isinstance(name, str) and name.startswith("/")


def is_legal_name(charge: Charge, name: Any) -> bool:
    """Whether roscpp and rospy accept a ROS 1 name (``?`` for an unknown part)."""
    if not isinstance(name, str):
        raise QueryTypeError("is_legal_name() takes a string")
    charge(1 + len(name) // 256)
    return rosname.is_legal_name(name)


MAX_DISTANCE_INPUT = 4096


def edit_distance(charge: Charge, a: Any, b: Any) -> int:
    """Levenshtein distance between two strings."""
    if not isinstance(a, str) or not isinstance(b, str):
        raise QueryTypeError("edit_distance() takes two strings")
    if len(a) > MAX_DISTANCE_INPUT or len(b) > MAX_DISTANCE_INPUT:
        raise QueryLimitError(f"edit_distance() on strings longer than {MAX_DISTANCE_INPUT}")
    charge(1 + len(a) * len(b) // 64)
    return distance(a, b)


# the last segments image_transport adds to a base topic (``image/compressed``): the name
# a topic is about is the segment before them
_TRANSPORT_SUFFIXES = frozenset(t.name for t in TRANSPORTS if t.name != "raw")


def topic_stem(charge: Charge, name: Any) -> str:
    """The last segment of a ROS name, or the one before it when the last is an
    image_transport transport's suffix: ``/cam/image/compressed`` is about ``image``
    (every compressed image topic ends in ``compressed``)."""
    if not isinstance(name, str):
        raise QueryTypeError("topic_stem() takes a name")
    charge(1)
    parts = [p for p in name.split("/") if p]
    if len(parts) > 1 and parts[-1] in _TRANSPORT_SUFFIXES:
        return parts[-2]
    return parts[-1] if parts else ""


def common_tail(charge: Charge, a: Any, b: Any) -> int:
    """How many last segments two ROS names share: ``/cybership/thruster/bow_port/issued``
    and ``/drillship/thruster/bow_port/issued`` 3, and ``/drillship/thruster/stern/issued``
    1 (which of several alike topics is a topic's closest partner)."""
    if not isinstance(a, str) or not isinstance(b, str):
        raise QueryTypeError("common_tail() takes two names")
    charge(1)
    left, right = [p for p in a.split("/") if p], [p for p in b.split("/") if p]
    shared = 0
    while shared < min(len(left), len(right)) and left[-1 - shared] == right[-1 - shared]:
        shared += 1
    return shared


def name_similarity(charge: Charge, a: Any, b: Any) -> float:
    """1.0 for equal names, towards 0.0 as the edit distance grows (over the longer)."""
    longest = max(len(a), len(b)) if isinstance(a, str) and isinstance(b, str) else 0
    if not longest:
        return 1.0 if a == b else 0.0
    return 1.0 - edit_distance(charge, a, b) / longest


def _downstream(entity: Any) -> Iterable[Any]:
    """Who an entity sends to: node -> topics it publishes / services it calls -> nodes."""
    if isinstance(entity, NodeInstance):
        for link in entity.links:
            if link.kind in ("publish", "client", "action-client", "write"):
                yield link.resource
    elif isinstance(entity, Resource):
        for link in entity.links:
            if link.kind in ("subscribe", "server", "action-server", "read"):
                yield link.node


def reachable(charge: Charge, source: Any, target: Any) -> bool:
    """True when data can flow from ``source`` to ``target`` (nodes or resources)."""
    if isinstance(source, Link):
        source = source.node
    if isinstance(target, Link):
        target = target.node
    if not isinstance(source, NodeInstance | Resource):
        raise QueryTypeError("reachable() takes node instances, topics, services, "
                             "actions or parameters")
    seen = {id(source)}
    queue = deque([source])
    while queue:
        current = queue.popleft()
        charge(1)
        if current is target and current is not source:
            return True
        for following in _downstream(current):
            if following is target:
                return True
            if id(following) not in seen:
                seen.add(id(following))
                queue.append(following)
    return False


_RELIABILITY = {"best_effort": 0, "reliable": 1}
_DURABILITY = {"volatile": 0, "transient_local": 1}


def qos_incompatible(charge: Charge, offered: Any, requested: Any) -> str:
    """Why a publisher's QoS cannot serve a subscriber's, or "" when it can (or unknown).

    Follows the ROS 2 request-vs-offered rules: reliability, durability, deadline and
    liveliness lease duration, where both sides give them.
    """
    if not isinstance(offered, dict) or not isinstance(requested, dict):
        return ""

    def rank(table: dict[str, int], side: dict[str, Any], key: str) -> int | None:
        value = side.get(key)
        return table.get(str(value).lower()) if value is not None else None

    off, req = rank(_RELIABILITY, offered, "reliability"), rank(_RELIABILITY, requested,
                                                                   "reliability")
    if off is not None and req is not None and off < req:
        return "the publisher is best-effort but the subscriber requires reliable"
    off, req = rank(_DURABILITY, offered, "durability"), rank(_DURABILITY, requested,
                                                                 "durability")
    if off is not None and req is not None and off < req:
        return "the publisher is volatile but the subscriber requires transient-local"
    for key, what in (("deadline", "deadline"), ("liveliness_lease_duration",
                                                  "liveliness lease duration")):
        a, b = offered.get(key), requested.get(key)
        if isinstance(a, int | float) and isinstance(b, int | float) and a > b:
            return f"the publisher offers a longer {what} ({a}) than the subscriber " \
                   f"requests ({b})"
    return ""


def _str(charge: Charge, value: Any) -> str:
    if isinstance(value, str | int | float | bool) or value is None:
        return str(value)
    raise QueryTypeError(f"str() of {type(value).__name__}")


def _number(kind: type) -> Callable[[Charge, Any], Any]:
    def convert(charge: Charge, value: Any) -> Any:
        if isinstance(value, str | int | float | bool):
            try:
                return kind(value)
            except (ValueError, OverflowError) as err:  # int(inf), a 5,000-digit string
                raise QueryTypeError(str(err)) from None
        raise QueryTypeError(f"{kind.__name__}() of {type(value).__name__}")
    return convert


def _bool(charge: Charge, value: Any) -> bool:
    return bool(value)


def _round(charge: Charge, value: Any, digits: Any = 0) -> Any:
    if isinstance(value, int | float) and isinstance(digits, int):
        if isinstance(value, int) and digits < 0 and -digits > value.bit_length() // 3 + 2:
            return 0  # Python would compute 10 ** -digits first: round(5, -10**9) never ends
        return round(value, digits)
    raise QueryTypeError("round() takes a number")


_MANY = 1 << 20
FUNCTIONS: dict[str, Function] = {f.name: f for f in (
    Function("len", _len, charged=True),
    Function("min", _aggregate("min", min), 1, _MANY, charged=True),
    Function("max", _aggregate("max", max), 1, _MANY, charged=True),
    Function("sum", _aggregate("sum", sum), 1, _MANY, charged=True),
    Function("any", _aggregate("any", any), charged=True),
    Function("all", _aggregate("all", all), charged=True),
    Function("abs", _abs, charged=True),
    Function("bool", _bool, charged=True),
    Function("int", _number(int), charged=True),
    Function("float", _number(float), charged=True),
    Function("str", _str, charged=True),
    Function("round", _round, 1, 2, charged=True),
    Function("is_rosglobal", is_rosglobal, charged=True),
    Function("is_legal_name", is_legal_name, charged=True),
    Function("edit_distance", edit_distance, 2, 2, charged=True),
    Function("topic_stem", topic_stem, charged=True),
    Function("common_tail", common_tail, 2, 2, charged=True),
    Function("name_similarity", name_similarity, 2, 2, charged=True),
    Function("reachable", reachable, 2, 2, charged=True),
    Function("qos_incompatible", qos_incompatible, 2, 2, charged=True),
)}


def group_by(charge: Charge, values: Any, field: Any) -> list[list[Any]]:
    """The values of a list in groups of equal ``field`` (a field a query may read, or
    a dotted path of them: ``'name'``, ``'rosname.own'``): one list per value of it, in
    the order each is first seen, the values of each in the list's order. What a rule
    reports once per name, not once per pair, iterates over (the node instances of one
    name)."""
    if not isinstance(field, str) or not field:
        raise QueryTypeError("group_by() takes a list and a field name")
    path = field.split(".")
    groups: dict[Any, list[Any]] = {}
    for value in _items(values):
        charge(len(path))
        key = value
        for name in path:
            read = readers_of(type(key)).get(name)
            if read is None:
                raise QueryTypeError(f"group_by(): {type(key).__name__} has no field "
                                     f"'{name}'")
            key = read(key)
        try:
            groups.setdefault(key, []).append(value)
        except TypeError:  # a list or a map: grouped as the same object only
            groups.setdefault(("#id", id(key)), []).append(value)
    return list(groups.values())


FUNCTIONS["group_by"] = Function("group_by", group_by, 2, 2, charged=True)


# ``/Users/``: a macOS home, as ``/home/`` is Linux's (voxblox's eval launch files)
_PATH_PREFIXES = ("/home/", "/opt/", "/usr/", "/mnt/", "/media/", "/root/",
                  "/var/", "/etc/", "/srv/", "/Users/")
# folders every Linux machine has with the same meaning, whatever was installed or who
# uses it: scratch space for files a run writes (robot_localization's ``debug_out_file``
# ``/tmp/robot_localization_debug.txt``), the run's sockets and locks, and the kernel's
# devices (``/dev/ttyUSB0``) and views of the system (``/proc``, ``/sys``). A path there
# names the same thing on the robot as on the author's machine: no portability mistake.
_SYSTEM_FOLDERS = ("/tmp/", "/var/tmp/", "/run/", "/var/run/", "/dev/", "/proc/", "/sys/")
_FILE_SUFFIXES = (".yaml", ".yml", ".urdf", ".xacro", ".launch", ".xml", ".json", ".pgm",
                  ".png", ".bag", ".db3", ".csv", ".txt", ".so", ".py", ".cfg", ".ini")


_XML_COMMENT = re.compile(r"<!--.*?(?:-->|$)", re.DOTALL)
_SLASHES = re.compile(r"/{2,}")


def is_absolute_path(charge: Charge, value: Any, portable: Any = ()) -> bool:
    """True when a value (or a word of it) looks like an absolute filesystem path that
    is not one of the ``portable`` folders (``config.package_paths``: where ``$(find
    pkg)`` led, what the launch files took from the environment) or under one."""
    if not isinstance(value, str):
        return False
    folders = [f.rstrip("/") + "/" for f in _items(portable) if isinstance(f, str)] \
        if portable else []
    charge(1 + len(value) // 256 + len(folders))
    # the words of an XML comment are prose, no value a program reads: a document loaded
    # with ``textfile`` (amr-ros-config's URDF says to install meshes "/opt/ros/... or
    # from source repository")
    for word in _XML_COMMENT.sub(" ", value).replace("=", " ").split():
        # repeated slashes are one (POSIX): "/$(find pkg)/x" is "//<the package>/x"
        word = _SLASHES.sub("/", word.strip("'\""))
        if any(word.startswith(folder) or word == folder[:-1] for folder in folders):
            continue
        if posixpath.normpath(word).startswith(_SYSTEM_FOLDERS):
            continue
        if word.startswith(_PATH_PREFIXES) or (
                word.startswith("/") and word.lower().endswith(_FILE_SUFFIXES)):
            return True
    return False


FUNCTIONS["is_absolute_path"] = Function("is_absolute_path", is_absolute_path, max_args=2,
                                         charged=True)


# topics the ROS client libraries and standard tools use by convention, under names
# the node's author does not choose: tf, diagnostics, logging, simulated time, ROS 2
# parameter events, and dynamic_reconfigure's description / update topics of a node
_INFRASTRUCTURE = frozenset({"/tf", "/tf_static", "/diagnostics", "/diagnostics_agg",
                             "/rosout", "/rosout_agg", "/clock", "/parameter_events"})
# ... and wherever they are: dynamic_reconfigure's topics of each server, and tf's and
# diagnostics' topics of a robot in a namespace (``/robot1/tf`` of the usual
# ``remappings=[("/tf", "tf")]``, which every broadcaster of the robot publishes)
_INFRASTRUCTURE_OWN = frozenset({"parameter_descriptions", "parameter_updates", "tf",
                                 "tf_static", "diagnostics", "diagnostics_agg",
                                 # bondcpp: both sides of a bond publish on its one topic
                                 "bond"})


def is_infrastructure(charge: Charge, name: Any) -> bool:
    """True for a topic name that ROS libraries and tools use by convention; for a name
    with ``?``, also when it could be one of the root names (``/?``, ``?``: a name of
    which nothing is known could be any)."""
    if not isinstance(name, str):
        return False
    charge(1)
    if name in _INFRASTRUCTURE or name.rsplit("/", 1)[-1] in _INFRASTRUCTURE_OWN:
        return True
    if UNKNOWN_MARK not in name:
        return False
    pattern = re.compile(rosname.pattern_for(name))
    return any(pattern.match(each) for each in _INFRASTRUCTURE)


FUNCTIONS["is_infrastructure"] = Function("is_infrastructure", is_infrastructure,
                                          charged=True)


# the topics of tf2's frame tree, which every broadcaster of a robot publishes: at the
# root, or in the robot's namespace where its nodes are remapped so (``/robot1/tf``)
_FRAME_TREE = frozenset({"tf", "tf_static"})


def frame_tree_elsewhere(charge: Charge, config: Any, link: Any) -> list[str]:
    """For a subscription to a topic of the frame tree in a namespace (``/prbt/tf``:
    code run in ``prbt`` waiting on the relative name ``tf``) that nothing publishes, the
    names of that topic elsewhere in ``config`` that something does publish (``/tf``):
    the transforms go there, not where the subscriber listens. Empty for any other
    link, and where the topic has a publisher or no namespace, so a convention name
    nobody publishes in the configuration (a driver's, started elsewhere) stays out; and
    where the code wrote the global name (tf2's listener's ``/tf``) that a remap moved
    into the namespace: the usual ``/tf:=tf`` of a robot's nodes, whose broadcasters
    the same remap moves, is the launch's convention, not the code's mistake."""
    if not isinstance(config, Configuration) or not isinstance(link, Link):
        raise QueryTypeError("frame_tree_elsewhere() takes a configuration and a link")
    charge(1)
    name = link.rosname.full
    head, _, last = name.rpartition("/")
    if (link.kind != "subscribe" or last not in _FRAME_TREE or not head
            or link.rosname.given.startswith("/")
            or UNKNOWN_MARK in name or name in _INFRASTRUCTURE
            or any(each.kind == "publish" for each in link.resource.links)):
        return []
    charge(1 + len(config.topics) // 64)
    return sorted(topic.name for topic in config.topics
                  if topic.name != name and topic.name.rpartition("/")[2] == last
                  and UNKNOWN_MARK not in topic.name
                  and any(each.kind == "publish" for each in topic.links))


FUNCTIONS["frame_tree_elsewhere"] = Function("frame_tree_elsewhere", frame_tree_elsewhere,
                                             2, 2, charged=True)


# services a node offers by itself, under names its author does not choose, so that a
# client of one has its server wherever the node runs: ROS 2's parameter services and
# type description service of every node, a lifecycle node's state services, ROS 1's
# logger services of every roscpp node, dynamic_reconfigure's ``<server>/set_parameters``
_OWN_SERVICES = frozenset({
    "get_parameters", "get_parameter_types", "set_parameters", "set_parameters_atomically",
    "describe_parameters", "list_parameters", "get_type_description",
    "change_state", "get_state", "get_available_states", "get_available_transitions",
    "get_transition_graph", "get_loggers", "set_logger_level"})


# the services a lifecycle node offers by itself (rclcpp_lifecycle's and rclpy's
# LifecycleNode): a node of that name must run to offer them
_LIFECYCLE_SERVICES = frozenset({"change_state", "get_state", "get_available_states",
                                 "get_available_transitions", "get_transition_graph"})


def is_own_service(charge: Charge, name: Any, config: Any = None) -> bool:
    """True for a service name that every node (or every lifecycle node, or
    dynamic_reconfigure server) offers by itself: its last segment is one of them.
    With ``config``, a lifecycle service only where a node of its prefix's name runs
    there (or one whose name is not known statically): ouster-ros' ``ros2 lifecycle set
    /ouster/os_sensor configure`` calls ``/ouster/os_sensor/change_state``, and no node
    of that name runs (its driver is /ouster/os_driver)."""
    if not isinstance(name, str):
        return False
    charge(1)
    prefix, _, last = name.rpartition("/")
    if last not in _OWN_SERVICES:
        return False
    if not isinstance(config, Configuration) or last not in _LIFECYCLE_SERVICES:
        return True
    charge(len(config.nodes))
    owner = prefix or "/"
    return any(node.name == owner or (UNKNOWN_MARK in node.name and re.match(
        rosname.pattern_for(node.name), owner) is not None) for node in config.nodes)


FUNCTIONS["is_own_service"] = Function("is_own_service", is_own_service, 1, 2,
                                       charged=True)


# checks that claim an absence, and similar-name pairing through an index (absence.py)
FUNCTIONS["unknown_users"] = Function("unknown_users", unknown_users, 2, 3, charged=True)
FUNCTIONS["similar_to"] = Function("similar_to", similar_to, 2, 2, charged=True)
FUNCTIONS["meeting"] = Function("meeting", meeting, 2, 2, charged=True)
FUNCTIONS["same_setting"] = Function("same_setting", same_setting, 2, 2, charged=True)
FUNCTIONS["same_setting_elsewhere"] = Function("same_setting_elsewhere",
                                              same_setting_elsewhere, 3, 3, charged=True)
FUNCTIONS["reads_dropped"] = Function("reads_dropped", reads_dropped, 2, 2, charged=True)


# topics that rviz's tools publish when an operator clicks: 2D Pose Estimate, 2D Nav Goal
# (ROS 1 and ROS 2) and Publish Point; nodes subscribe to them to wait for a person,
# also in a robot's namespace (summit_xl's amcl in /summit_xl: /summit_xl/initialpose,
# where the operator points the tool); and the command smach_viewer sends to a smach_ros
# IntrospectionServer to set a state machine's initial state (<server>/smach/container_init)
_TOOL_INPUTS = ("/initialpose", "/move_base_simple/goal", "/goal_pose", "/clicked_point",
                "/smach/container_init")


def is_tool_input(charge: Charge, name: Any) -> bool:
    """True for a topic that an operator's tool (rviz) publishes by convention, at the
    root or in a namespace."""
    charge(1)
    return isinstance(name, str) and name.endswith(_TOOL_INPUTS)


FUNCTIONS["is_tool_input"] = Function("is_tool_input", is_tool_input, charged=True)


def _conditions(value: Any, function: str) -> tuple[Condition, ...]:
    if not isinstance(value, NodeInstance | Link):
        raise QueryTypeError(f"{function}() takes node instances or links")
    return tuple(value.conditions)


def never_together(charge: Charge, first: Any, second: Any) -> bool:
    """True when the conditions of two node instances (or links) cannot both hold:
    ``<group if="$(eval model == 'a')">`` and ``'b'``, ``if`` and ``unless`` of one value;
    or when one instance starts only once the other's process has ended (a ROS 2 launch
    ``OnProcessExit`` whose target is the other)."""
    one, other = _conditions(first, "never_together"), _conditions(second, "never_together")
    charge(1 + len(one) * len(other))
    if isinstance(first, NodeInstance) and isinstance(second, NodeInstance) and (
        after_exit(one, second.location) or after_exit(other, first.location)
    ):
        return True
    return exclusive(one, other)


def apart(charge: Charge, first: Any, second: Any) -> list[Any]:
    """The two node instances (or links) when their conditions differ, so that one may
    exist without the other (an ``undecided_by`` list); none when they exist together."""
    one, other = _conditions(first, "apart"), _conditions(second, "apart")
    charge(1 + len(one) + len(other))
    return [] if same_conditions(one, other) else [first, second]


def together(charge: Charge, values: Any) -> list[Any]:
    """The node instances (or links) of a list that can exist together with another of
    it: none of two that ``never_together`` says exclude each other (the two branches of
    a launch file's ``if`` / ``else``, ``if`` and ``unless`` of one argument)."""
    if not isinstance(values, list):
        raise QueryTypeError("together() takes a list of node instances or links")
    return [one for one in values if any(
        other is not one and not never_together(charge, one, other) for other in values)]


def _one_ros1_name(first: Any, second: Any) -> bool:
    """Two ROS 1 node instances (or the links of two) of one name: they never run at one
    time, as the master keeps one node of a name (roslaunch refuses to start a launch
    that has two, LAUNCH_NODE_DUPLICATE; a node started later under the name shuts the
    earlier down; a nodelet manager refuses a second nodelet of a name it has)."""
    one = first.node if isinstance(first, Link) else first
    other = second.node if isinstance(second, Link) else second
    return (isinstance(one, NodeInstance) and isinstance(other, NodeInstance)
            and one is not other and one.ros_version == 1 and other.ros_version == 1
            and one.name == other.name)


def running_together(charge: Charge, values: Any) -> list[Any]:
    """``together``'s node instances (or links), each beside another of the list that
    can run at the same time as it: not two ROS 1 instances of one name (a launch file's
    one mistake, said by LAUNCH_NODE_DUPLICATE or duplicate-node-names, is not also
    each topic and service of that node said again)."""
    if not isinstance(values, list):
        raise QueryTypeError("running_together() takes a list of node instances or links")
    return [one for one in values if any(
        other is not one and not _one_ros1_name(one, other)
        and not never_together(charge, one, other) for other in values)]


def all_apart(charge: Charge, values: Any) -> list[Any]:
    """The node instances (or links) of a list when no two of them have the same
    conditions, so that each may exist without the others (an ``undecided_by`` list);
    none when two of them exist together whenever either does."""
    if not isinstance(values, list):
        raise QueryTypeError("all_apart() takes a list of node instances or links")
    distinct = list({id(value): value for value in values}.values())
    for index, first in enumerate(distinct):
        for second in distinct[index + 1:]:
            if not apart(charge, first, second):
                return []
    return distinct


def _existing(value: Any) -> list[Any]:
    items = value if isinstance(value, list | tuple) else [value]
    for item in items:
        if not isinstance(item, NodeInstance | Link | Parameter):
            raise QueryTypeError("undecided() takes node instances, links or parameters "
                                 "(or lists of them)")
    return list(items)


def _same_condition(item: Any, condition: Condition) -> tuple[Any, ...]:
    """What makes two conditions one: a launch condition's text (it reads launch
    arguments, taken as one scope's, as ``same_conditions`` does, and a Python launch
    test's run of it); a source condition's
    place in the code and its node instance (the values it reads are that instance's)."""
    if condition.kind == "launch":
        return ("launch", condition.text.strip(), condition.statement, condition.runs)
    instance = item.node if isinstance(item, Link) else item
    return (condition.kind, id(instance), condition.text.strip(), condition.statement,
            condition.location)


def undecided(charge: Charge, values: Any, given: Any = ()) -> list[Any]:
    """The conditions not decided for the configuration under which the node instances,
    links or parameters ``values`` (one or a list) may not exist (``model.conditions.
    undecided``: what the graph could not decide, a ``try``, ``do`` or timer aside),
    each once;
    none that ``given`` (one or a list) has too, as those hold wherever it exists. A
    finding that rests on ``values`` existing is undecided when this is not empty (an
    ``undecided_by`` list); one that rests on their absence, when it is not empty for
    each of them."""
    known = {_same_condition(item, c) for item in _existing(given)
             for c in item.conditions if c.text.strip() != UNKNOWN_MARK}
    found: dict[tuple[Any, ...], Condition] = {}
    for item in _existing(values):
        conditions = undecided_of(tuple(item.conditions))
        charge(1 + len(conditions))
        for c in conditions:
            key = _same_condition(item, c)
            if key not in known:
                found.setdefault((c.kind, c.text.strip(), c.statement, c.location), c)
    return list(found.values())


def one_process(charge: Charge, first: Any, second: Any = None) -> str:
    """For node instances of one name (two, or a list) of which one launched process
    runs several (the launch name renames every node of it), a clause that says so and
    names the nodes its code makes; else nothing."""
    values = [first, second] if second is not None else first
    if not isinstance(values, list) or not all(
            isinstance(value, NodeInstance) for value in values):
        raise QueryTypeError("one_process() takes two node instances or a list of them")
    charge(1 + len(values))
    # the instances of one launch action, each made by the code under its own name; one
    # without a code name is the node whose code name is the launch name (doosan's
    # dsr_control_node2 beside the stop_subscriber_node its code makes too)
    processes: dict[Any, list[str]] = {}
    renamed: set[Any] = set()
    for value in values:
        own = value.code_name if value.code_name is not None else (
            value.name.rsplit("/", 1)[-1])
        if value.code_name is not None:
            renamed.add(value.location)
        names = processes.setdefault(value.location, [])
        if own not in names:
            names.append(own)
    clauses = [" and ".join(names) for where, names in processes.items()
               if len(names) > 1 and where in renamed]
    if not clauses:
        return ""
    return ("; one process: the launch file's name renames every node its code makes, "
            + "; ".join(clauses))


def more_unknown_names(charge: Charge, links: Any) -> str:
    """For the links one call of one node instance makes whose names hold ``?`` (a
    parameter client's services, the parameters a wrapper reads under a prefix not known),
    reported once: a clause naming the others than the first, at most a few; else
    nothing."""
    if not isinstance(links, list) or not all(isinstance(link, Link) for link in links):
        raise QueryTypeError("more_unknown_names() takes a list of links")
    charge(1 + min(len(links), _MORE_SHOWN))
    others = links[1:]
    if not others:
        return ""
    shown = ", ".join(f"{link.kind} {link.rosname.given}" for link in others[:_MORE_SHOWN])
    rest = len(others) - _MORE_SHOWN
    return (f"; the same call makes {len(others)} more such name"
            f"{'s' if len(others) > 1 else ''}: {shown}"
            + (f" and {rest} more" if rest > 0 else ""))


_MORE_SHOWN = 4
FUNCTIONS["more_unknown_names"] = Function("more_unknown_names", more_unknown_names,
                                           charged=True)


# two node instances of one name: a duplicate only when both can start
FUNCTIONS["one_process"] = Function("one_process", one_process, 1, 2, charged=True)
FUNCTIONS["never_together"] = Function("never_together", never_together, 2, 2, charged=True)
FUNCTIONS["apart"] = Function("apart", apart, 2, 2, charged=True)
FUNCTIONS["together"] = Function("together", together, charged=True)
FUNCTIONS["running_together"] = Function("running_together", running_together,
                                        charged=True)
FUNCTIONS["all_apart"] = Function("all_apart", all_apart, charged=True)
FUNCTIONS["undecided"] = Function("undecided", undecided, 1, 2, charged=True)


def installed_with(charge: Charge, package: Any, packages: Any, test: Any = False
                   ) -> list[str]:
    """The names of the packages a binary install of ``package`` brings: its run
    dependencies (exec_depend, depend, run_depend; test_depend too when ``test``), and
    theirs where they are among ``packages`` (``manifest.installed_with``)."""
    if not isinstance(package, Package):
        raise QueryTypeError("installed_with() takes a package first")
    known = [p for p in _items(packages) if isinstance(p, Package)]
    charge(1 + len(known) + sum(len(p.dependencies) for p in known))
    return sorted(manifest.installed_with(package, known, bool(test)))


FUNCTIONS["installed_with"] = Function("installed_with", installed_with, 2, 3, charged=True)
