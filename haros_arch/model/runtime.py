"""The runtime side of the model: a configuration's Computation Graph.

Node instances, topics, services, actions and parameters are linked by ``Link`` values.
A configuration owns the list of links; the ``links`` lists on node instances and
resources are indexes filled when the graph is built, and every other view (who
publishes, is the topic disconnected, ...) is computed from them.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, ClassVar

from .conditions import Condition, undecided
from .diagnostic import Diagnostic
from .launch_tree import IncludeArg, LaunchItem, PackageUse, include_args
from .location import NOWHERE, Location
from .robot import RobotDescription
from .rosname import RosName, namespace_of, pattern_for, resolve, resolve_remaps
from .source import KNOWN_COMPLETENESS, Node, PrimitiveCall
from .values import UNKNOWN_MARK

INDEX: dict[str, Any] = {"json": False}
REF: dict[str, Any] = {"ref": True}
LAUNCH_WRITER = "<launch>"
# the suffix of an entity's id that tells apart entities of one name (the graph numbers
# them in the order it meets them): "node:/requester#2", "topic:/?#2"
REPEAT = re.compile(r"#\d+$")


def _names(links: list[Link]) -> list[str]:
    return sorted({link.node.name for link in links})


@dataclass(eq=False)
class NodeInstance:
    """A node started by a configuration: its ROS name and what it runs."""

    name: str
    node: Node | None = field(default=None, metadata=REF)
    id: str = ""  # unique in its configuration: "node:/talker" (set by graph.build)
    namespace: str = "/"
    remaps: list[tuple[str, str]] = field(default_factory=list)
    args: str = ""
    conditions: tuple[Condition, ...] = ()
    location: Location = NOWHERE
    origin: str = "launch"  # "launch", "hint" (a project-file hint), "plugin" (a host made it)
    ros_version: int = 1  # 2: ROS 2 naming (node-scoped parameters)
    # a roslaunch <test>: only rostest starts it (kept in rostest configurations only)
    test: bool = field(default=False, metadata={"optional": True})
    # the remaps' sources (resolved in this instance's namespace) that changed a name
    # its links were made with: what ROS would remap (``graph.build`` records them)
    remaps_applied: list[str] = field(default_factory=list, metadata={"optional": True})
    # ROS 2: the name its code gives this node when the launch name renames it, as it
    # renames every node of a process that runs several (ublox_gps_node's own node and
    # its raw_data_pa, both /sensing/gnss/ublox under name="ublox")
    code_name: str | None = field(default=None, metadata={"optional": True})
    # a host row loaded its plugins (``plugins.attach``): what its code loads by name is
    # in its links or in the instances it made, and a plugin not found made it partial
    hosted: bool = field(default=False, metadata={"optional": True})
    # a plugin node its host loads because it loads every class it finds (mavros' plugins:
    # ``hosts.Slot`` EXPORTED), of an installed package's model: what it subscribes is
    # input the host offers, which a configuration need not feed
    offered: bool = field(default=False, metadata={"optional": True})
    # ROS 1: a controller loaded by a manager no instance of the configuration is
    # (``plugins.attach.ros1_controllers``): it stands for its part of a process not
    # seen (Gazebo with a control plugin not known, a hardware node), whose other code
    # may read and set the parameters under its name (cob's hwi_switch_gazebo_ros_control
    # reads each controller's ``required_drive_mode``)
    host_unseen: bool = field(default=False, metadata={"optional": True})
    # ROS 1: where each remap of ``remaps`` is written (its ``<remap>`` element), by its
    # text ``from:=to``: one element a group gives nodes of several namespaces is one
    # remap (``remaps_of``)
    remap_places: dict[str, Location] = field(default_factory=dict,
                                              metadata={"optional": True})
    links: list[Link] = field(default_factory=list, metadata=INDEX)
    # a host's plugin objects by where its code keeps them (``hosts.Slot.kept``: the
    # container's function, the name's method): whether every plugin of that slot is
    # known, and the name each is given with the conditions that chose it and its
    # class's chain of bases (plain names, most derived first; None: not known)
    # (``plugins.attach``; ``graph.build.element_calls`` names a call per plugin)
    kept: dict[tuple[str, str], tuple[bool, list[tuple[
        str, tuple[Condition, ...], tuple[str, ...] | None]]]] = field(
        default_factory=dict, metadata=INDEX)

    JSON_VIEWS: ClassVar[dict[str, Callable[[Any], Any]]] = {
        "completeness": lambda n: n.completeness,
        "remapped": lambda n: n.remapped,
    }
    JSON_OPTIONAL_VIEWS: ClassVar[tuple[str, ...]] = ("remapped",)  # left out when empty

    @property
    def completeness(self) -> str:
        """How much of this instance's interface is known: its node's completeness, or
        "unknown" when no node model is known for what it runs."""
        return "unknown" if self.node is None else self.node.completeness

    @property
    def completeness_reasons(self) -> list[str]:
        if self.node is None:
            return ["no source and no interface model for what it runs"]
        return list(self.node.completeness_reasons)

    @property
    def is_complete(self) -> bool:
        """Every link of this instance is known (complete source or interface model)."""
        return self.completeness in KNOWN_COMPLETENESS

    @property
    def rosname(self) -> RosName:
        return RosName(self.name, self.name, namespace_of(self.name))

    def remap_rules(self) -> dict[str, str]:
        """Its remaps resolved, ``{from: to}`` (full names), one rule per source: the
        one its ROS version applies (``resolve_remaps``)."""
        return resolve_remaps(self.remaps, self.namespace, self.name,
                              first_wins=self.ros_version == 2)

    @property
    def remapped(self) -> list[list[str]]:
        """``[name in code, name it resolves to, name a remap made of it]`` for each name
        of this instance's links that one of its remaps changed (once per name)."""
        rules = self.remap_rules()
        out: dict[tuple[str, str], list[str]] = {}
        for link in self.links:
            given, full = link.rosname.given, link.rosname.full
            if UNKNOWN_MARK in given or (given, full) in out:
                continue
            before = resolve(given, self.namespace, self.name)
            if before != full and rules.get(before) == full:
                out[(given, full)] = [given, before, full]
        return list(out.values())

    def _of(self, kind: str) -> list[Link]:
        return [link for link in self.links if link.kind == kind]

    @property
    def publishers(self) -> list[Link]:
        return self._of("publish")

    @property
    def subscribers(self) -> list[Link]:
        return self._of("subscribe")

    @property
    def servers(self) -> list[Link]:
        return self._of("server")

    @property
    def clients(self) -> list[Link]:
        return self._of("client")

    @property
    def action_servers(self) -> list[Link]:
        return self._of("action-server")

    @property
    def action_clients(self) -> list[Link]:
        return self._of("action-client")

    @property
    def reads(self) -> list[Link]:
        return self._of("read")

    @property
    def writes(self) -> list[Link]:
        return self._of("write")

    def __repr__(self) -> str:
        return f"NodeInstance({self.name})"


