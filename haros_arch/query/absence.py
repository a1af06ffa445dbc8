"""Query functions for checks that claim something is absent, and that must stay fast.

``unknown_users(config, resource)``: the node instances of partial or unknown interface,
or with a name not known statically, that could use the resource through a call the
model does not show (and, for a parameter nothing sets, launch parameters with ``?``
that may be it). A check that says
"nobody publishes this" or "nobody reads this" is a fact only when this list is empty.

``similar_to(word, items)``: the items (resources, links or strings) whose own name is the
word or within edit distance 2 of it, through an index built once per list, not by
comparing every pair.
"""

from __future__ import annotations

import re
from collections import OrderedDict
from collections.abc import Callable
from functools import lru_cache
from typing import Any, TypeVar
from weakref import WeakKeyDictionary

from ..model.launch_tree import LaunchItem
from ..model.rosname import pattern_for
from ..model.runtime import Configuration, Link, NodeInstance, Parameter, Resource
from ..model.values import UNKNOWN_MARK
from .errors import QueryTypeError

Charge = Callable[[int], None]


class Known:
    """What ``unknown_users`` needs of a configuration, built once per configuration."""

    def __init__(self, config: Configuration) -> None:
        self.size = (len(config.nodes), len(config.links))
        self.by_name: dict[str, NodeInstance] = {}
        for node in config.nodes:
            self.by_name.setdefault(node.name, node)
        self.incomplete = config.incomplete_nodes
        # ROS 1 controllers whose manager is not seen (``NodeInstance.host_unseen``), by
        # name: a node launched under the same name (squirrel_robotino's door_controller
        # .py beside the door_controller of Gazebo's manager) does not make the
        # parameters under it that node's alone
        self.host_unseen: set[str] = {node.name for node in config.nodes
                                      if node.host_unseen}
        # includes the launch stage could not read (a file not known statically, a
        # package not found: tiago's ``$(find cartesian_impedance)/launch/...``): what
        # they start or set is not seen, so they may be the missing side of anything
        self.unread: list[LaunchItem] = [
            item for tree in config.launch_tree for item in tree.walk()
            if item.kind == "include" and not item.skipped]
        # a configuration that starts no node (a ROS 1 launch file that only sets
        # parameters, run beside the one that starts their nodes: m-explore's
        # ``experiments/3-robots.ttt.launch``): what reads its parameters is elsewhere
        # (a <test> that roslaunch leaves out is a node its file starts, under rostest)
        self.elsewhere: list[LaunchItem] = [] if config.nodes else [
            tree for tree in config.launch_tree if tree.kind == "file"
            and not any(item.kind == "node" for item in tree.walk())]
        # ROS 1 dynamic_reconfigure servers: each reads and sets every field of its .cfg
        # under the namespace of the handle it is given (``N/set_parameters``,
        # ``N/parameter_updates``), names we do not read. Namespace -> serving nodes;
        # a namespace with "?" as the pattern of the parameter names under it. A server
        # whose reads the extraction made from its .cfg (``extract.cpp.reconfigure``: at
        # the server's own place in the code) is read as they say for the parameters
        # right under its namespace (``reconfigured_read``); deeper ones stay undecided
        # by it only while its node's interface is not wholly known, as the code that
        # reads them may be out of sight (the generated server reads and sets its
        # config's fields under its handle's namespace, never a name below: move_base's
        # server on ``~`` reads none of its costmaps' parameters, costmap_2d's library
        # does, which a complete model of move_base shows)
        self.reconfigured: dict[str, list[NodeInstance]] = {}
        self.reconfigured_read: dict[str, list[NodeInstance]] = {}
        self.reconfigured_unresolved: list[tuple[re.Pattern[str], NodeInstance]] = []
        explicit = {(id(link.node), link.location) for link in config.links
                    if link.kind == "read" and link.location.file is not None}
        for link in config.links:
            namespace = _reconfigure_namespace(link)
            if namespace is None:
                continue
            if UNKNOWN_MARK in namespace:
                self.reconfigured_unresolved.append(
                    (re.compile(pattern_for(namespace + "/" + UNKNOWN_MARK)), link.node))
            elif (id(link.node), link.location) in explicit:
                self.reconfigured_read.setdefault(namespace, []).append(link.node)
            else:
                self.reconfigured.setdefault(namespace, []).append(link.node)
        # resource -> nodes that use a name with "?" that may stand for it, each with
        # the kind of its link
        self.guessed: dict[int, list[tuple[NodeInstance, str]]] = {}
        # parameter -> parameters with "?" that the launch sets and that may be it (a
        # parameter file not read, an entry not known statically: ``/ns/node/?``)
        self.launch_guessed: dict[int, list[Parameter]] = {}
        for collection in (config.topics, config.services, config.actions,
                           config.parameters):
            for unresolved in collection:
                if not unresolved.is_unresolved:
                    continue
                users = list(dict.fromkeys((link.node, link.kind)
                                           for link in unresolved.links))
                launched = unresolved if isinstance(unresolved, Parameter) and (
                    unresolved.set_by_launch) else None
                for candidate in unresolved.candidates:
                    self.guessed.setdefault(id(candidate), []).extend(users)
                    if launched is not None:
                        self.launch_guessed.setdefault(id(candidate), []).append(launched)