@dataclass(eq=False)
class Resource:
    """What links point at: a topic, service, action or parameter."""

    name: str
    id: str = ""  # unique in its configuration: "topic:/chatter", "topic:/?#2"
    links: list[Link] = field(default_factory=list, metadata=INDEX)
    # for a name with "?": known resources of the same kind it may stand for, best first
    candidates: list[Resource] = field(default_factory=list, metadata=INDEX)

    @property
    def rosname(self) -> RosName:
        return RosName(self.name, self.name, namespace_of(self.name))

    @property
    def is_unresolved(self) -> bool:
        return UNKNOWN_MARK in self.name

    @property
    def types(self) -> list[str]:
        return sorted({link.type for link in self.links if link.type})

    @property
    def conditions(self) -> tuple[Condition, ...]:
        """Conditions common to every link: the resource exists only under them."""
        if not self.links:
            return ()
        common = list(self.links[0].conditions)
        for link in self.links[1:]:
            common = [c for c in common if c in link.conditions]
        return tuple(common)

    def _of(self, kind: str) -> list[Link]:
        return [link for link in self.links if link.kind == kind]

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.name})"


@dataclass(eq=False, repr=False)
class Topic(Resource):
    JSON_VIEWS: ClassVar[dict[str, Callable[[Any], Any]]] = {
        "types": lambda t: t.types,
        "publishers": lambda t: _names(t.publishers),
        "subscribers": lambda t: _names(t.subscribers),
        "conditions": lambda t: t.conditions,
        "candidates": lambda t: [c.id for c in t.candidates],
    }

    @property
    def publishers(self) -> list[Link]:
        return self._of("publish")

    @property
    def subscribers(self) -> list[Link]:
        return self._of("subscribe")

    @property
    def is_disconnected(self) -> bool:
        return not (self.publishers and self.subscribers)


@dataclass(eq=False, repr=False)
class Service(Resource):
    JSON_VIEWS: ClassVar[dict[str, Callable[[Any], Any]]] = {
        "types": lambda s: s.types,
        "servers": lambda s: _names(s.servers),
        "clients": lambda s: _names(s.clients),
        "conditions": lambda s: s.conditions,
        "candidates": lambda s: [c.id for c in s.candidates],
    }

    @property
    def servers(self) -> list[Link]:
        return self._of("server")

    @property
    def clients(self) -> list[Link]:
        return self._of("client")

    @property
    def is_disconnected(self) -> bool:
        return not (self.servers and self.clients)


@dataclass(eq=False, repr=False)
class Action(Resource):
    JSON_VIEWS: ClassVar[dict[str, Callable[[Any], Any]]] = {
        "types": lambda a: a.types,
        "servers": lambda a: _names(a.servers),
        "clients": lambda a: _names(a.clients),
        "conditions": lambda a: a.conditions,
        "candidates": lambda a: [c.id for c in a.candidates],
    }

    @property
    def servers(self) -> list[Link]:
        return self._of("action-server")

    @property
    def clients(self) -> list[Link]:
        return self._of("action-client")

    @property
    def is_disconnected(self) -> bool:
        return not (self.servers and self.clients)