def _reconfigure_namespace(link: Link) -> str | None:
    """The namespace of the dynamic_reconfigure server a link is part of (its
    ``parameter_updates`` publisher or ``set_parameters`` server), or None."""
    namespace, _, own = link.rosname.full.rpartition("/")
    if link.kind == "publish" and own == "parameter_updates":
        return namespace
    if (link.kind == "server" and own == "set_parameters"
            and link.type == "dynamic_reconfigure/Reconfigure"):
        return namespace
    return None


def reconfiguring(config: Configuration, parameter: Parameter,
                  known: Known | None = None) -> list[NodeInstance]:
    """The nodes whose dynamic_reconfigure server may read and set the parameter: those
    serving on a namespace its name is under (not those right above it whose reads of
    their .cfg's parameters are known: they read it or not as their links say).
    ``known``: ``Known(config)`` made by the caller, not the cached one (the graph
    stage, before the queries' candidates are found)."""
    known = known or _known(config)
    found: list[NodeInstance] = []
    name = parameter.name
    deeper = False  # the namespace is the parameter's own (its reads decide) or above it
    while "/" in name.rstrip("/"):
        name = name.rstrip("/").rsplit("/", 1)[0]
        found.extend(known.reconfigured.get(name, ()))
        if deeper:  # a server's own reads stop at its namespace: deeper, the node's
            # other code reads, which only an interface not wholly known may hide
            found.extend(node for node in known.reconfigured_read.get(name, ())
                         if not node.is_complete)
        deeper = True
    found.extend(node for pattern, node in known.reconfigured_unresolved
                 if pattern.match(parameter.name))
    return found


_KNOWN: WeakKeyDictionary[Configuration, Known] = WeakKeyDictionary()


def unread_launch(config: Configuration) -> list[LaunchItem]:
    """The includes and launch actions the launch stage could not read: what they start
    or set is not seen (``Known.unread``)."""
    return list(_known(config).unread)


def _known(config: Configuration) -> Known:
    return _per_configuration(_KNOWN, config, (len(config.nodes), len(config.links)), Known)


Built = TypeVar("Built", "Known", "_Settings", "_Dropped", "_Names")


def _per_configuration(cache: WeakKeyDictionary[Configuration, Built], config: Configuration,
                       size: tuple[int, int], build: Callable[[Configuration], Built]
                       ) -> Built:
    """What ``build`` makes of a configuration, made again when its ``size`` changed
    (a configuration a hint or a query grew)."""
    found = cache.get(config)
    if found is None or found.size != size:
        found = cache[config] = build(config)
    return found


def owner_of(config: Configuration, parameter: Parameter,
             known: Known | None = None) -> NodeInstance | None:
    """The node instance a parameter is private to (``/ns/node/param`` of ``/ns/node``;
    a ROS 2 parameter always belongs to its node), or None for a shared one. A ROS 2
    parameter whose own name begins with a slash (launch_ros hands ``{"/frame_id": ...}``
    to the node as written) is ``/ns/node//frame_id``: still ``/ns/node``'s."""
    by_name = (known or _known(config)).by_name
    name = parameter.name
    while "/" in name.rstrip("/"):
        name = name.rstrip("/").rsplit("/", 1)[0]
        found = by_name.get(name.rstrip("/") or name)
        if found is not None:
            return found
    return None