@dataclass(eq=False, repr=False)
class Parameter(Resource):
    """A parameter; ``set_by_launch`` when a launch file gives it a value."""

    value: Any = None
    launch_type: str | None = field(default=None, metadata=INDEX)
    set_by_launch: bool = field(default=False, metadata=INDEX)
    launch_location: Location = field(default=NOWHERE, metadata=INDEX)
    launch_conditions: tuple[Condition, ...] = field(default=(), metadata=INDEX)
    # set under a namespace that a node reads whole (``get_param("gains")``)
    read_as_part_of: Parameter | None = field(default=None, metadata=INDEX)
    # given to a ``<test>`` that this (roslaunch) configuration leaves out: its name
    for_test: str | None = field(default=None, metadata=INDEX)
    # the launch setting for several nodes that set it, not one for its node alone
    # (``launch.model.ParamDecl.setting``: a ``SetParameter``'s place, a parameter file
    # whose ``/**`` entries each node it is given to gets, a ROS 1 parameter file loaded
    # into several nodes); the same setting's parameters on the other nodes:
    # ``query.absence.same_setting``
    setting: str | None = field(default=None, metadata={"optional": True})

    JSON_VIEWS: ClassVar[dict[str, Callable[[Any], Any]]] = {
        "type": lambda p: p.type,
        "readers": lambda p: _names(p.readers),
        "writers": lambda p: p.writer_names,
        "conditions": lambda p: p.conditions,
        "location": lambda p: p.location,
        "candidates": lambda p: [c.id for c in p.candidates],
        "read_as_part_of": lambda p: p.read_as_part_of.id if p.read_as_part_of else None,
    }

    @property
    def types(self) -> list[str]:
        found = {link.type for link in self.links if link.type}
        if self.launch_type:
            found.add(self.launch_type)
        return sorted(found)

    @property
    def type(self) -> str | None:
        """The launch file's type if it sets one, else the one type the code uses."""
        if self.launch_type:
            return self.launch_type
        types = self.types
        return types[0] if len(types) == 1 else None

    @property
    def location(self) -> Location:
        """Where the value is set by launch, else the first use in code."""
        if self.set_by_launch or not self.links:
            return self.launch_location
        return self.links[0].location

    @property
    def readers(self) -> list[Link]:
        return self._of("read")

    @property
    def is_read(self) -> bool:
        """Read by name, or as part of a namespace that a node reads whole."""
        return bool(self.readers) or self.read_as_part_of is not None

    @property
    def has_default(self) -> bool:
        """Every read of it gives a default in code, so an unset value is harmless."""
        return bool(self.readers) and all(
            link.call is not None and link.call.has_default for link in self.readers)

    @property
    def writers(self) -> list[Link]:
        return self._of("write")

    @property
    def setters(self) -> list[Link]:
        """Writes that give it a value (``writers`` without those that delete it)."""
        return [link for link in self.writers
                if not (isinstance(link, ParamWriteLink) and link.deletes)]

    @property
    def is_set(self) -> bool:
        """A launch file or a node gives it a value; deleting it does not."""
        return self.set_by_launch or bool(self.setters)

    @property
    def writer_names(self) -> list[str]:
        names = _names(self.writers)
        return [LAUNCH_WRITER, *names] if self.set_by_launch else names

    @property
    def conditions(self) -> tuple[Condition, ...]:
        """A launch-set parameter exists under the launch conditions (or when written)."""
        if self.set_by_launch:
            return self.launch_conditions if not self.setters else ()
        return super().conditions


@dataclass(eq=False)
class Link:
    """A node instance's use of a resource, from one primitive call."""

    KIND: ClassVar[str] = ""
    node: NodeInstance = field(metadata=INDEX)
    resource: Resource = field(metadata={"json": False})
    rosname: RosName = field(metadata={"json": False})
    type: str | None = None
    queue_size: int | None = None
    qos: dict[str, Any] | None = None
    latch: bool = False
    conditions: tuple[Condition, ...] = ()
    location: Location = NOWHERE
    origin: str = "source"  # "source", or "hint" when a project-file hint made it
    call: PrimitiveCall | None = field(default=None, metadata=INDEX)

    JSON_VIEWS: ClassVar[dict[str, Callable[[Any], Any]]] = {}
    JSON_HEAD: ClassVar[dict[str, Callable[[Any], Any]]] = {
        "kind": lambda link: link.kind,
        "node": lambda link: link.node.name,
        "node_id": lambda link: link.node.id,  # tells apart two instances of one name
        "name": lambda link: link.rosname.full,
        "given": lambda link: link.rosname.given,
        "resource": lambda link: link.resource.id,
    }

    @property
    def kind(self) -> str:
        return self.KIND

    @property
    def name(self) -> str:
        return self.rosname.full

    @property
    def undecided_conditions(self) -> tuple[Condition, ...]:
        """Its conditions under which it may not exist (``conditions.undecided``: not a
        ``try`` block, nor the first turn of a ``while`` over the node's running)."""
        return undecided(self.conditions)

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.node.name} -> {self.rosname.full})"


class _TopicLink(Link):
    @property
    def topic(self) -> Topic:
        return self.resource  # type: ignore[return-value]

    @property
    def topic_name(self) -> str:
        return self.rosname.full


class PublishLink(_TopicLink):
    KIND = "publish"


class SubscribeLink(_TopicLink):
    KIND = "subscribe"


class _ServiceLink(Link):
    @property
    def service(self) -> Service:
        return self.resource  # type: ignore[return-value]

    @property
    def service_name(self) -> str:
        return self.rosname.full


class ServiceProviderLink(_ServiceLink):
    KIND = "server"


class ServiceClientLink(_ServiceLink):
    KIND = "client"


class _ActionLink(Link):
    @property
    def action(self) -> Action:
        return self.resource  # type: ignore[return-value]

    @property
    def action_name(self) -> str:
        return self.rosname.full


class ActionServerLink(_ActionLink):
    KIND = "action-server"


class ActionClientLink(_ActionLink):
    KIND = "action-client"


class _ParamLink(Link):
    @property
    def parameter(self) -> Parameter:
        return self.resource  # type: ignore[return-value]

    @property
    def param_name(self) -> str:
        return self.rosname.full


class ParamReadLink(_ParamLink):
    KIND = "read"


class ParamWriteLink(_ParamLink):
    KIND = "write"

    # a write that deletes the parameter (rospy.delete_param, ros::param::del, ...)
    JSON_VIEWS: ClassVar[dict[str, Callable[[Any], Any]]] = {
        "deletes": lambda link: link.deletes,
    }

    @property
    def deletes(self) -> bool:
        return self.call is not None and self.call.deletes


LINK_CLASSES: dict[str, type[Link]] = {
    cls.KIND: cls
    for cls in (
        PublishLink, SubscribeLink, ServiceProviderLink, ServiceClientLink,
        ActionServerLink, ActionClientLink, ParamReadLink, ParamWriteLink,
    )
}
# ROS 2 parameter declarations read the parameter (and give it its default value)
LINK_CLASSES["declare"] = ParamReadLink


@dataclass(eq=False)
class Remap:
    """A remap a configuration's launch files give (``from:=to``, as written) and the
    node instances given it: those whose names it changed, and those that could use
    the name unseen (an interface partly or wholly unknown, a name with ``?`` that may
    be it, a container whose components take its remaps)."""

    source: str
    target: str
    nodes: list[NodeInstance] = field(default_factory=list)
    users: list[NodeInstance] = field(default_factory=list)
    # (and the includes not read that take it: ``Configuration.remaps``)
    unseen: list[NodeInstance | LaunchItem] = field(default_factory=list)
    # the conditions not decided for the configuration under which alone a node given
    # it makes the links it renames (``_conditional_use``): not a user for certain
    conditional: list[Condition] = field(default_factory=list)
    # what the nodes use beside the name: their names in its namespace or ending as it
    # does (``cmd_vel_mux/output`` for ``cmd_vel_mux/mux_cmd_vel``)
    near: list[str] = field(default_factory=list)
    # where it is written (ROS 1's ``<remap>`` element), when known
    place: Location | None = None

    @property
    def node(self) -> NodeInstance:
        return self.nodes[0]

    @property
    def location(self) -> Location:
        """Its ``<remap>`` element when known, else the first node it is given to."""
        return self.place or self.nodes[0].location

    @property
    def text(self) -> str:
        return f"{self.source}:={self.target}"

    @property
    def node_names(self) -> str:
        return ", ".join(n.name for n in self.nodes)

    @property
    def hint(self) -> str:
        """What the nodes use near the name, for a message: "" when nothing is."""
        return f" (they use {', '.join(self.near)})" if self.near else ""

    def __repr__(self) -> str:
        return f"Remap({self.text})"