def same_setting(charge: Charge, config: Any, parameter: Any) -> list[Parameter]:
    """The parameters that the launch setting which set ``parameter`` gave the nodes
    it is for, in the configuration's order (``parameter`` among them), when it is a
    setting for several nodes (``Parameter.setting``: a ``SetParameter`` for every
    node of its scope, the ``/**`` entries of a parameter file given to several
    nodes); ``[parameter]`` for one set for its node alone. Each node there gets the
    value and takes it only if it declares the parameter, so such a setting is
    unread only when none of them reads it."""
    if not isinstance(config, Configuration) or not isinstance(parameter, Parameter):
        raise QueryTypeError("same_setting() takes a configuration and a parameter")
    charge(1)
    if parameter.setting is None:
        return [parameter]
    settings = _settings(config)
    key = settings.key.get(id(parameter))
    found = settings.groups.get(key, [parameter]) if key is not None else [parameter]
    charge(len(found) // 64)
    return list(found)


def same_setting_elsewhere(charge: Charge, configs: Any, config: Any, parameter: Any
                           ) -> list[Parameter]:
    """The parameters that the same launch setting for several nodes (``same_setting``:
    the ``/**`` entries of one parameter file, a ROS 1 file loaded into several nodes)
    gives, under the same name within each node, in the other configurations of
    ``configs``; none for a parameter set for its node alone. A robot-wide file handed to
    the nodes of several launch files (vortex-asv's freya.yaml: five of them, each node
    declaring its own few keys of it) is read where any of them reads a key."""
    if not isinstance(config, Configuration) or not isinstance(parameter, Parameter) or (
            not isinstance(configs, list)):
        raise QueryTypeError("same_setting_elsewhere() takes the configurations, a "
                             "configuration and a parameter")
    charge(1)
    if parameter.setting is None:
        return []
    key = _settings(config).key.get(id(parameter))
    if key is None:
        return []
    found: list[Parameter] = []
    for other in configs:
        if other is config or not isinstance(other, Configuration):
            continue
        charge(1)
        found.extend(_settings(other).groups.get(key, ()))
    return found


class _Settings:
    """The parameters of each launch setting for several nodes: by the setting and
    the parameter's name within its node."""

    def __init__(self, config: Configuration) -> None:
        self.size = (len(config.nodes), len(config.parameters))
        self.key: dict[int, tuple[Any, ...]] = {}
        self.groups: dict[tuple[Any, ...], list[Parameter]] = {}
        for parameter in config.parameters:
            if parameter.setting is None:
                continue
            owner = owner_of(config, parameter)
            own = parameter.name[len(owner.name.rstrip("/")) + 1:] if owner is not None \
                else parameter.rosname.own
            key = (parameter.setting, own)
            self.key[id(parameter)] = key
            self.groups.setdefault(key, []).append(parameter)
        for group in self.groups.values():  # a node named with "?" last: never reported
            group.sort(key=lambda p: p.is_unresolved)


_SETTINGS: WeakKeyDictionary[Configuration, _Settings] = WeakKeyDictionary()


def _settings(config: Configuration) -> _Settings:
    return _per_configuration(_SETTINGS, config, (len(config.nodes), len(config.parameters)),
                              _Settings)


def unknown_users(charge: Charge, config: Any, resource: Any, side: Any = None
                  ) -> list[NodeInstance | Parameter | LaunchItem]:
    """``_unknown_users`` of a resource or link, or of each of a list of them (what
    could use any of them unseen). ``side``, for parameters: ``'readers'`` when the
    missing side is a reader (a node that only writes a name with ``?`` reads nothing:
    duckietown's DTROS writes ``<node>/?``); None: either, as for a missing setter (a
    read with ``?`` may stand for a declaration, which sets)."""
    if side not in (None, "readers"):
        raise QueryTypeError("unknown_users()'s third argument can only be 'readers'")
    if isinstance(resource, list):
        found: list[NodeInstance | Parameter | LaunchItem] = []
        for each in resource:
            found.extend(_unknown_users(charge, config, each, side))
        return _unique(found)
    return _unknown_users(charge, config, resource, side)


def _unknown_users(charge: Charge, config: Any, resource: Any, side: str | None = None
                   ) -> list[NodeInstance | Parameter | LaunchItem]:
    """The node instances that could use ``resource`` through a call the model does not
    show: those of partial or unknown interface, and those that use a name with ``?``
    that may stand for it (a ``getParam(name_read_at_run_time)``). For a parameter
    that nothing is seen to set, also the parameters with ``?`` that the launch sets
    and that may be it (``/ns/node/?`` of a parameter file not read): the launch may
    set it unseen. And the includes the launch stage could not read, which may start
    or set anything (for a parameter private to a node of known interface, only when
    nothing is seen to set it). A parameter under a ROS 1 controller whose manager
    is not seen (``NodeInstance.host_unseen``) may also be used by the nodes of partial
    or unknown interface and the includes not read: one of them may be (or start) the
    process it runs in.

    A node of partial or unknown interface could publish, subscribe, serve or call any
    topic, service or action name, and read or set any shared parameter; a private
    parameter (ROS 1 ``/node/param``, every ROS 2 parameter) only its own node. A
    parameter under the namespace of a dynamic_reconfigure server (the fields
    of its .cfg: the node's own ``~``, a planner's ``~DWAPlannerROS``, a controller's
    handle on its host) also the node running that server, which reads and sets it
    unseen."""
    # for a link, a name with "?" can be the missing side only from the other side: a
    # node that subscribes ``?`` publishes nothing (VINS-Mono's feature_tracker
    # subscribes a name read from a file: it may be any image topic's subscriber, never
    # the publisher of one)
    sides = _OTHER_SIDE.get(resource.kind) if isinstance(resource, Link) else None
    if side == "readers":
        sides = ("read",)
    if isinstance(resource, Link):
        resource = resource.resource
    if not isinstance(config, Configuration) or not isinstance(resource, Resource):
        raise QueryTypeError("unknown_users() takes a configuration and a topic, service, "
                             "action, parameter or link")
    known = _known(config)
    charge(1)
    found: list[NodeInstance | Parameter | LaunchItem] = list(known.incomplete)
    found.extend(known.unread)
    if isinstance(resource, Parameter):
        found.extend(known.elsewhere)
        owner = owner_of(config, resource)
        if owner is not None:
            found = [] if owner.is_complete else [owner]
            if owner.name in known.host_unseen:  # a ROS 1 controller whose manager is not seen: a
                # node of partial or unknown interface may be its process (Gazebo with a
                # control plugin not known), or an include not read start it, whose
                # code may use its parameters
                found.extend(node for node in known.incomplete if not node.host_unseen)
                found.extend(known.unread)
            if not resource.is_set:  # an include not read may set it
                found.extend(known.unread if owner.ros_version == 1 else [
                    item for item in known.unread if _sets_later(item, owner)])
        charge(len(known.reconfigured_unresolved) // 64)
        found.extend(reconfiguring(config, resource))
        if not resource.is_set:
            found.extend(known.launch_guessed.get(id(resource), ()))
    found.extend(node for node, kind in known.guessed.get(id(resource), ())
                 if sides is None or kind in sides)
    charge(len(found) // 64)
    return _unique(found)


# the link kinds that are the other side of a topic, service or action link (a
# parameter's readers and writers are left whole: a read may stand for a declaration)
_OTHER_SIDE: dict[str, tuple[str, ...]] = {
    "publish": ("subscribe",), "subscribe": ("publish",), "server": ("client",),
    "client": ("server",), "action-server": ("action-client",),
    "action-client": ("action-server",),
}


def meeting(charge: Charge, config: Any, link: Any) -> list[Link]:
    """The links on the other side of ``link`` (a subscriber's publishers, a client's
    servers, an action client's servers): those of its resource; for a name with ``?``,
    those of every resource of its kind whose name it could be (``RosName.pattern``),
    and of every other name with ``?`` that could be the same name (``may_meet``). A
    check that says a name with ``?`` has no other side rests on this list being empty:
    whatever the unknown part is, nothing in the configuration is on the other side."""
    if not isinstance(config, Configuration) or not isinstance(link, Link):
        raise QueryTypeError("meeting() takes a configuration and a link")
    sides = _OTHER_SIDE.get(link.kind, ())
    charge(1)
    if not link.rosname.is_unresolved:
        return [each for each in link.resource.links if each.kind in sides]
    names = _names(config)
    pattern = re.compile(link.rosname.pattern)
    known, unresolved = names.of.get(type(link.resource), ([], []))
    charge(1 + (len(known) + len(unresolved)) // 64)
    found = [resource for resource in known if pattern.match(resource.name)]
    found.extend(resource for resource in unresolved
                 if resource is link.resource or may_meet(resource.name, link.rosname.full))
    return [each for resource in found for each in resource.links if each.kind in sides]


class _Names:
    """The resources of a configuration by kind: those of known names and those with ``?``."""

    def __init__(self, config: Configuration) -> None:
        self.size = (len(config.nodes), len(config.links))
        self.of: dict[type, tuple[list[Resource], list[Resource]]] = {}
        for collection in (config.topics, config.services, config.actions):
            for resource in collection:
                known, unresolved = self.of.setdefault(type(resource), ([], []))
                (unresolved if resource.is_unresolved else known).append(resource)


_NAMES: WeakKeyDictionary[Configuration, _Names] = WeakKeyDictionary()


def _names(config: Configuration) -> _Names:
    return _per_configuration(_NAMES, config, (len(config.nodes), len(config.links)), _Names)


@lru_cache(maxsize=65536)
def may_meet(first: str, second: str) -> bool:
    """Whether two names with ``?`` parts could be one name: some text fits both when
    each ``?`` stands for any text (a little more than ``pattern_for`` allows, which
    errs towards a meeting). The known text before the first ``?`` of each, and after
    the last, must agree first: most pairs part there, before any search."""
    head_one, head_other = _head(first), _head(second)
    if not (head_one.startswith(head_other) or head_other.startswith(head_one)):
        return False
    tail_one, tail_other = _tail_text(first), _tail_text(second)
    if not (tail_one.endswith(tail_other) or tail_other.endswith(tail_one)):
        return False
    one = _glob(first)
    other = _glob(second)
    seen: set[tuple[int, int]] = set()
    todo = [(0, 0)]
    while todo:
        at = todo.pop()
        if at in seen:
            continue
        seen.add(at)
        i, j = at
        if i == len(one) and j == len(other):
            return True
        if i < len(one) and one[i] is None:
            todo.append((i + 1, j))
            if j < len(other):
                todo.append((i, j + 1))
        elif j < len(other) and other[j] is None:
            todo.append((i, j + 1))
            if i < len(one):
                todo.append((i + 1, j))
        elif i < len(one) and j < len(other) and one[i] == other[j]:
            todo.append((i + 1, j + 1))
    return False


def _head(name: str) -> str:
    """The known text before a name's first ``?`` (without a slash the ``?`` may drop)."""
    head = name.split(UNKNOWN_MARK, 1)[0]
    return head[:-1] if UNKNOWN_MARK in name and head.endswith("/") else head


def _tail_text(name: str) -> str:
    """The known text after a name's last ``?`` (the whole name when it has none)."""
    return name.rsplit(UNKNOWN_MARK, 1)[-1] if UNKNOWN_MARK in name else name


def _glob(name: str) -> list[str | None]:
    """A name as its characters, each ``?`` (with the slash before it, as a segment
    that is all ``?`` may be no segment: ``pattern_for``) as None: any text."""
    out: list[str | None] = []
    for at, part in enumerate(name.split(UNKNOWN_MARK)):
        if at:
            if out and out[-1] == "/":
                out.pop()
            out.append(None)
        out.extend(part)
    return out


def _sets_later(include: LaunchItem, owner: NodeInstance) -> bool:
    """Whether a ROS 2 include not read may set a parameter of ``owner``: a ROS 2
    parameter belongs to its node, and a file it includes can set it only through a
    ``SetParameter`` that reaches the nodes launched after the include in the file that
    includes it (ROS 1's parameter server takes any name from any file). Nodes launched
    from files that file includes later are not followed."""
    where, at = include.location, owner.location
    return where.file is not None and where.file == at.file and where.line < at.line


def _unique(items: list[Any]) -> list[Any]:
    """Each item once, in order (a launch item, not hashable, by identity)."""
    seen: set[Any] = set()
    out: list[Any] = []
    for item in items:
        key = ("item", id(item)) if isinstance(item, LaunchItem) else item
        if key not in seen:
            seen.add(key)
            out.append(item)
    return out


MAX_DISTANCE = 2
_PARTS = MAX_DISTANCE + 1
_Index = tuple[dict[tuple[int, int, str], list[int]], list[str], list[frozenset[str]]]
_INDEXES: OrderedDict[int, tuple[Any, _Index]] = OrderedDict()
_KEEP_INDEXES = 16
# items' places by their names' spelling (``similar_to``), kept as the indexes are
_SPELLINGS: OrderedDict[int, tuple[Any, dict[str, list[int]], dict[str, list[int]]]] = (
    OrderedDict())


def _own(item: Any) -> str | None:
    if isinstance(item, str):
        return item
    if isinstance(item, Link | Resource):
        return item.rosname.own
    return None


def _bounds(length: int) -> list[int]:
    """Where a word of this length is cut into three parts."""
    return [length * k // _PARTS for k in range(_PARTS + 1)]


def _index(items: list[Any], charge: Charge) -> _Index:
    """(length, part number, part) -> places of the items whose own name has it; and
    each item's own name and the set of its characters.

    Two edits change at most two of a word's three parts, so a word within distance 2
    of another holds one of its parts unchanged, shifted by at most two characters (the
    pigeonhole filter of PassJoin): three entries per name, some 75 look-ups per probe.
    """
    cached = _INDEXES.get(id(items))
    if cached is not None and cached[0] is items:
        _INDEXES.move_to_end(id(items))
        return cached[1]
    index: dict[tuple[int, int, str], list[int]] = {}
    owns: list[str] = []
    for place, item in enumerate(items):
        own = _own(item)
        if own is None:
            raise QueryTypeError("similar_to() compares names: strings, resources or links")
        owns.append(own)
        cut = _bounds(len(own))
        for part in range(_PARTS):
            index.setdefault((len(own), part, own[cut[part]:cut[part + 1]]), []).append(place)
    charge(len(items))
    found = (index, owns, [frozenset(own) for own in owns])
    _INDEXES[id(items)] = (items, found)
    while len(_INDEXES) > _KEEP_INDEXES:
        _INDEXES.popitem(last=False)
    return found


def distance(word: str, other: str, pattern: dict[str, int] | None = None) -> int:
    """Levenshtein distance, bit-parallel (Myers 1999, as Hyyrö writes it): one pass
    over ``other`` with the columns of the table for ``word`` packed in an integer.
    ``pattern`` is ``word``'s bit masks per character (``masks(word)``), to reuse."""
    if not word:
        return len(other)
    pattern = masks(word) if pattern is None else pattern
    full = (1 << len(word)) - 1
    top = 1 << (len(word) - 1)
    plus, minus, score = full, 0, len(word)
    for char in other:
        equal = pattern.get(char, 0)
        vertical = equal | minus
        horizontal = (((equal & plus) + plus) ^ plus) | equal
        up = minus | ~(horizontal | plus)
        down = plus & horizontal
        if up & top:
            score += 1
        elif down & top:
            score -= 1
        up = (up << 1) | 1
        down <<= 1
        plus = (down | ~(vertical | up)) & full
        minus = up & vertical & full
    return score


def masks(word: str) -> dict[str, int]:
    found: dict[str, int] = {}
    for i, char in enumerate(word):
        found[char] = found.get(char, 0) | (1 << i)
    return found


def spelling(name: str) -> str:
    """A name as its words are, whatever their spelling: lower case, without ``_``,
    ``-`` and ``.`` (``configFilePath_``, ``config_file_path`` and ``config-file-path``
    alike; ROS 2's ``onnxruntime.use_cuda`` beside ``onnxruntime_use_cuda``)."""
    return name.lower().replace("_", "").replace("-", "").replace(".", "")


def _tail(item: Any) -> str | None:
    """A resource's or link's last two name segments as one word (``/yolox/onnxruntime/
    use_cuda``: ``onnxruntimeuse_cuda``), spelt as ``spelling`` does: a key nested in a
    namespace where the code reads one flat key of the same words; None for a plain
    name or one of one segment."""
    if not isinstance(item, Link | Resource):
        return None
    parts = [p for p in item.rosname.full.split("/") if p]
    return spelling("".join(parts[-2:])) if len(parts) >= 3 else None


def similar_to(charge: Charge, word: Any, items: Any) -> list[Any]:
    """The items whose own name equals ``word``'s or is within edit distance 2 of it, or
    is spelt with the same words another way (``spelling``: grid_map_pcl's launch file
    sets ``configFilePath_``, its node reads ``config_file_path``), or whose last two
    segments are one's own name spelt so (YOLOX-ROS' launch file sets
    ``onnxruntime/use_cuda``, its node declares ``onnxruntime_use_cuda``)."""
    tail = _tail(word)
    word = _own(word)
    if word is None or not isinstance(items, list):
        raise QueryTypeError("similar_to() takes a name (or a resource or link) and a list")
    index, owns, letters = _index(items, charge)
    spelt = _SPELLINGS.get(id(items))
    if spelt is None or spelt[0] is not items:
        by_spelling: dict[str, list[int]] = {}
        by_tail: dict[str, list[int]] = {}
        for place, own in enumerate(owns):
            by_spelling.setdefault(spelling(own), []).append(place)
            two = _tail(items[place])
            if two is not None:
                by_tail.setdefault(two, []).append(place)
        charge(len(owns))
        spelt = (items, by_spelling, by_tail)
        _SPELLINGS[id(items)] = spelt
        while len(_SPELLINGS) > _KEEP_INDEXES:
            _SPELLINGS.popitem(last=False)
    alike = set(spelt[1].get(spelling(word), ())) | set(spelt[2].get(spelling(word), ()))
    if tail is not None:
        alike.update(spelt[1].get(tail, ()))
    places: set[int] = set()
    for length in range(max(0, len(word) - MAX_DISTANCE), len(word) + MAX_DISTANCE + 1):
        cut = _bounds(length)
        for part in range(_PARTS):
            size = cut[part + 1] - cut[part]
            for shift in range(-MAX_DISTANCE, MAX_DISTANCE + 1):
                begin = cut[part] + shift
                if begin >= 0 and begin + size <= len(word):
                    places.update(index.get((length, part, word[begin:begin + size]), ()))
    charge(1 + len(places))
    pattern, mine = masks(word), frozenset(word)
    # an edit adds or takes away at most two letters of the set of letters used: a
    # cheap test before the distance
    # by full name: the same names in the same order in every configuration (one
    # finding for a parameter file several launch files load, not one per order)
    return sorted((items[place] for place in places | alike
                   if place in alike or (len(letters[place] ^ mine) <= 2 * MAX_DISTANCE
                                         and distance(word, owns[place], pattern)
                                         <= MAX_DISTANCE)), key=_full_name)


def _full_name(item: Any) -> str:
    return item if isinstance(item, str) else str(getattr(item, "name", ""))


# CONDITION_FALSE about a read (``diagnostics.CATALOGUE``'s template, filled)
_READ_DROPPED = re.compile(
    r"(?P<node>\S+): no read (?P<name>\S+) in this configuration: the code makes it under "
    r"(?P<condition>.*) \((?P<where>[^()]*)\), which does not hold here")
MAX_DROPPED_SAID = 2


class _Dropped:
    """The reads each configuration's code makes under a condition false there, by the
    parameter's full name: (node, condition, where)."""

    def __init__(self, config: Configuration) -> None:
        self.size = (len(config.diagnostics), 0)
        self.by_name: dict[str, list[tuple[str, str, str]]] = {}
        for found in config.diagnostics:
            if found.code != "CONDITION_FALSE":
                continue
            read = _READ_DROPPED.fullmatch(found.message)
            if read is not None:
                self.by_name.setdefault(read["name"], []).append(
                    (read["node"], read["condition"], read["where"]))


_DROPPED: WeakKeyDictionary[Configuration, _Dropped] = WeakKeyDictionary()


def reads_dropped(charge: Charge, config: Any, parameter: Any) -> str:
    """Why no node reads ``parameter`` though one's code names it: the reads of it that
    the configuration dropped, their condition false there (CONDITION_FALSE), as a
    clause (`` in this configuration: /n reads it only under if (x) (a.cpp:7), which
    does not hold here``); empty when there is none. A finding that says "no node reads
    it" sends the user to code that reads it, under a test the launch file decides."""
    if not isinstance(config, Configuration) or not isinstance(parameter, Parameter):
        raise QueryTypeError("reads_dropped() takes a configuration and a parameter")
    charge(1)
    index = _per_configuration(_DROPPED, config, (len(config.diagnostics), 0), _Dropped)
    found = index.by_name.get(parameter.name, [])
    if not found:
        return ""
    said = [f"{node} reads it only under {condition} ({where})"
            for node, condition, where in found[:MAX_DROPPED_SAID]]
    more = f" and {len(found) - MAX_DROPPED_SAID} more" if len(found) > MAX_DROPPED_SAID \
        else ""
    verb = "does" if len(found) == 1 else "do"
    return f" in this configuration: {', '.join(said)}{more}, which {verb} not hold here"