def _could_use(instance: NodeInstance, name: str) -> bool:
    """Whether ``instance`` may use ``name`` through something the model does not show:
    an interface partly or wholly unknown; one read from an interface model of code that
    loads plugins (a remap is often given for a name a plugin adds: move_base's ``odom``
    is its local planner's; a complete model of code that loads none lists every name,
    its options' under their conditions, as the workspace's own code would), unless a
    host row loaded them (``NodeInstance.hosted``: ros2_control_node's controllers are
    nodes of the configuration, which take its remaps, and a plugin not found would
    have made it partial); a
    container, whose components take the process's remaps; a name with ``?`` that may
    be it; in ROS 1, a name on a handle whose namespace is not known (``?/camera_info``):
    roscpp resolves and remaps a NodeHandle's namespace, so that namespace may be it
    (depth_image_proc's ``NodeHandle(nh, "right")`` with ``right:=projector``)."""
    node = instance.node
    if node is None or not instance.is_complete or (
        node.model is not None and node.plugin_loads and not instance.hosted
    ):
        return True
    for link in instance.links:
        given = link.rosname.given
        if UNKNOWN_MARK not in given:
            continue
        head = given.rpartition("/")[0]
        if re.match(pattern_for(resolve(given, instance.namespace, instance.name)), name) or (
            re.match(pattern_for(link.rosname.full), name)
        ) or (instance.ros_version == 1 and UNKNOWN_MARK in head and re.match(
            pattern_for(resolve(head, instance.namespace, instance.name)), name)):
            return True
    return False


def _may_be_used(instance: NodeInstance, source: str, name: str) -> bool:
    """Whether a remap's source with ``?`` (a launch value not known statically:
    spot_ros2's ``f"{cam_prefix}/left/image"``, ``cam_prefix`` ``"/" + spot_name`` or
    empty) may be a name ``instance`` uses: one its ``?`` parts match, resolved in the
    node's namespace or, when the source starts with ``?``, as written (the unknown
    part may make it absolute)."""
    if UNKNOWN_MARK not in source:
        return False
    patterns = [pattern_for(name)]
    if source.startswith(UNKNOWN_MARK):
        patterns.append(pattern_for(source))
    for link in instance.links:
        before = resolve(link.rosname.given, instance.namespace, instance.name)
        if any(re.match(p, before) or re.match(p, link.rosname.full) for p in patterns):
            return True
    return False


def _conditional_use(instance: NodeInstance, name: str, target: str | None
                     ) -> tuple[Condition, ...]:
    """The conditions under which alone ``instance`` makes the links that use a remap of
    ``name`` to ``target`` (those it renamed, and those of the target's name)
    (``undecided``: each link's own, beside its instance's, as the remap goes with the
    instance), when every such link has one; else none (a link made for certain, or a
    use through no link seen: a handle's namespace)."""
    found: list[Condition] = []
    renamed = False
    for link in instance.links:
        if link.rosname.full != target and resolve(
            link.rosname.given, instance.namespace, instance.name
        ) != name:
            continue
        renamed = True
        own = [c for c in undecided(link.conditions) if c not in instance.conditions]
        if not own:
            return ()
        found.extend(c for c in own if c not in found)
    return tuple(found) if renamed else ()


def _near(instance: NodeInstance, name: str) -> list[str]:
    namespace, _, own = name.rpartition("/")
    found: set[str] = set()
    for link in instance.links:
        given = link.rosname.given
        if UNKNOWN_MARK in given or link.origin == "action" or isinstance(link, _ParamLink):
            continue  # what a remap is usually meant for: topics, services and actions
        before = resolve(given, instance.namespace, instance.name)
        space, _, last = before.rpartition("/")
        if before != name and ((namespace and space == namespace) or last == own):
            found.add(before)
    return sorted(found)


def unread_users(remap: Remap, includes: list[LaunchItem]) -> list[LaunchItem]:
    """The includes not read (``includes``) whose nodes may use ``remap``: those given
    its text (roslaunch gives an include the remaps written before it in its scope)
    whose nodes may resolve its source to the name it remaps for its own nodes: any, for
    a global source; for a relative one, an include in that namespace or above it (its
    file may push groups down to it, for the namespace of any node given the remap: one
    ``<remap>`` element reaches nodes of nested groups); never for a private ``~name``,
    another node's."""
    if remap.source.startswith("~"):
        return []
    spaces = {node.namespace.rstrip("/") + "/" for node in remap.nodes}
    return [item for item in includes if (remap.source, remap.target) in item.remaps and (
        remap.source.startswith("/") or any(
            at.startswith(item.namespace.rstrip("/") + "/") for at in spaces))]


def remaps_of(nodes: list[NodeInstance]) -> list[Remap]:
    """The remaps given to ``nodes``, one per ``from:=to`` pair as written and name it
    remaps (a pair given to several instances in one namespace is one remap: a list of
    remappings shared by a launch file's nodes; the same text given in two namespaces
    remaps two names, each its own remap), but a ROS 1 ``<remap>`` element is one remap
    whichever namespaces its nodes resolve it in (``NodeInstance.remap_places``: a
    group's element that a nested group's nodes do not use is still used), and two
    elements of one text are two (jackal's teleop.launch gives ``cmd_vel:=/cmd_vel`` to
    teleop_twist_joy in ``/bluetooth_teleop``, which uses it, and to the marker server
    in ``/``, which does not). Special keys (``__name``,
    ``__ns``) are left out. A remap of a name to itself (``imu/data:=imu/data``;
    ``cmd_vel:=/cmd_vel`` in the root namespace) is kept: it changes nothing here, but it
    says the author took the name to be one the node uses, and when no node it is given
    to uses it, that is wrong in every namespace (robot_localization's navsat_transform
    subscribes ``imu``; interactive_marker_twist_server publishes ``~cmd_vel``). A
    ``key:=value`` word that the node's code reads as an argument (roscpp's
    ``getROSArg``: tiago_tutorials' run_loop_node given ``robot:=steel``) is used."""
    found: dict[tuple[str, str, Location | str], Remap] = {}
    # the launch's nodes first: the remaps are theirs; the nodes hosts make can only use
    for instance in sorted(nodes, key=lambda n: n.origin != "launch"):
        rules = instance.remap_rules()
        # the names the instance uses, remapped or not: a remap to one of them makes no
        # connection the instance does not have (turtlebot's ``camera/image`` beside
        # ``image``, a workaround for a nodelet bug)
        reached = {link.rosname.full for link in instance.links}
        # the ``key:=value`` words its code reads as arguments (``PrimitiveCall.argument``)
        read = {c.name for c in instance.node.calls if c.argument} if (
            instance.node is not None) else set()
        # the names its code has roscpp resolve and remap (``PrimitiveCall.resolved``)
        resolves = {resolve(c.name, instance.namespace, instance.name)
                    for c in instance.node.calls if c.resolved and UNKNOWN_MARK not in c.name
                    } if instance.node is not None else set()
        for source, target in dict.fromkeys(instance.remaps):
            if not source or source.startswith("__"):
                continue
            name = resolve(source, instance.namespace, instance.name)
            # (a target not known statically is no name the instance is seen to use: the
            # ``?`` of another remap's unknown target is no use of this one, aerostack2's
            # ``('cloud', LaunchConfiguration('cloud_topic_in'))`` beside ``('scan', ...)``
            # given to pointcloud_to_laserscan, which subscribes cloud_in)
            to = rules.get(name)
            used = name in instance.remaps_applied or (
                to is not None and UNKNOWN_MARK not in to and to in reached) or (
                source in read) or name in resolves
            if instance.origin != "launch":
                # a node a host makes in its process (nav2's costmaps) takes the
                # process's remaps, given for the host: a use counts, a non-use does not
                # (resolved in its own namespace, the name is not its host's: the remap
                # is the one given to a launch node whose namespace holds it); one that
                # may use it unseen (a controller of a class found nowhere) may be its use
                unseen = not used and (_could_use(instance, name)
                                       or _may_be_used(instance, source, name))
                inside = instance.namespace.rstrip("/") + "/"
                for key, remap in found.items():
                    if key[:2] == (source, target) and any(
                        inside.startswith(n.namespace.rstrip("/") + "/")
                        for n in remap.nodes
                    ):
                        if used or unseen:
                            (remap.unseen if unseen else remap.users).append(instance)
                        # its names are among those the remap may have meant (the
                        # controller's own commands topic beside its manager's)
                        remap.near.extend(n for n in _near(instance, name)
                                          if n not in remap.near)
                continue
            # one ``<remap>`` element is one remap, whichever namespaces the nodes it
            # reaches resolve it in (autoware_mini's ``detected_objects:=...`` of a group
            # whose nested group's nodes do not use the name); without an element, one
            # per name it remaps
            place = instance.remap_places.get(f"{source}:={target}")
            remap = found.setdefault((source, target, place or name),
                                     Remap(source, target, place=place))
            remap.nodes.append(instance)
            maybe = _conditional_use(instance, name, rules.get(name)) if used else ()
            if maybe:
                remap.conditional.extend(c for c in maybe if c not in remap.conditional)
            elif used:
                remap.users.append(instance)
            elif _could_use(instance, name) or _may_be_used(instance, source, name):
                remap.unseen.append(instance)
            remap.near.extend(n for n in _near(instance, name) if n not in remap.near)
    return list(found.values())


@dataclass(eq=False)
class Configuration:
    """One configuration of the project and the Computation Graph it creates."""

    name: str
    launch: list[str] = field(default_factory=list)
    args: dict[str, str] = field(default_factory=dict)
    environment: dict[str, str] = field(default_factory=dict, metadata=INDEX)
    nodes: list[NodeInstance] = field(default_factory=list)
    topics: list[Topic] = field(default_factory=list)
    services: list[Service] = field(default_factory=list)
    actions: list[Action] = field(default_factory=list)
    parameters: list[Parameter] = field(default_factory=list)
    links: list[Link] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    # the workspace and installed-package folders that launch values lead into, as
    # $(find pkg) / FindPackageShare resolved them here: paths under them are portable
    package_paths: list[str] = field(default_factory=list)
    # how the launch files make the nodes: one tree per launch file named (launch_tree.py)
    launch_tree: list[LaunchItem] = field(default_factory=list, metadata={"optional": True})
    # the packages the launch files name (a node's, a $(find pkg)), one per launch file
    # and package, where first written (launch-undeclared-dependency)
    package_uses: list[PackageUse] = field(default_factory=list, metadata={"optional": True})
    # the robot descriptions spawned into a simulator, as read (robot.py)
    robot_descriptions: list[RobotDescription] = field(default_factory=list,
                                                       metadata={"optional": True})

    def __repr__(self) -> str:
        return f"Configuration({self.name})"

    @property
    def direct_links(self) -> list[Link]:
        """``links`` without the topic and service links that an action link stands for
        (``origin == "action"``): what the code (or a hint) asked for by name."""
        return [link for link in self.links if link.origin != "action"]

    @property
    def remaps(self) -> list[Remap]:
        """The remaps the launch files give its node instances (``remaps_of``). One no
        node uses that an include the launch stage could not read takes too (a package
        not found) may be used by what that file starts: the include is among its
        ``unseen`` (``unread_users``)."""
        found = remaps_of(self.nodes)
        unread = [item for tree in self.launch_tree for item in tree.walk()
                  if item.kind == "include" and not item.skipped and item.remaps]
        for remap in found if unread else ():
            if not remap.users:
                remap.unseen.extend(unread_users(remap, unread))
        return found

    @property
    def include_args(self) -> list[IncludeArg]:
        """The arguments the ROS 2 includes of its launch files pass, with how the
        included files use them (launch-include-argument-unused)."""
        return include_args(self.launch_tree)

    @property
    def incomplete_nodes(self) -> list[NodeInstance]:
        """The node instances whose interface is partly or wholly unknown: a link they
        may have is not in ``links``, so an absence is not a fact where they could be."""
        return [n for n in self.nodes if not n.is_complete]

    def node(self, name: str) -> NodeInstance | None:
        return next((n for n in self.nodes if n.name == name), None)

    def topic(self, name: str) -> Topic | None:
        return next((t for t in self.topics if t.name == name), None)

    def service(self, name: str) -> Service | None:
        return next((s for s in self.services if s.name == name), None)

    def parameter(self, name: str) -> Parameter | None:
        return next((p for p in self.parameters if p.name == name), None)
