"""Assemble a configuration's Computation Graph from its launch model and node models."""

from __future__ import annotations

import bisect
import os
from collections import Counter
from collections.abc import Mapping, Sequence
from dataclasses import replace
from typing import Any
from weakref import WeakKeyDictionary

from .. import diagnostics as diag
from ..diagnostics import Diagnostic
from ..launch.model import LaunchModel, NodeDecl, ParamDecl, shell_words
from ..launch.ros2.naming import pattern_matches
from ..model.conditions import EACH_STATEMENT, ELEMENT_PARAMETER, Condition
from ..model.launch_tree import LaunchItem, PackageUse, installed_check
from ..model.location import Location
from ..model.rosname import (
    RosName,
    clean,
    is_legal_name,
    is_ros2_node_name,
    namespace_of,
    own_unknown,
    remap,
    resolve,
    ros2_name_problem,
)
from ..model.runtime import (
    LINK_CLASSES,
    Action,
    Configuration,
    Link,
    NodeInstance,
    Parameter,
    Resource,
    Service,
    Topic,
)
from ..model.source import (
    COUNTED,
    LOADED,
    NUMBERED,
    PROCESS_HANDLE,
    ROS_ARGUMENT,
    WORDS,
    Node,
    PrimitiveCall,
    counted_turns,
    counts_length,
    name_runs,
)
from ..model.values import UNKNOWN_MARK, Unknown
from ..models import rviz
from ..models.commands import refused
from ..plugins.attach import (
    PROCESSES,
    PluginModels,
    chains,
    class_packages,
    own_partial,
    plugin_types,
)
from ..plugins.attach import attach as attach_plugins
from ..plugins.transports import RAW as RAW_TRANSPORT
from ..plugins.transports import Transports
from ..robot.attach import GZSERVER
from ..robot.attach import attach as attach_descriptions
from ..robot.bridge import IMAGE_BRIDGES, PARAMETER_BRIDGES
from ..rosrun import find_executable
from ..workspace import Workspace, installed_roots
from .actions import action_links
from .conditions import (
    NOT_GIVEN,
    decide,
    decide_links,
    drop_links,
    getopt_option,
    program_argument,
    program_option,
    program_views,
)
from .processes import (
    code_node,
    guessed_names,
    own_calls,
    process_nodes,
    process_params,
    unnamed_param_files,
)

RESOURCE_OF_KIND: dict[str, type[Resource]] = {
    "publish": Topic, "subscribe": Topic, "server": Service, "client": Service,
    "action-server": Action, "action-client": Action,
    "read": Parameter, "write": Parameter, "declare": Parameter,
}


class Resources:
    """Topics, services, actions and parameters by name; unresolved names stay apart."""

    def __init__(self, config: Configuration) -> None:
        self.config = config
        self.by_name: dict[tuple[type[Resource], str], Resource] = {}
        self.repeats: dict[tuple[type[Resource], str], int] = {}
        for collection in (config.topics, config.services, config.actions,
                           config.parameters):
            for resource in collection:
                key = (type(resource), resource.name)
                self.by_name.setdefault(key, resource)
                if UNKNOWN_MARK in resource.name:
                    self.repeats[key] = self.repeats.get(key, 0) + 1

    def get(self, cls: type[Resource], name: str, owner: str | None = None) -> Resource:
        """The resource of a name; a new one for each name with ``?``, as two unknown
        parts may differ, unless its one unknown part is in the name of its ``owner``,
        the node whose private parameter it is (``own_unknown``): one node's."""
        key = (cls, name)
        if (UNKNOWN_MARK not in name or (
                cls is Parameter and owner is not None and own_unknown(owner, name))
                ) and key in self.by_name:
            return self.by_name[key]
        resource = cls(name)
        kind = cls.__name__.lower()
        resource.id = f"{kind}:{name}"
        if key in self.by_name:  # a second unresolved name: keep ids unique
            self.repeats[key] = self.repeats.get(key, 1) + 1
            resource.id += f"#{self.repeats[key]}"
        self.by_name.setdefault(key, resource)
        self._collection(cls).append(resource)
        return resource

    def _collection(self, cls: type[Resource]) -> list[Any]:
        collections: dict[type[Resource], list[Any]] = {
            Topic: self.config.topics, Service: self.config.services,
            Action: self.config.actions, Parameter: self.config.parameters,
        }
        return collections[cls]


def remaps_in_args(args: str) -> list[tuple[str, str]]:
    """``from:=to`` pairs among a node's command-line arguments (not ``__name:=``)."""
    words = shell_words(args)
    pairs = []
    for word in words:
        if ":=" in word and not word.startswith("_"):
            source, target = word.split(":=", 1)
            pairs.append((source, target))
    return pairs


def ros_argument(instance: NodeInstance, key: str) -> str | None:
    """The value of the ``key:=value`` word roslaunch gives a ROS 1 instance (of its
    ``args`` or a ``<remap>``: both are such words of its command line), the first as
    roscpp's ``getROSArg`` finds it; None when none gives it or its value is unknown."""
    value = next((target for source, target in instance.remaps if source == key), None)
    return None if value is None or UNKNOWN_MARK in value else value


CHAIN_DEPTH = 4  # filter chains configured by the filters of a chain, and so on


def build(config: Configuration, launch: LaunchModel, workspace: Workspace,
          nodes: Mapping[str, Node], plugin_models: PluginModels | None = None,
          ) -> Configuration:
    """Fill ``config`` with node instances, resources and links; ``nodes`` by pkg/exec;
    ``plugin_models`` finds plugin classes of packages without source in their models."""
    resources = Resources(config)
    config.diagnostics.extend(launch.diagnostics)
    config.diagnostics.extend(guessed_names(launch, nodes))
    config.diagnostics.extend(unnamed_param_files(launch, nodes))
    given = process_params(launch, nodes)
    unknown_nodes = [decl.name for decl in launch.nodes if UNKNOWN_MARK in decl.name]
    for param in given:
        owner = next((n for n in unknown_nodes if own_unknown(n, param.name)), None)
        parameter = resources.get(Parameter, param.name, owner)
        assert isinstance(parameter, Parameter)
        parameter.launch_type = param.type
        parameter.value = param.value
        parameter.set_by_launch = True
        parameter.launch_location = param.location
        parameter.launch_conditions = param.conditions
        parameter.for_test = param.test
        parameter.setting = param.setting
    transports = Transports(workspace, resources)
    seen: dict[str, NodeInstance] = {}
    started: list[tuple[NodeDecl, NodeInstance]] = []
    # the calls a nodelet loaded into a manager makes on handles its code constructs,
    # with the manager's name: linked once every instance, the manager's too, is known
    in_manager: list[tuple[NodeInstance, list[PrimitiveCall], str]] = []
    per_plugin: list[tuple[NodeInstance, list[PrimitiveCall]]] = []
    own_values = _own_values(launch, given)
    for index, launched, decl, own in (
            (index, original, decl, own) for index, original in enumerate(launch.nodes)
            for decl, own in process_nodes([original], nodes)):
        instance = _instance(decl, nodes, workspace, config)
        if index in own_values:
            _OWN_VALUES[instance] = own_values[index]
        if own is not None and own.rsplit("/", 1)[-1] != instance.name.rsplit("/", 1)[-1]:
            instance.code_name = own
        instance.conditions = (*instance.conditions, *_made_under(instance.node, own))
        started.append((decl, instance))
        # two instances with one name keep apart by id; the duplicate-node-names query
        # reports them (and roslaunch's own refusal is LAUNCH_NODE_DUPLICATE)
        instance.id = f"node:{instance.name}"
        if instance.name in seen:
            instance.id += f"#{sum(1 for n in config.nodes if n.name == instance.name) + 1}"
        seen.setdefault(instance.name, instance)
        config.nodes.append(instance)
        if instance.node is None:
            continue
        calls = [*own_calls(decl, instance.node, own), *in_process_nodelets(
            instance, nodes, plugin_models)]
        manager = loading_manager(decl)
        moved = [c for c in calls if c.handle_origin == PROCESS_HANDLE] if (
            manager is not None) else []
        if moved:
            in_manager.append((instance, moved, manager or ""))
            calls = [c for c in calls if c.handle_origin != PROCESS_HANDLE]
        if instance.ros_version == 2:
            PROCESSES[instance] = (launched, instance)
        # a call per plugin object the host keeps: once its plugins are attached
        kept = [c for c in calls if _per_kept_plugin(c)]
        if kept:
            per_plugin.append((instance, kept))
            calls = [c for c in calls if not _per_kept_plugin(c)]
        _link_process(instance, calls, resources, config, transports)
    for instance, calls, manager in in_manager:
        _link_in_manager(instance, calls, manager, resources, config, transports)
    # robot descriptions first: a ros2_control Gazebo plugin starts a controller manager
    # whose controllers the plugin hosts load, and a ROS 1 gazebo_ros_control plugin
    # serves the controller_manager services the spawners' controllers are loaded by
    # (linked before the plugins attach, which look for the instance that serves them)
    # the ROS 1 gazebo node an unread include of gazebo_ros' launch files starts: its
    # gzserver, of the distribution's model (looked up, so listed, only when needed)
    models = plugin_models
    described = attach_descriptions(
        config, launch, started, workspace, resources, given,
        None if models is None else lambda: models(GZSERVER))
    for instance, calls in described.calls:
        _link_calls(instance, calls, resources, config, transports)
    config.launch_tree = launch.tree  # the includes not read, which may set parameters
    attached = attach_plugins(config, [*started, *described.managers], nodes, resources,
                              workspace, plugin_models, described.hardware)
    for instance, calls in [*per_plugin, *attached]:
        _link_process(instance, calls, resources, config, transports)
    # then the classes any instance's own code loads by a parameter's value (filters'
    # chains), controllers and plugins made above included, and the chains those
    # classes configure in turn (a few levels)
    chained: list[tuple[NodeInstance, list[PrimitiveCall]]] = []
    done: set[tuple[int, str]] = set()
    for _ in range(CHAIN_DEPTH):
        more = chains(config, nodes, resources, workspace, plugin_models, done)
        for instance, calls in more:
            _link_process(instance, calls, resources, config, transports)
        chained += more
        if not more:
            break
    _drop_base_copies(config, [*attached, *chained])
    config.diagnostics.extend(_foreign_sections(launch, config, nodes, plugin_models))
    for action, call, name in action_links(config):
        link(action.node, call, {}, resources, config, _wire_remapped(action.node, name))
    config.launch_tree = launch.tree  # what decide_links asks of includes not read
    _field_watchers(config, resources)
    decide_links(config)  # source conditions this configuration decides
    _namespace_values(config)
    config.package_paths = package_paths(launch, workspace)
    config.package_uses = package_uses(launch, workspace, started)
    return config


def _wire_remapped(instance: NodeInstance, name: RosName) -> RosName:
    """A ROS 1 action's topic as the node's remaps rename it: actionlib makes each on a
    handle in the action's namespace (roscpp's ``NodeHandle(nh, "move_base")``, rospy's
    ``remap_name(ns) + "/goal"``), and roscpp and rospy remap every name they resolve,
    so ``move_base/goal:=motion_manager/move_base/goal`` moves that topic alone
    (omniveyor's explore launch file moves all five of explore_lite's client). The
    action's own name is remapped already (``link``)."""
    if instance.ros_version != 1 or UNKNOWN_MARK in name.full:
        return name
    moved = _Applied(instance.remap_rules(), instance).get(name.full, name.full)
    if moved is None or moved == name.full:
        return name
    return RosName(name.given, moved, namespace_of(moved))


def _field_watchers(config: Configuration, resources: Resources) -> None:
    """rostopic's watchers (``PrimitiveCall.name_field``) subscribe to the topic their
    name is, when one is published; else to the longest published topic whose name
    followed by ``/`` begins it, the rest a field of its message (ros_comm's
    ``_get_topic_type``: ``rostopic echo /odom/pose/pose`` subscribes to ``/odom``).
    Such a subscription moves to that topic; one with no such topic stays as named."""
    published = {topic.name: topic for topic in config.topics
                 if UNKNOWN_MARK not in topic.name
                 and any(link.kind == "publish" for link in topic.links)}
    for made in config.links:
        call = made.call
        if made.kind != "subscribe" or call is None or not call.name_field or (
                made.rosname.full in published or UNKNOWN_MARK in made.rosname.full):
            continue
        full = made.rosname.full
        prefixes = [name for name in published if full.startswith(name.rstrip("/") + "/")]
        if not prefixes:
            continue
        topic = published[max(prefixes, key=len)]
        before = made.resource
        before.links = [link for link in before.links if link is not made]
        if not before.links and before in config.topics:
            config.topics.remove(before)
            resources.by_name.pop((Topic, before.name), None)
        made.resource = topic
        made.rosname = replace(made.rosname, full=topic.name,
                               namespace=namespace_of(topic.name))
        topic.links.append(made)


def _foreign_sections(launch: LaunchModel, config: Configuration,
                      nodes: Mapping[str, Node] | None = None,
                      models: PluginModels | None = None) -> list[Diagnostic]:
    """``LAUNCH_PARAMS_NO_NODE`` for each ROS 2 parameter file whose sections are all for
    names none of the nodes it is given to has (``LaunchModel.foreign_sections``). rcl
    applies the file in the processes it is given to, so only a node one of them makes
    can take a section: not said when a node of the configuration has one of the names
    (a nav2 server's costmap takes its section of the server's file), nor when a node
    it is given to may make nodes we do not see (its code is not known, or it loads
    plugins by name)."""
    names = [n.name for n in config.nodes]
    by_name = {n.name: n for n in config.nodes}
    found: list[Diagnostic] = []
    for item in launch.foreign_sections:
        given = [by_name.get(name) for name in item.nodes]
        if any(n is None or n.node is None or n.node.plugin_loads for n in given):
            continue
        patterns = item.patterns
        if item.lonely:  # the sections no node has, named after the node
            alone = given[0]
            runs = _component_executables(alone.node, nodes or {}, models) if (
                alone is not None and alone.node is not None) else set()
            patterns = [p for p in patterns if _names_the_node(p, alone, runs) and not any(
                pattern_matches(p, name) for name in names)]
            if not patterns:
                continue
        elif any(pattern_matches(p, name) for p in patterns for name in names):
            continue
        found.append(diag.make("LAUNCH_PARAMS_NO_NODE", item.location, file=item.path,
                               nodes=", ".join(item.nodes), patterns=", ".join(patterns)))
    return found


def _component_executables(node: Node, nodes: Mapping[str, Node],
                           models: PluginModels | None) -> set[str]:
    """The executables ``node``'s package builds of a component's own sources, none for
    another node: those ``rclcpp_components_register_node(... EXECUTABLE x)`` makes, which
    run the component in a process of their own (pointcloud_to_laserscan_node for
    ``pointcloud_to_laserscan::PointCloudToLaserScanNode``); of the workspace's nodes, or of
    the package's interface model."""
    if node.kind != "component" or not node.sources:
        return set()
    siblings = [n for key, n in nodes.items() if key.partition("/")[0] == node.package]
    package = getattr(models, "package", None)
    model = package(node.package) if callable(package) else None
    if model is not None:
        siblings += model.nodes
    own = sorted(node.sources)
    return {n.executable for n in siblings
            if n.kind == "executable" and sorted(n.sources) == own}


def _names_the_node(pattern: str, instance: NodeInstance | None,
                    runs: set[str] | frozenset[str] = frozenset()) -> bool:
    """Whether a parameter file's section (``/teleop_node``, ``teleop_node``), which
    does not match the node, is named after it: after the node's executable or the name
    its code gives it, not the name the launch file gave it (a section written for the
    node before it was renamed), or, with no wildcard, after the name the launch file
    gave it in another namespace (``/cabot/people_speed_control_node`` for the node
    started as ``/people_speed_control_node``: written for the namespace the launch file
    does not give it). ``runs``: for a component, the executables that run it alone
    (``_component_executables``), whose names a section may be written under."""
    node = instance.node if instance is not None else None
    if instance is None or node is None:
        return False
    last = pattern.rstrip("/").rsplit("/", 1)[-1]
    if last in ("", "*", "**"):
        return False
    if last == instance.name.rsplit("/", 1)[-1]:
        return "*" not in pattern
    own = {node.executable.rsplit("/", 1)[-1], (node.rosname or "").rsplit("/", 1)[-1],
           (instance.code_name or "").rsplit("/", 1)[-1], *runs}
    return last in own


def loading_manager(decl: NodeDecl) -> str | None:
    """The full name of the manager ``<node pkg="nodelet" type="nodelet" args="load
    pkg/Name manager">`` loads its nodelet into: the loader resolves it in its own
    namespace (nodelet.cpp's ``manager + "/load_nodelet"`` service); None for another
    declaration (``standalone``: the process is the nodelet's own)."""
    words = decl.args.split()
    if nodelet_plugin(decl) is None or words[0] != "load" or len(words) < 3:
        return None
    # (a word that is no name, an argument's text left as written: not known)
    known = is_legal_name(words[2].replace(UNKNOWN_MARK, "x"))
    return resolve(words[2] if known else UNKNOWN_MARK, decl.namespace)


def _link_process(instance: NodeInstance, calls: Sequence[PrimitiveCall],
                  resources: Resources, config: Configuration,
                  transports: Transports) -> None:
    """Link a node instance's calls, those made on a node a library makes in its process
    (ROS 2, ``PrimitiveCall.handle_origin`` ``process``) where that node resolves them
    (``_process_node``)."""
    library = [c for c in calls if c.handle_origin == PROCESS_HANDLE]
    process = _process_node(instance) if library else None
    if process is not None:
        _link_calls(instance, library, resources, config, transports, at=process,
                    noted=instance)
        calls = [c for c in calls if c.handle_origin != PROCESS_HANDLE]
    _link_calls(instance, calls, resources, config, transports)


def _process_node(instance: NodeInstance) -> NodeInstance | None:
    """ROS 2: the node a library makes with default options in the process of
    ``instance`` (tf2_ros' ``TransformListener(buffer)``: ``transform_listener_impl_``
    and an address), where the calls it makes there resolve. It takes the process's
    global arguments only: the namespace and remaps of the launch declaration that
    starts the process (and the name ``name=`` gives every node of it), not the
    namespace the code gives the node the call is written in (nav2's costmap, a node of
    its own in ``/local_costmap``), nor the local arguments of a controller. None where
    the process is not known here (an instance no launch declaration starts: a hint's),
    and for a component, whose process is its container's: those calls stay the
    instance's own, as before."""
    found = PROCESSES.get(instance)
    if instance.ros_version != 2 or found is None or found[0].composable:
        return None
    decl, started = found
    name = decl.name if decl.name_given else resolve(
        f"transform_listener_impl_{UNKNOWN_MARK}", decl.namespace)
    return NodeInstance(name, instance.node, namespace=decl.namespace,
                        remaps=list(started.remaps), args=started.args,
                        conditions=instance.conditions, location=instance.location,
                        ros_version=2)


def _link_in_manager(instance: NodeInstance, calls: Sequence[PrimitiveCall], manager: str,
                     resources: Resources, config: Configuration,
                     transports: Transports) -> None:
    """Link the calls a nodelet loaded into ``manager`` makes on handles its code
    constructs (``PrimitiveCall.handle_origin`` ``process``): roscpp makes such a
    handle in the process's node, the manager's, so its names resolve in the manager's
    namespace, ``~`` is the manager's private namespace, and the remaps are the
    manager's, not those the nodelet was loaded with (laser_filters before 7c18194).
    The links stay the nodelet instance's: its code makes them. A manager the
    configuration does not start gives its name, from the load's arguments, and no
    remaps known: NODELET_PROCESS_HANDLES says so."""
    found = [n for n in config.nodes if n.name == manager and n.ros_version == 1]
    process = found[0] if len(found) == 1 else None
    at = NodeInstance(manager, instance.node, namespace=namespace_of(manager),
                      remaps=list(process.remaps) if process is not None else [],
                      args=process.args if process is not None else "",
                      conditions=instance.conditions, location=instance.location)
    config.diagnostics.append(diag.make(
        "NODELET_PROCESS_HANDLES", instance.location, nodelet=instance.name,
        count=len(calls), manager=manager, remaps="its remaps" if process is not None
        else "no remaps known: the configuration does not start it"))
    _link_calls(instance, calls, resources, config, transports, at=at,
                noted=process or at)


def _link_calls(instance: NodeInstance, calls: Sequence[PrimitiveCall], resources: Resources,
                config: Configuration, transports: Transports,
                at: NodeInstance | None = None, noted: NodeInstance | None = None) -> None:
    """Link a node instance's calls: one per element of a list parameter, and for an
    image_transport publisher or subscriber the topics of its transport plugins. The
    names resolve as the node ``at`` (by default the instance itself) resolves them,
    whose remaps that change a name are noted on ``noted`` (``at`` by default): a
    nodelet's calls on the handles of its manager's process (``_link_in_manager``)."""
    made = instance
    instance = at or instance
    remaps = _Applied(instance.remap_rules(), noted or instance)
    images: dict[Location, list[PrimitiveCall]] = {}  # image_transport calls by place
    for each in calls:
        if each.transport is not None:
            images.setdefault(each.location, []).append(each)
    for call in calls:
        if call.argument or call.resolved:
            # a command-line word the code reads, a name roscpp resolves for it: no
            # ROS resource
            continue
        if call.name_option_null and call.name_getopt is not None and (
            call.name_option is not None and UNKNOWN_MARK in call.name
            and getopt_option(instance, call.name_option, call.name_getopt,
                              NOT_GIVEN) == NOT_GIVEN
        ):
            # named by a getopt option's argument, a null pointer where the instance's
            # arguments do not give the option (pr2_ethercat's ``-x`` beside ``-r``):
            # ``std::string`` of it throws, the call names nothing
            continue
        for each in element_calls(call, instance, resources):  # list parameters
            each = _argument_param(each, instance)
            if each.camera_of is not None:
                info = _camera_info(instance, each, images.get(each.location, []), remaps,
                                    resources)
                if info is not None:
                    link(made, each, remaps, resources, config, info)
                    continue
            base = resolved_name(instance, each, remaps, resources)
            if each.name_param is not None and base.is_unresolved and (
                each.name.count(UNKNOWN_MARK) == 1
                or _given_name(each, instance, resources) == each.name
            ):
                # (a name of several unknown runs keeps the others: unset only when the
                # parameter gave none)
                config.diagnostics.append(_name_param_unset(instance, each, resources))
            if each.name_arg is not None and UNKNOWN_MARK in each.name and not (
                program_argument(instance, each.name_arg)
            ):
                config.diagnostics.append(_name_arg_unset(instance, each))
            if each.transport is None:
                link(made, each, remaps, resources, config, base)
                continue
            # the transport's topic is named below the base and resolved (and remapped)
            # again; ROS 1 image_transport's publishers and camera subscribers remap the
            # base first (resolveName), its Subscriber (``/`` mark) and ROS 2's only
            # expand it (expand_topic_or_service_name): usb_cam's launch file remaps
            # image_raw/compressed on its own; unless the ROS 2 code gave it a base it
            # resolved and remapped itself (``=`` mark: image_pipeline)
            remapped = each.transport.endswith("=") or (
                instance.ros_version == 1 and not each.transport.endswith("/"))
            plain = resolved_name(instance, each, {}, resources)
            expanded = base if remapped else plain
            for one in transports.calls(each, expanded.full, instance,
                                        _transport_given(each, instance, resources)):
                link(made, one, remaps, resources, config, base if one is each else
                     _below_base(resolved_name(instance, one, remaps, resources), expanded,
                                 plain.full, instance.namespace))


def _transport_given(call: PrimitiveCall, instance: NodeInstance,
                     resources: Resources) -> str | None:
    """What gives an image_transport subscriber's ``?`` transport where the node's
    ``image_transport`` parameter does not (``PrimitiveCall.transport_param``, ...): the
    value of a parameter, else of a program argument, else a default written in the
    code, else ``raw``; None when not known (an argument the launch file does not give,
    a value the extractor could not read)."""
    default = call.transport_default
    if call.transport_arg is not None:
        default = program_argument(instance, call.transport_arg)
    elif default is None:
        default = RAW_TRANSPORT
    if call.transport_param is not None:
        default = _parameter_value(call.transport_param, default, instance, resources)
    return None if default is None or UNKNOWN_MARK in default else default


def _drop_base_copies(config: Configuration,
                      attached: Sequence[tuple[NodeInstance, Sequence[PrimitiveCall]]]) -> None:
    """A host's own calls with ``?`` in their name made where its plugins' calls are
    (the same kind and place) are the plugins' base-class code, which the host's
    executable links (nav2's costmap runs ``CostmapFilter::onInitialize`` for each
    filter): each plugin's copy names them, so the host's unnamed copy goes. Kept when
    the host is not complete (a plugin not known may be what runs that code). A plugin's
    own copy stays, also one whose ``?`` is the value of a parameter the graph has just
    read under the plugin's name: a ros_control controller's topic named by its
    ``topic_command`` parameter (sawyer_sim_controllers' head controller: its
    subscription was dropped once the controller's code parsed clean)."""
    places: dict[int, set[tuple[str, Location]]] = {}
    copies: set[int] = set()  # the plugins' calls themselves
    for instance, calls in attached:
        # the plugins' calls, not the instance's own (a host's child, a costmap that a
        # planner server makes, comes with its node's calls)
        own = {id(c) for c in instance.node.calls} if instance.node is not None else set()
        places.setdefault(id(instance), set()).update(
            (c.kind, c.location) for c in calls if id(c) not in own)
        copies.update(id(c) for c in calls if id(c) not in own)
    gone = []
    for instance in config.nodes:
        node, placed = instance.node, places.get(id(instance))
        if node is None or not placed or node.completeness != "complete":
            continue
        unnamed = {(c.kind, c.location, c.name) for c in node.calls
                   if UNKNOWN_MARK in c.name and (c.kind, c.location) in placed}
        gone += [link for link in instance.links if link.call is not None
                 and id(link.call) not in copies and (
                     link.call.kind, link.call.location, link.call.name) in unnamed]
    if gone:
        drop_links(config, gone)


def _camera_info(instance: NodeInstance, info: PrimitiveCall, images: list[PrimitiveCall],
                 remaps: Mapping[str, str], resources: Resources) -> RosName | None:
    """The camera_info topic of an image_transport camera publisher or subscriber:
    ``camera_info`` in the namespace of its image topic (of ``images``, the image_transport
    calls at the same place: the one of the same kind, or the one named as ``camera_of``
    says) as ROS 1 resolves and remaps it (``resolveName``) or ROS 2 expands it (or takes
    it as the code resolved it), then
    remapped on its own; named as the code wrote it. None when the image topic is not
    known: the info call's own name is used."""
    same = [c for c in images if c.kind == info.kind]
    if len(same) > 1:
        same = [c for c in same if c.name == info.camera_of]
    if len(same) != 1:
        return None
    image = same[0]
    # ROS 2 expands it only, unless the code gave a base it resolved (and so remapped)
    # itself (``=`` mark: apriltag_ros' resolve_topic_name("image_rect"))
    remapped = instance.ros_version == 1 or (image.transport or "").endswith("=")
    base = resolved_name(instance, image, remaps if remapped else {}, resources)
    if UNKNOWN_MARK in base.full:
        return None
    named = RosName.make(f"{base.full.rpartition('/')[0]}/camera_info", instance.namespace,
                         instance.name, remaps)
    return replace(named, given=info.name)


def _below_base(rosname: RosName, base: RosName, plain: str, namespace: str) -> RosName:
    """A name an image_transport plugin makes below the base topic, resolved from it
    (``/cam/image/compressed``), given as the code wrote the base (``image/compressed``):
    global only when the base was. A base a remap changed before the plugin named
    below it (``plain``: the base without remaps; roscpp's resolveName, a ROS 2 base the
    code resolved) is what the plugin's name is remapped from in turn, not the code's
    base: given relative to the node's namespace when inside it (flir_blackfly's
    debayer, ``image_color:=color/image``: ``color/image/compressed``, which a rule
    ``image_color/compressed:=...`` does not remap). The resolved name stays as the
    plugin resolves it."""
    prefix = base.full.rstrip("/") + "/"
    if base.is_global or not rosname.given.startswith(prefix):
        return rosname
    inside = namespace.rstrip("/") + "/"
    if base.full != plain and rosname.given.startswith(inside):
        return replace(rosname, given=rosname.given[len(inside):])
    return replace(rosname, given=f"{base.given.rstrip('/')}/{rosname.given[len(prefix):]}")


class _Applied(dict[str, str]):
    """An instance's resolved remaps that note, on the instance, each one that changes
    a name it is asked for (``remap`` and ``RosName.make`` ask with ``get``)."""

    def __init__(self, rules: dict[str, str], instance: NodeInstance) -> None:
        super().__init__(rules)
        self.instance = instance

    def get(self, key: str, default: str | None = None) -> str | None:  # type: ignore[override]
        found = super().get(key)
        if found is None:
            return default
        if found != key and key not in self.instance.remaps_applied:
            self.instance.remaps_applied.append(key)
        return found


def package_paths(launch: LaunchModel, workspace: Workspace) -> list[str]:
    """The folders (workspace roots, installed package roots, absolute paths the launch
    files took from the environment) that launch values lead into: ``$(find
    pkg)/maps/a.yaml`` or ``$(env HOME)/maps/a.yaml`` is an absolute path here, but not a
    hard-coded one."""
    roots = {os.path.normpath(r) for r in (*workspace.roots,
                                           *installed_roots(workspace.environment)) if r}
    # a value of the environment is a folder or the whole path ($(env MAP_FILE))
    environment = {v.rstrip("/") for v in launch.environment_values
                   if v.startswith("/") and v.strip("/") and "\n" not in v}
    roots |= environment
    texts = [p.value for p in launch.params if isinstance(p.value, str)]
    texts += [d.args for d in launch.nodes]
    return sorted(root for root in roots
                  if any(root.rstrip("/") + "/" in text or (
                      root in environment and root in text.split()) for text in texts))


TEST_FOLDERS = ("test", "tests")  # a package's folders of rostest / launch_testing files


def package_uses(launch: LaunchModel, workspace: Workspace,
                 started: Sequence[tuple[NodeDecl, NodeInstance]] = ()) -> list[PackageUse]:
    """The packages the launch files name, one per launch file and package, where first
    written: the packages of the nodes they start (a nodelet's: the package its class was
    found in, among ``started``) and the folders their substitutions ask for
    (``$(find pkg)``); ``test`` when rostest or launch_testing runs the file (one under
    its package's test/ or tests/ folder, a ``.test`` file) or the node is a ``<test>``,
    where a package's test dependencies are installed too."""
    uses = [PackageUse(d.package, d.package_location or d.location, "node", d.is_test,
                       _guard(d))
            for d in launch.nodes]
    uses += [PackageUse(instance.node.package, decl.location, "node", decl.is_test,
                        _guard(decl))
             for decl, instance in started
             if instance.node is not None and nodelet_plugin(decl) is not None]
    uses += launch.package_uses
    uses.sort(key=lambda u: (str(u.location.file), u.location.line, u.location.column))
    tests: dict[str, bool] = {}
    found: dict[tuple[str, str, bool], PackageUse] = {}
    for use in uses:
        file = use.location.file
        if not file or not use.location.package or not use.package.strip():
            continue  # a file of no package of the workspace, or no name at all
        if file not in tests:
            tests[file] = _test_file(file, workspace)
        test = use.test or tests[file]
        key = (file, use.package, test)
        if key not in found or (found[key].guard is not None and use.guard is None) or (
                found[key].chosen_by and not use.chosen_by and use.guard is None):
            # one not under an install check wins, and one whose name the file chose
            found[key] = replace(use, test=test)
    return list(found.values())


def _guard(decl: NodeDecl) -> str | None:
    """The package whose installation a launch condition of ``decl`` checks (a ROS 2
    Python ``if 'G' in get_packages_with_prefixes():`` around it)."""
    return installed_check(c.text for c in decl.conditions
                           if c.kind == "launch" and c.statement == "if")


def _test_file(file: str, workspace: Workspace) -> bool:
    """A launch file rostest or launch_testing runs: a ``.test`` file, or one under a
    test/ or tests/ folder of its package."""
    if file.endswith(".test"):
        return True
    path = os.path.join(workspace.root, file)
    package = workspace.package_of(path)
    if package is None or not package.root:
        return False
    folders = os.path.relpath(os.path.dirname(path), package.root).split(os.sep)
    return any(folder in TEST_FOLDERS for folder in folders)


def _namespace_values(config: Configuration) -> None:
    """A parameter read as a whole namespace (``get_param("gains")`` when the launch file
    sets ``gains/P``, ``gains/I``) holds the dictionary of what is set under it, as the
    parameter server answers. A ROS 2 read of a prefix (``PrimitiveCall.under``: the
    parameter ``gains.`` of ``get_parameters_by_prefix("gains")``, when the configuration
    sets ``gains.P``, ``gains.I.max``) is the same read with ``.`` for ``/``, its
    dictionary keyed by the rest of each name (``P``, ``I.max``), as rclpy and rclcpp
    give it; it does not read ``gains`` itself. A node that does not declare the
    overrides it is given (``PrimitiveCall.declared_only``) gets only what it declares
    there: what nothing else of it reads is not read as part of it."""
    set_params = [p for p in config.parameters if p.set_by_launch]
    # their names in order, and each one's place among them: the names under a prefix
    # are one run of the sorted names (found by bisection, then taken in their order)
    order = sorted(range(len(set_params)), key=lambda index: set_params[index].name)
    names = [set_params[index].name for index in order]
    for param in config.parameters:
        if param.set_by_launch or not param.readers or param.is_unresolved:
            continue
        under = any(link.call is not None and link.call.under for link in param.readers)
        prefix = param.name if under else param.name.rstrip("/") + "/"
        first = bisect.bisect_left(names, prefix)
        last = first
        while last < len(names) and names[last].startswith(prefix):
            last += 1
        below = [set_params[index] for index in sorted(order[first:last])]
        if all(link.call is not None and link.call.declared_only for link in param.readers):
            # a ROS 2 node that does not declare its overrides gets only the parameters
            # it declares (``PrimitiveCall.declared_only``): what it reads by name, never
            # one the configuration sets beside them
            below = [child for child in below if child.readers]
        if not below:
            continue
        tree: dict[str, Any] = {}
        for child in below:
            if child.is_unresolved:  # ``ns/?``: a file not read sets what is unknown
                continue
            rest = child.name[len(prefix):]
            *path, leaf = [rest] if under else rest.split("/")
            branch = tree
            for key in path:
                branch = branch.setdefault(key, {})
            branch[leaf] = child.value
        if not all(link.call is not None and link.call.keys_only for link in param.readers):
            for child in below:  # unless every reader takes its keys alone
                child.read_as_part_of = param
        param.value = None if any(c.is_unresolved for c in below) else tree
        # a dictionary when some key under the name is known; set only through content
        # not known (``name/?``: a ``<rosparam param="name">`` that is no YAML, a file not
        # named statically), the value may be a scalar as well: no type
        param.launch_type = "dict" if tree else None
        param.set_by_launch = True
        param.launch_location = below[0].launch_location
        param.launch_conditions = below[0].launch_conditions


def _instance(decl: NodeDecl, nodes: Mapping[str, Node], workspace: Workspace,
              config: Configuration) -> NodeInstance:
    key = node_key(decl, nodes)
    plugin = nodelet_plugin(decl)
    # rostopic pub, a ROS 2 spawner: its arguments say (a spawner's first: its code or
    # interface model builds its names from sys.argv)
    node = code_node(decl, nodes, key)
    why = refused(decl)
    if why is not None:
        config.diagnostics.append(diag.make("NODE_EXITS", decl.location, node=key, why=why))
    # rviz: the displays and tools of the configuration it is started with
    node = rviz.with_displays(decl, node, workspace, config.diagnostics) or node
    if node is not None and plugin is None and node.kind == "nodelet":
        # a program no target of its package's CMake files makes, built by a command
        # from outside the workspace that was given this nodelet (``node_key``)
        config.diagnostics.append(diag.make(
            "NODE_STANDALONE_NODELET", decl.location, node=f"{decl.package}/{decl.executable}",
            plugin=node.executable))
    if node is None and plugin is None and is_container(decl):
        # a nodelet manager or component container: what it loads are node instances of
        # their own; the process's own interface is its loader's services, known
        node = container_node(decl)
    elif node is None and plugin is None and UNKNOWN_MARK in key:
        # ``executable=LaunchConfiguration('script')`` with no value: which program runs
        # is not known, not missing (crazyswarm2's example launch file)
        config.diagnostics.append(diag.make("NODE_TYPE_UNKNOWN", decl.location, node=key))
    elif node is None and plugin is not None and key == plugin and _bare(plugin):
        config.diagnostics.append(diag.make("NODE_NOT_FOUND", decl.location, node=plugin,
                                            hint=""))
    elif node is None and workspace.find(key.partition("/")[0]) is None:
        # the package's interface model was found without this node: said there
        if not any(d.code == "MODEL_NODE_MISSING" and d.location == decl.location
                   for d in config.diagnostics):
            name = key.partition("/")[0]
            # (a ros_gz bridge's topics are its arguments: ``robot.bridge`` reads them)
            bridge = (decl.package, decl.executable) in (*PARAMETER_BRIDGES, *IMAGE_BRIDGES)
            config.diagnostics.append(diag.make(
                "NODE_PACKAGE_UNKNOWN", decl.location, name=name, node=plugin or key,
                why=workspace.absence(name),
                interface="its topics are read from its arguments" if bridge
                else "its interface is unknown"))
    elif node is None and plugin is None and decl.ros_version == 1 and (
        found := _program_file(workspace, *key.partition("/")[::2])
    ):
        config.diagnostics.append(diag.make("NODE_NOT_READ", decl.location, node=key,
                                            path=workspace.relpath(found)))
    elif node is None and plugin is None and (
        found := _installed_program(workspace, decl.package, decl.executable)
    ):
        # a shell script (or prebuilt program) its package installs into its lib folder
        # (mrover-ros2's ``install(PROGRAMS .../gui_prod.sh DESTINATION lib/...)``):
        # ros2 launch runs it; so does roslaunch from the install space, with the execute
        # bit install(PROGRAMS) gives the copy whatever the source file's (subt's
        # ``rostopic_stats_logger.sh``, 644 in git); not missing, not read
        config.diagnostics.append(diag.make("NODE_NOT_READ", decl.location, node=key,
                                            path=workspace.relpath(found)))
    elif node is None and plugin is None and decl.ros_version == 1 and (
        found := _program_file(workspace, *key.partition("/")[::2], executable=False)
    ):
        # roslaunch finds the file and refuses it: "Found ... but it is not executable"
        config.diagnostics.append(diag.make("NODE_NOT_EXECUTABLE", decl.location, node=key,
                                            path=workspace.relpath(found)))
    elif node is None and plugin is None and not decl.executable.strip():
        # ``executable="  "`` (Universal_Robots_ROS2_Driver 2477f13's spawner): the package
        # is there, the program named is blank; NODE_NOT_FOUND said it was not in the
        # workspace
        config.diagnostics.append(diag.make("NODE_EXECUTABLE_BLANK", decl.location,
                                            package=decl.package, given=decl.executable))
    elif node is None and plugin is None and (
        gated := _option_gated(workspace, decl.package, decl.executable)
    ) is not None:
        # its package's CMake files make it only with an option given otherwise than its
        # default (cartographer_ros' grpc launch files: ``-DBUILD_GRPC=ON``)
        option, default, where = gated
        config.diagnostics.append(diag.make(
            "NODE_BUILT_BY_OPTION", decl.location, node=key, option=option, default=default,
            cmake=f"{where.file}:{where.line}" if where.file else "its CMake files"))
    elif node is None:
        config.diagnostics.append(diag.make(
            "NODE_NOT_FOUND", decl.location, node=plugin or key,
            hint="" if plugin else _programs_hint(decl, nodes, workspace)))
    if decl.ros_version == 2:
        _illegal_remaps(decl, config)
        _illegal_node_name(decl, config)
    # a ROS 1 node takes ``from:=to`` anywhere on its command line; rcl reads remaps only
    # after ``--ros-args`` (the launch reader has them in ``decl.remaps``): a ROS 2
    # node's plain argument (a spawner's ``--controller-ros-args "-r a:=b"``, meant for
    # the controller it loads) is none. roslaunch puts a ROS 1 node's ``args`` before the
    # ``<remap>`` rules on its command line (node_args.create_local_process_args), and
    # roscpp and rospy keep the last rule of a name: a ``<remap>`` wins over ``args``
    remaps = [*remaps_in_args(decl.args), *decl.remaps] if decl.ros_version == 1 else \
        list(decl.remaps)
    return NodeInstance(decl.name, node, namespace=decl.namespace, remaps=remaps,
                        args=decl.args, conditions=decl.conditions, location=decl.location,
                        ros_version=decl.ros_version, test=decl.is_test,
                        remap_places={f"{a}:={b}": where
                                      for (a, b), where in decl.remap_places.items()})


def _illegal_remaps(decl: NodeDecl, config: Configuration) -> None:
    """ROS 2: the remap rules of ``decl`` whose source or target rcl refuses as a name
    (clearpath_sensors' image_rectify.launch.py gives the rectify node
    ``rectify:=`rectif`y/image``, a backquoted default of its ``output_ns`` argument, and
    the same for three transports): LAUNCH_REMAP_ILLEGAL, once per node, the first rule
    told and the others named."""
    found: list[tuple[str, str, str]] = []
    for source, target in dict.fromkeys(decl.remaps):
        if not source or source.startswith("__"):
            continue  # __node, __ns, __log_level: not names
        for side, name, is_source in (("its source", source, True),
                                      ("its target", target, False)):
            why = ros2_name_problem(name, source=is_source)
            if why is not None:
                found.append((f"{source}:={target}", f"{side} {name!r}", why))
                break
    if not found:
        return
    rule, side, why = found[0]
    others = [other for other, _, _ in found[1:]]
    shown = ", ".join(others[:MAX_RULES_NAMED]) + (
        f" and {len(others) - MAX_RULES_NAMED} more" if len(others) > MAX_RULES_NAMED else "")
    more = f"; so are {len(others)} more of its rules ({shown})" if others else ""
    config.diagnostics.append(diag.make("LAUNCH_REMAP_ILLEGAL", decl.location, rule=rule,
                                        node=decl.name, side=side, why=why, more=more))


MAX_RULES_NAMED = 4  # illegal remap rules of a node named beside the first


def _illegal_node_name(decl: NodeDecl, config: Configuration) -> None:
    """ROS 2: a node name the launch file gives that rmw refuses (letters, digits and
    ``_``, not starting with a digit: rmw_validate_node_name): rcl_node_init fails and
    the process exits (a container refuses the component). LAUNCH_NODE_NAME_REFUSED."""
    own = decl.name.rpartition("/")[2]
    if not decl.name_given or not own or UNKNOWN_MARK in own:
        return
    if not is_ros2_node_name(own):
        config.diagnostics.append(diag.make("LAUNCH_NODE_NAME_REFUSED", decl.location,
                                            name=own))


def _programs_hint(decl: NodeDecl, nodes: Mapping[str, Node], workspace: Workspace) -> str:
    """The rest of NODE_NOT_FOUND's sentence when ``decl``'s package is in the workspace:
    the programs it builds (executables and scripts, the nearest to the name given
    first: one name holding the other, then by edit distance), a launch file's
    executable renamed in CMakeLists.txt and not in the launch file being the usual
    cause; nothing when the package is not here."""
    from ..query.absence import distance, masks

    if decl.package not in workspace.packages:
        return ""
    programs = sorted({node.executable for node in nodes.values()
                       if node.package == decl.package and node.kind in PROGRAM_KINDS
                       and node.executable})
    if not programs:
        return (f"; package {decl.package} is in the workspace, with no program found in "
                "its build files")
    given, pattern = decl.executable, masks(decl.executable)
    # one name holding the other (a suffix added: ``urg_node`` -> ``urg_node_driver``)
    # before the edit distance, which ranks ``getID`` nearer
    programs.sort(key=lambda name: (given not in name and name not in given,
                                    distance(given, name, pattern), name))
    shown = ", ".join(programs[:MAX_PROGRAMS_SHOWN])
    more = len(programs) - MAX_PROGRAMS_SHOWN
    tail = f" and {more} more" if more > 0 else ""
    return f"; package {decl.package} is in the workspace and builds {shown}{tail}"


# the kinds of node a launch file's ``executable=`` / ``type=`` may name
PROGRAM_KINDS = frozenset({"executable", "script"})
MAX_PROGRAMS_SHOWN = 6


def _option_gated(workspace: Workspace, package: str, executable: str
                  ) -> tuple[str, str, Location] | None:
    """The option, its default and where it is declared, when the workspace package
    ``package``'s CMake files make a target ``executable`` only in a branch an option
    keeps from running while it has its default (``cmake.option_gated``)."""
    from ..cmake import option_gated

    found = workspace.packages.get(package)
    if found is None or not executable or UNKNOWN_MARK in executable:
        return None
    return option_gated(found, workspace).get(executable)


def _installed_program(workspace: Workspace, package: str, executable: str) -> str | None:
    """The file the workspace package ``package``'s CMake files install as the program
    ``executable`` and that is no node this tool reads (``cmake.installed_program``)."""
    from ..cmake import installed_program

    found = workspace.packages.get(package)
    if found is None or not executable or UNKNOWN_MARK in executable:
        return None
    return installed_program(found, workspace, executable)


def _program_file(workspace: Workspace, package: str, name: str,
                  executable: bool = True) -> str | None:
    """An executable file ``name`` in ``package``'s folder, as roslaunch finds a node
    type (``rosrun.find_executable``): a shell script in scripts/, a prebuilt program
    (with ``executable=False``, a file of that name without its execute bit too).
    None when there is none, or the name is not a plain file name."""
    root = workspace.find(package)
    if not root or not name or "/" in name or UNKNOWN_MARK in name:
        return None
    return find_executable(root, name, executable)


def external_containers(config: Configuration, launch: LaunchModel) -> None:
    """Components the configuration loads into a container it does not start
    (``LoadComposableNodes(target_container=...)`` of a container that another launch
    file runs: clearpath_sensors' image_proc launch files load into the camera's
    ``image_processing_container``): that container runs elsewhere, with components
    of its own not seen here (the camera driver that publishes the image the loaded
    node subscribes to). Each such container is an unread part of the launch tree
    (``query.absence``: checks that claim an absence do not decide), said once
    (LAUNCH_CONTAINER_EXTERNAL)."""
    started = {decl.name for decl in launch.nodes}
    said: set[str] = set()
    for decl in launch.nodes:
        target = decl.container
        if not decl.composable or not target or UNKNOWN_MARK in target or "$(" in target:
            continue
        full = target if target.startswith("/") else "/" + target
        if full in started or target in started or full in said:
            continue
        said.add(full)
        config.diagnostics.append(diag.make("LAUNCH_CONTAINER_EXTERNAL", decl.location,
                                            container=full))
        if config.launch_tree:
            config.launch_tree[0].add(LaunchItem("include", full, decl.location,
                                                 namespace=decl.namespace,
                                                 detail="container"))


def is_container(decl: NodeDecl) -> bool:
    """A nodelet manager or an rclcpp component container (their plugins do the work)."""
    return decl.package == "nodelet" or (
        decl.package == "rclcpp_components" and decl.executable.startswith("component_container"))


# the loader services a container's own node serves (rclcpp_components' ComponentManager;
# nodelet's Loader in a manager), private to the container's node
# parameters of a numbered family read at most (robot_localization reads until one is unset)
_NUMBERED_LIMIT = 100

_CONTAINER_SERVICES = {
    2: (("~/_container/load_node", "composition_interfaces/srv/LoadNode"),
        ("~/_container/unload_node", "composition_interfaces/srv/UnloadNode"),
        ("~/_container/list_nodes", "composition_interfaces/srv/ListNodes")),
    1: (("~load_nodelet", "nodelet/NodeletLoad"), ("~unload_nodelet", "nodelet/NodeletUnload"),
        ("~list", "nodelet/NodeletList")),
}
# and the parameters it reads there: nodelet's Loader (loader.cpp, advertiseRosApi) reads
# ``num_worker_threads`` (default 0: as many as the machine has cores) on the manager's
# private handle
_CONTAINER_READS = {1: (("~num_worker_threads", "int"),), 2: ()}
_CONTAINERS: dict[tuple[str, str, int], Node] = {}


def container_node(decl: NodeDecl) -> Node | None:
    """The node type of a nodelet manager (``nodelet manager``) or a component container:
    known whole (completeness ``model``), as the services its loader serves and the
    parameters it reads."""
    if decl.package == "nodelet" and decl.args.split()[:1] != ["manager"]:
        return None
    version = 2 if decl.package == "rclcpp_components" else 1
    key = (decl.package, decl.executable, version)
    if key not in _CONTAINERS:
        _CONTAINERS[key] = Node(
            decl.package, decl.executable,
            calls=[*(PrimitiveCall("server", name, type_) for name, type_ in
                     _CONTAINER_SERVICES[version]),
                   *(PrimitiveCall("read", name, type_, has_default=True)
                     for name, type_ in _CONTAINER_READS[version])],
            completeness="model", model="built-in: the loader services of a "
            + ("component container" if version == 2 else "nodelet manager"))
    return _CONTAINERS[key]


def node_key(decl: NodeDecl, nodes: Mapping[str, Node]) -> str:
    """The node type ``pkg/exec`` a declaration starts; for a nodelet, ``pkg/Class`` of
    the package that exports the class. pluginlib finds a nodelet by its lookup name in
    whichever package exports it, and the name's first part need not be that package
    (pcl_ros exports ``pcl/VoxelGrid``): the lookup name's package, else the one
    ``class_packages`` names, else the one package of ``nodes`` that exports it."""
    plugin = nodelet_plugin(decl)
    if plugin is None:
        key = f"{decl.package}/{decl.executable}"
        return key if key in nodes else standalone_nodelet(decl, nodes) or key
    return nodelet_key(plugin, nodes)


def standalone_nodelet(decl: NodeDecl, nodes: Mapping[str, Node]) -> str | None:
    """The node type ``pkg/Class`` of the one nodelet of the declaration's package that a
    command defined outside the workspace was given with the executable's name
    (``Node.aliases`` of a nodelet: jsk_topic_tools' ``jsk_nodelet`` builds a program
    that runs the class alone, as ``nodelet standalone``); None when no one class is."""
    found = [key for key, node in nodes.items() if node.kind == "nodelet"
             and node.package == decl.package and decl.executable in node.aliases]
    return found[0] if len(found) == 1 else None


def nodelet_key(plugin: str, nodes: Mapping[str, Node]) -> str:
    """The node type ``pkg/Class`` of the nodelet of lookup name ``plugin`` (``node_key``)."""
    keys = [f"{package}/{plugin}" for package in class_packages(plugin)]
    found = next((key for key in keys if key in nodes), None)
    if found is None:
        exporting = [key for key, node in nodes.items() if node.kind == "nodelet"
                     and key.endswith("/" + plugin) and "/" not in key[:-len(plugin) - 1]]
        found = exporting[0] if len(exporting) == 1 else None
    if found is None and _bare(plugin):
        return plugin  # no package of the workspace exports it: NODE_NOT_FOUND
    return found or (keys[0] if keys else f"{plugin.partition('/')[0]}/{plugin}")


def in_process_nodelets(instance: NodeInstance, nodes: Mapping[str, Node],
                        models: PluginModels | None) -> list[PrimitiveCall]:
    """The calls of the nodelets ``instance``'s program runs in its own process under its
    own node name (``Node.nodelets``: image_view's wrapper executable), made as its own:
    the nodelet's handles are the node's, with its remaps. Each class is found as a
    launch file's ``nodelet standalone`` finds it (``nodelet_key``), else in the
    interface models; one found nowhere, or partial, leaves the instance partial (its
    own copy of the node model)."""
    node = instance.node
    if node is None or not node.nodelets:
        return []
    calls: list[PrimitiveCall] = []
    owned: set[int] = set()
    for plugin in node.nodelets:
        key = nodelet_key(plugin, nodes)
        # (a plugin class created by its C++ type, exported under another lookup name)
        found = nodes.get(key) or next(
            (n for n in nodes.values() if n.kind in ("plugin", "nodelet")
             and plugin.lstrip(":") in plugin_types(n)), None) or (
            models(key) or models(plugin) if models is not None else None)
        if found is None:
            own_partial(instance, f"runs the class {plugin} in its process (a nodelet or "
                        "plugin), which no package of the workspace nor interface model "
                        "has", owned)
            continue
        if not found.is_complete:
            reasons = found.completeness_reasons[:1] or [found.completeness]
            own_partial(instance, f"nodelet {found.name}: {reasons[0]}", owned)
        elif found.plugin_loads:
            own_partial(instance, f"nodelet {found.name}: loads plugin classes by name "
                        f"({found.plugin_loads[0]})", owned)
        calls.extend(found.calls)
    return calls


def nodelet_plugin(decl: NodeDecl) -> str | None:
    """``pkg/Name`` for ``<node pkg="nodelet" type="nodelet" args="load pkg/Name mgr">``
    (or ``pkg::Class``, a class looked up by its type)."""
    if (decl.package, decl.executable) != ("nodelet", "nodelet"):
        return None
    words = decl.args.split()
    # the lookup name: ``pkg/Name``, or the C++ type of a class its description gives no
    # name (pluginlib then looks it up by its type: ``vesc_ackermann::VescToOdomNodelet``),
    # or any other name a description gives its class: PX4-Avoidance's local_planner
    # exports ``<class name="LocalPlannerNodelet" ...>``, loaded by that one word
    if len(words) >= 2 and words[0] in ("load", "standalone") and (
            "/" in words[1] or "::" in words[1].strip(":") or words[1].isidentifier()):
        return words[1]
    return None


def _bare(plugin: str) -> bool:
    """A lookup name that names no package (``LocalPlannerNodelet``): only a package that
    exports it tells which it is."""
    return not class_packages(plugin)


def link(instance: NodeInstance, call: PrimitiveCall, remaps: Mapping[str, str],
         resources: Resources, config: Configuration, rosname: RosName | None = None
         ) -> Link:
    """Instantiate one primitive call for a node instance: resolve, remap, connect.
    ``rosname`` gives the resolved name when the caller already knows it."""
    if rosname is None:
        rosname = resolved_name(instance, call, remaps, resources)
    resource = resources.get(RESOURCE_OF_KIND[call.kind], rosname.full, instance.name)
    made = LINK_CLASSES[call.kind](
        node=instance, resource=resource, rosname=rosname, type=call.type,
        queue_size=call.queue_size, qos=call.qos, latch=call.latch,
        conditions=(*instance.conditions, *call.conditions), location=call.location,
        origin=call.origin, call=call)
    instance.links.append(made)
    resource.links.append(made)
    config.links.append(made)
    return made


def resolved_name(instance: NodeInstance, call: PrimitiveCall, remaps: Mapping[str, str],
                  resources: Resources) -> RosName:
    """The name a call of ``instance`` resolves to, remapped (not a ROS 2 parameter's:
    rcl's remap rules rename topics and services, and the node's name and namespace,
    never a parameter; lbr_fri_ros2_stack remaps the controller manager's
    ``~/robot_description`` topic, not the parameter of that name it reads)."""
    if call.name_below is not None and call.name.startswith(UNKNOWN_MARK):
        # below the topic of a publisher or subscription the node made, as resolved and
        # remapped (``"<topic>" + "/debug/published_time"``)
        base = resolved_name(instance, replace(call, name=call.name_below, name_below=None),
                             remaps, resources).full
        call = replace(call, name=_filled(call.name, base), name_below=None)
    given = _given_name(call, instance, resources)
    if instance.ros_version == 2 and RESOURCE_OF_KIND[call.kind] is Parameter:
        remaps = {}
        exact = _slashed_parameter(call.name, instance)
        if exact is not None:  # the node's own (``~/...`` as given), not a global name
            return RosName(given, exact, namespace_of(exact))
    namespace = call.handle_namespace
    if namespace and UNKNOWN_MARK in namespace and call.name.startswith(namespace + "/") and (
        given != call.name and given.endswith(call.name[len(namespace):])
    ):
        # the handle's namespace was the ``?`` a parameter's value filled (pointgrey's
        # ``NodeHandle lnh(nh, firstcam)``): the handle's, resolved and remapped first
        call = replace(call, handle_namespace=given[:len(given) - len(call.name) + len(
            namespace)])
    rosname = _handle_name(given, call, instance, remaps) or RosName.make(
        given, instance.namespace, instance.name, remaps)
    if call.searched:
        rosname = _search(rosname, instance, resources, call.handle_namespace)
    return rosname


def _handle_name(given: str, call: PrimitiveCall, instance: NodeInstance,
                 remaps: Mapping[str, str]) -> RosName | None:
    """A ROS 1 name given on a NodeHandle with a namespace: roscpp resolves (and remaps)
    the handle's namespace first, then the name within it, then remaps the result
    (``NodeHandle input("input")`` with ``input:=turtle1`` subscribes ``/turtle1/pose``).
    None when the call has no such namespace."""
    namespace = call.handle_namespace
    if not namespace or instance.ros_version != 1:
        return None
    prefix = namespace if namespace == "~" or namespace.endswith("/") else namespace + "/"
    if not given.startswith(prefix) or len(given) == len(prefix):
        return None
    written = given[len(prefix):]
    if written.startswith(("/", "~")):
        return None
    handle = RosName.make(namespace, instance.namespace, instance.name, remaps).full
    full = remap(resolve(written, handle), remaps)
    return RosName(given, full, namespace_of(full))


def _given_name(call: PrimitiveCall, instance: NodeInstance, resources: Resources) -> str:
    """The call's name; a name taken from a parameter gets this configuration's value.

    The parameter's launch value wins, then the default written in the code; with
    neither, the name keeps its ``?``. ROS 2 parameters belong to their node, so their
    names are resolved as private names.
    """
    if call.name_arg is not None and UNKNOWN_MARK in call.name:
        # a command-line argument's value (``"/" + argv[1] + "/cmd"``); none: the ``?``
        given = program_argument(instance, call.name_arg)
        if given:
            call = replace(call, name=_filled(call.name, given), name_arg=None)
    if call.name_self and UNKNOWN_MARK in call.name:
        # the node's own name (``"get_cost_" + get_name()``): the instance's
        call = replace(call, name=_filled(call.name, instance.name.rstrip("/").rsplit(
            "/", 1)[-1]), name_self=False)
    if call.name_full and call.name.count(UNKNOWN_MARK) == 1:
        # the node's fully qualified name (``"/" + rospy.get_name() + "/x"``): the
        # instance's; rospy's names are canonical (``canonicalize_name``: no ``//``)
        filled = _filled(call.name, instance.name)
        if instance.ros_version == 1:
            filled = ("/" if filled.startswith("/") else "") + "/".join(
                part for part in filled.split("/") if part)
        call = replace(call, name=filled, name_full=False)
    if call.name_option is not None and UNKNOWN_MARK in call.name:
        # an option's value (``"/robot/limb/" + args.limb``), else its default when the
        # arguments are known and do not give it; neither: the ``?``
        given = program_option(instance, call.name_option, call.name_option_default) if (
            call.name_getopt is None) else getopt_option(
                instance, call.name_option, call.name_getopt, call.name_option_default)
        filled = _filled(call.name, given) if given is not None else ""
        if filled.strip("/~"):  # an empty value is no name (a ``?`` alone given "")
            call = replace(call, name=filled, name_option=None)
    if instance.ros_version == 2 and RESOURCE_OF_KIND[call.kind] is Parameter:
        # a parameter named by another one's value (navigation2's route server reads
        # ``<value of graph_file_loader>.plugin``, default ``GeoJsonGraphFileLoader``):
        # that value, a name's piece; none known (or a list's elements): the ``?``
        if call.name_param is not None and call.name_each is None and not call.name_more \
                and call.name.count(UNKNOWN_MARK) == 1 and not call.name_param.startswith(
                    ROS_ARGUMENT):
            value = _parameter_value(call.name_param, _name_default(call, instance),
                                     instance, resources)
            if value and UNKNOWN_MARK not in value and "/" not in value and (
                    value.strip() == value):
                return _node_scoped(_filled(call.name, value))
        return _node_scoped(call.name)
    if call.name_param is None or UNKNOWN_MARK not in call.name:
        return call.name
    value = _parameter_value(call.name_param, _name_default(call, instance), instance,
                             resources, integers=call.name != UNKNOWN_MARK)
    if value is not None and UNKNOWN_MARK in value and call.default_param is not None:
        # the default holds another parameter's value (topic_tools' relay: the input
        # topic and "_relay"); that one's value, or its own default: known only when it is
        # one the code sets from a value it knows, not read recursively any further
        other = _parameter_value(call.default_param, None, instance, resources)
        value = value.replace(UNKNOWN_MARK, other, 1) if other else None
    if call.name_more:  # several parameters, one per ``?`` in order (or several joined
        # in one, JOINED: ``prefix + arm``, known when each is); unknown: ``?``
        values = name_runs(call, value, [_parameter_value(p or "", d, instance, resources)
                                         for p, d, *_ in call.name_more])
        pieces = call.name.split(UNKNOWN_MARK)
        if len(pieces) != len(values) + 1:
            return call.name
        if len(values) > 1:
            return pieces[0] + "".join(
                (UNKNOWN_MARK if v is None else v) + piece for v, piece in zip(
                    values, pieces[1:], strict=True))
        value = values[0]  # one ``?``, its values joined: as one parameter's below
    if value == "" and instance.ros_version == 1 and _empty_piece(call):
        # an empty piece of a longer name (heron's ``"/" + ns + "/activate_control"``,
        # ``~namespace`` set to ""): roscpp and rospy drop the empty segment its slashes
        # leave, ``//activate_control`` is ``/activate_control``
        return clean(_filled(call.name, value))
    if value == "" and _empty_prefix(call):
        # an empty prefix of a segment (ros_kortex's ``m_prefix + m_gripper_name +
        # "_gripper_controller/gripper_cmd"``, both set to ""): the rest of the segment
        return _filled(call.name, value)
    if value == "" and _empty_head(call):
        # an empty value that begins what the code wrote, before ``/`` (aau_multi_robot's
        # map_merger: ``robot_prefix + "/adhoc_communication/send_position"`` on its
        # private handle, ``~robot_prefix`` set to ""): the rest, a global name on any
        # handle
        return call.name.partition(UNKNOWN_MARK)[2]
    if not value:  # none, or empty: no topic is named "" (rosbot's gz bridge guards it)
        return call.name
    if value.startswith("/") and call.name.count(UNKNOWN_MARK) == 1 and (
            call.name.partition(UNKNOWN_MARK)[0] == _handle_prefix(call)):
        # a global value that begins what the code wrote, on a handle with a namespace
        # (OpenMower's ``paramNh.advertise(topic + "/converted")``, ``paramNh`` private):
        # the name is global, not resolved in the handle's namespace
        return value + call.name.partition(UNKNOWN_MARK)[2]
    return _filled(call.name, value)


def _handle_prefix(call: PrimitiveCall) -> str:
    """What the handle's namespace puts before a relative name the code writes: ``~``,
    ``ns/``, or nothing."""
    handle = call.handle_namespace or ""
    return handle if handle in ("", "~") or handle.endswith("/") else handle + "/"


def _empty_piece(call: PrimitiveCall) -> bool:
    """Whether the one ``?`` of a ROS 1 call's name, given "", leaves the name the code
    wrote around it: text written before it and a name after it (``/?/activate_control``,
    ``robot_?/odom``). Not when the ``?`` begins what the code wrote: ``"" + "/scan"`` is a
    global name on any handle, and a ``?`` with nothing after it named the handle itself."""
    if call.name.count(UNKNOWN_MARK) != 1:
        return False
    head, _, tail = call.name.partition(UNKNOWN_MARK)
    prefix = _handle_prefix(call)
    return bool(tail.strip("/")) and head.startswith(prefix) and len(head) > len(prefix)


def _empty_prefix(call: PrimitiveCall) -> bool:
    """Whether the one ``?`` of a call's name, given "", leaves a name: text of the same
    segment follows it (``?_gripper_controller/gripper_cmd``, ``~?_state``); not a ``?``
    followed by ``/`` or by nothing (``"" + "/scan"`` would be global, ``?`` alone no
    name)."""
    if call.name.count(UNKNOWN_MARK) != 1:
        return False
    tail = call.name.partition(UNKNOWN_MARK)[2]
    return bool(tail) and not tail.startswith("/")


def _empty_head(call: PrimitiveCall) -> bool:
    """Whether the one ``?`` of a call's name begins what the code wrote (right after the
    handle's namespace) and is followed by ``/`` and a name: given "", the name is that
    global rest (``"" + "/scan"``)."""
    if call.name.count(UNKNOWN_MARK) != 1:
        return False
    head, _, tail = call.name.partition(UNKNOWN_MARK)
    return head == _handle_prefix(call) and tail.startswith("/") and bool(tail.strip("/"))


def _argument_param(call: PrimitiveCall, instance: NodeInstance) -> PrimitiveCall:
    """``call`` with the one ``?`` of the parameter its name is the value of
    (``name_param``) filled from the command line, where the node reads that parameter by
    a name written the same whose ``?`` is a command-line argument (``name_arg``, one
    index): underwater_vehicle_dynamics' dynamics.py reads
    ``argv[1] + "/dynamics/external_force_topic"`` (``g500/...``) and subscribes to its
    value, the configuration's ``g500/ForceSensor``. Unchanged otherwise."""
    written = call.name_param
    if written is None or written.count(UNKNOWN_MARK) != 1 or instance.node is None:
        return call
    indexes = {c.name_arg for c in instance.node.calls
               if c.kind == "read" and c.name == written and c.name_arg is not None}
    given = program_argument(instance, indexes.pop()) if len(indexes) == 1 else None
    return replace(call, name_param=_filled(written, given)) if given else call


def _filled(name: str, value: str) -> str:
    """``name`` with ``value`` in the place of its (first) ``?``."""
    if value.startswith(("/", "~")) and name.count(UNKNOWN_MARK) == 1 and (
            name in (UNKNOWN_MARK, "~" + UNKNOWN_MARK) or name.endswith("/" + UNKNOWN_MARK)):
        # a global or private name is not resolved in the handle's namespace (the private
        # handle's ``~`` takes no slash: ``~?``)
        return value
    return name.replace(UNKNOWN_MARK, value, 1)


def _name_default(call: PrimitiveCall, instance: NodeInstance) -> str | None:
    """The value the code gives the parameter that names ``call`` when nothing sets it:
    the default the call's own reading wrote (``name_default``), else the one string
    default of the node's declarations of it (nav2's behavior server declares
    ``local_costmap_topic`` with ``local_costmap/costmap_raw``, reads it with
    ``get_parameter(name, value)`` and hands the value to the costmap subscriber, whose
    subscription the name is; a declared parameter nothing overrides holds its
    default). ROS 2 only, and its declarations only: a ROS 1 read without a default
    leaves the variable as it was, whatever another read's default."""
    if call.name_default is not None or call.name_param is None or (
            instance.ros_version != 2 or instance.node is None):
        return call.name_default
    found = [c.default for c in instance.node.calls
             if c.kind == "declare" and c.name == call.name_param and c.has_default
             and c.node_name == call.node_name]
    if not found or not isinstance(found[0], str) or any(d != found[0] for d in found):
        return None
    return found[0]


# ROS 2: the values the launch gives an instance that shares its name with another
# (``_own_values``), by full parameter name
_OWN_VALUES: WeakKeyDictionary[NodeInstance, dict[str, ParamDecl]] = WeakKeyDictionary()


def _own_values(launch: LaunchModel, given: list[ParamDecl]) -> dict[int, dict[str, ParamDecl]]:
    """The parameters the launch gives each node declaration (by its index) whose name
    another declaration has too. launch_ros hands each process its own parameters, so
    two ROS 2 nodes of one name (a duplicate, said as such) each read their own values,
    while the graph keeps one parameter per full name, set to the last one's
    (Nautilus-One's two ``publish_camera`` nodes of ``camera_name`` front and down: both
    were named after the down camera, two false multiple publishers). In ROS 1 two names
    that read alike with ``?`` in them are two names as far as is known (robosub-ros'
    ``$(anon pink_bins_detector)`` of two includes, of ``camera`` front and bottom, both
    ``/pink_bins_detector_?``), each with the parameters of its <node> element; a ROS 2
    name ``/?`` is a node not named yet, whose parameters go by their owner."""
    named = [(index, decl.name) for index, decl in enumerate(launch.nodes)
             if UNKNOWN_MARK not in decl.name or decl.ros_version == 1]
    names = Counter(name for _, name in named)
    shared = {index for index, name in named if names[name] > 1}
    found: dict[int, dict[str, ParamDecl]] = {}
    for param in given:
        if param.owner in shared and param.pattern is None:
            found.setdefault(param.owner, {})[param.name] = param
    return found


def _parameter_value(written: str, default: str | None, instance: NodeInstance,
                     resources: Resources, integers: bool = False) -> str | None:
    """The text value of the instance's parameter ``written`` (as the code names it):
    the launch value, else the one the node sets from its arguments, else ``default``.
    None when a launch file sets it to a value not known (an argument nobody gave): the
    node reads that value, not its default. With ``integers``, an integer value is its
    decimal text, as the code writes it into a longer name (``_element_name``: tauv's
    ``f'vehicle/servos/{self._torpedo_servo}/target_position'``)."""
    if written.startswith(ROS_ARGUMENT):  # ros::getROSArg's ``key:=value`` word
        return ros_argument(instance, written[len(ROS_ARGUMENT):])
    found, value = _set_value(written, instance, resources)
    if found and (isinstance(value, str) or value is None):
        return value
    if found and integers and type(value) is int:
        return str(value)
    # the node sets it itself from its command-line arguments
    return _argument_values(instance).get(_parameter_name(written, instance), default)


def _slashed_parameter(written: str, instance: NodeInstance) -> str | None:
    """The full name of a ROS 2 node's parameter whose name the code writes with a
    leading slash (``declare_parameter("/detector/topic")``, code ported from ROS 1), or
    None for another name. rcl and rclpy keep the name as written: a parameter apart from
    ``detector/topic``, which a launch file's ``{"/detector/topic": v}`` sets
    (``launch.ros2.runner.make_param`` joins node and key with a slash: two), and
    ``{"detector/topic": v}`` does not (moveit2_tutorials' ``/child_frame_id``)."""
    if instance.ros_version != 2 or not written.startswith("/") or UNKNOWN_MARK in written:
        return None
    return f"{instance.name}/{written}"


def _parameter_name(written: str, instance: NodeInstance) -> str:
    """The full name of the instance's parameter ``written`` (as the code names it: a
    list parameter a loop goes over, too)."""
    exact = _slashed_parameter(written, instance)
    if exact is not None:
        return exact
    source = _node_scoped(written) if instance.ros_version == 2 else written
    return RosName.make(source, instance.namespace, instance.name).full


def _made_under(node: Node | None, own: str | None) -> tuple[Condition, ...]:
    """The source conditions under which a process makes one of its nodes but the first:
    those all its calls share (the extractor gives each call of such a node the
    conditions of its construction, ``cpp._made_under``)."""
    if node is None or own is None or len(node.rosnames) < 2 or own in (
            node.rosnames[0], UNKNOWN_MARK):  # ``?``: calls of nodes made apart
        return ()
    calls = node.calls_of(own)
    if not calls:
        return ()
    return tuple(c for c in calls[0].conditions if c.kind == "source"
                 and all(c in other.conditions for other in calls[1:]))


_ARGUMENT_VALUES: WeakKeyDictionary[NodeInstance, dict[str, str]] = WeakKeyDictionary()


def _no_values(name: str) -> object:
    return Unknown(f"{name} is not one of the program's arguments")


def _argument_values(instance: NodeInstance) -> dict[str, str]:
    """The parameters the instance's code sets from its command-line arguments
    (``PrimitiveCall.program_arg``: topic_tools' relay takes ``input_topic`` from its
    first), by full name, with the arguments the launch file gives it; a write under a
    condition (``if (args.size() >= 2)``, over the arguments) counts where the
    argument is there."""
    found = _ARGUMENT_VALUES.get(instance)
    if found is not None:
        return found
    found = {}
    views = program_views(instance)
    # the writes that may happen with these arguments: those under a condition over the
    # arguments that they decide false are left out (throttle's "messages" mode takes
    # output_topic from its fourth argument, its "bytes" mode from its fifth)
    writes = [] if instance.node is None else [
        c for c in instance.node.calls if c.kind == "write" and c.program_arg is not None
        and not any(decide(k, _no_values, views) is False for k in c.conditions)]
    if writes:
        positions: dict[str, set[int]] = {}
        for write in writes:
            assert write.program_arg is not None
            if UNKNOWN_MARK not in write.name:
                name = _node_scoped(write.name) if instance.ros_version == 2 else write.name
                full = _slashed_parameter(write.name, instance) or RosName.make(
                    name, instance.namespace, instance.name).full
                positions.setdefault(full, set()).add(write.program_arg)
        # one argument per parameter: writes from different ones depend on conditions
        # over the arguments not read here (throttle's "messages" against "bytes")
        found = {full: value for full, (at, *others) in positions.items()
                 if not others and (value := program_argument(instance, at)) is not None}
    _ARGUMENT_VALUES[instance] = found
    return found


def element_calls(call: PrimitiveCall, instance: NodeInstance, resources: Resources
                  ) -> list[PrimitiveCall]:
    """A call named by each element of a list parameter (``name_each``): one call per
    element of the value the launch file gives the parameter, named by the element's
    field (``.``: the element itself; in ROS 2 the elements may be the parameters
    ``name.<key>.<field>``), none for an empty list (unless the launch file sets it
    under a condition); without such a value, the call as it is (its name keeps its
    ``?``)."""
    members = _member_calls(call, instance, resources)
    if members is not None:
        return members
    if _per_kept_plugin(call):
        return _kept_calls(call, instance)
    if call.name_each is None or call.name_param is None:
        return _element_turns(call, instance, resources)
    full = _parameter_name(call.name_param, instance)
    if call.name_each == NUMBERED:
        return _numbered_calls(call, full, resources)
    param = resources.by_name.get((Parameter, full))
    value = param.value if isinstance(param, Parameter) and param.set_by_launch else None
    if call.name_each == WORDS:
        return _word_calls(call, instance, param, value)
    if call.name_each.startswith(COUNTED):
        return _counted_calls(call, instance, param, value)
    elements = _list_elements(call, instance, resources, full)
    if elements is None:
        return [call]
    if not elements and not (isinstance(param, Parameter) and param.launch_conditions):
        # an empty list, given unconditionally or the code's default: the loop over it
        # makes nothing (warthog's twist_mux ``<rosparam param="locks">[]</rosparam>``)
        return []
    # the element is the whole name, or its one unknown run (``polygon_name + ".type"``);
    # a global element is not resolved in the handle's namespace (PX4-Avoidance's global
    # planner subscribes each of ``~pointcloud_topics``, ``[/camera/depth/points]``, on
    # its private handle: ``/camera/depth/points``)
    written = call.name if call.name.count(UNKNOWN_MARK) == 1 else UNKNOWN_MARK
    named = [(name, item) for name, item in (
        (_element_name(item, call.name_each, written != UNKNOWN_MARK), item)
        for item in elements) if name is not None]
    if not named:
        return [call]
    # the loop over the list that the extractor saw is what these calls stand for
    kept = tuple(c for c in call.conditions if c.statement != EACH_STATEMENT)
    return [replace(call, name=_filled(written, name), name_param=None,
                    name_default=None, name_each=None,
                    loads_given=name if call.loads is not None else None,
                    conditions=_element_conditions(kept, call.name_param, item))
            for name, item in named]


def _per_kept_plugin(call: PrimitiveCall) -> bool:
    """Whether ``call`` is named by each plugin object a loop of the host's code walks
    where it keeps them (``LOADED``), not by a parameter."""
    return call.name_param is None and (call.name_each or "").startswith(LOADED)


def _kept_calls(call: PrimitiveCall, instance: NodeInstance) -> list[PrimitiveCall]:
    """A call named by each plugin object a loop of the host's code walks where it keeps
    them (``LOADED``): one per plugin the host row's slot kept there loads
    (``NodeInstance.kept``, ``hosts.Slot.kept``), named by the name it was given, under
    the conditions that chose it; none when it loads none; the call as it is (its name
    keeps its ``?``) where the instance keeps no such slot, or beside the others where
    a parameter not seen may choose more plugins."""
    container, method, *cast = (call.name_each or "")[len(LOADED):].split(" ")
    kept = instance.kept.get((container, method))
    if kept is None or call.name.count(UNKNOWN_MARK) != 1:
        return [call]
    whole, plugins = kept
    conditions = tuple(c for c in call.conditions if c.statement != EACH_STATEMENT)
    made: list[PrimitiveCall] = []
    for name, chosen, bases in plugins:
        # the loop tests the object's class (``dynamic_pointer_cast<C>(layer)``): a
        # plugin whose bases are known makes the call only if C is one of them; where
        # they are not, the call is made under that test, undecided
        test = cast[0] if cast else None
        plain = test.rsplit("::", 1)[-1] if test else None
        if plain is not None and bases is not None and plain not in bases:
            continue
        undecided = (Condition(f"{name} is a {test}", location=call.location),) if (
            test is not None and bases is None) else ()
        made.append(replace(call, name=_filled(call.name, name), name_each=None,
                            conditions=conditions + chosen + undecided))
    return made if whole else [*made, call]


def _counted_calls(call: PrimitiveCall, instance: NodeInstance, param: Resource | None,
                   value: Any) -> list[PrimitiveCall]:
    """A call made in each turn of a counting loop up to an integer parameter's value,
    or a list parameter's length (``range(len(p))``) (``COUNTED``): one per turn, its
    ``?`` the turn's number, when the launch files give the parameter a value
    unconditionally (ego-planner's ``fsm/waypoint_num`` 4:
    ``~fsm/waypoint0_x`` to ``~fsm/waypoint3_x``) or, when nothing sets it, of the one
    integer default the node's code reads it with (mavros_controllers' trajectory_publisher
    ``nh_private_.param<int>("number_of_primitives", num_primitives_, 7)``: seven turns);
    none for a count that makes no turn; the call as it is otherwise (its name keeps its
    ``?``)."""
    if value is None and not (isinstance(param, Parameter) and param.is_set):
        # (a loop up to a list's length, ``range(len(p))``: the list default's length)
        value = _code_default(call, instance, list if counts_length(call.name_each or "")
                              else int)
        param = None  # a default: no launch conditions
    turns = counted_turns(call.name_each or "", value, _NUMBERED_LIMIT) if (
        (param is None or (isinstance(param, Parameter) and not param.launch_conditions))
        and call.name.count(UNKNOWN_MARK) == 1) else None
    if turns is None:
        return [call]
    kept = tuple(c for c in call.conditions if c.statement != EACH_STATEMENT)
    return [replace(call, name=_filled(call.name, str(turn)), name_param=None,
                    name_default=None, name_each=None, conditions=kept) for turn in turns]


def _member_calls(call: PrimitiveCall, instance: NodeInstance, resources: Resources
                  ) -> list[PrimitiveCall] | None:
    """A read of each member of a ROS 1 struct parameter the code walks and hands on
    (``PrimitiveCall.struct_member``: ``~rigid_bodies/?/child_frame_id``): one read per
    member the launch files set under the struct (``~rigid_bodies/1/child_frame_id``,
    ``~rigid_bodies/2/child_frame_id``), as ``element_calls`` names a list's elements;
    none when they set it to an empty dictionary unconditionally (the loop runs no
    turn). None where no member is known (the read keeps its ``?``)."""
    if not call.struct_member or call.name.count(UNKNOWN_MARK) != 1:
        return None
    head, mark, rest = call.name.partition("/" + UNKNOWN_MARK)
    if not mark or not head or head == "~" or (rest and not rest.startswith("/")):
        return None
    full = _parameter_name(head, instance).rstrip("/")
    param = resources.by_name.get((Parameter, full))
    value = param.value if isinstance(param, Parameter) and param.set_by_launch else None
    if value is not None:
        if not isinstance(value, dict):
            return None
        keys = [str(key) for key in value]
    else:
        keys = list(dict.fromkeys(
            name[len(full) + 1:].split("/", 1)[0] for (cls, name), found
            in resources.by_name.items() if cls is Parameter and name.startswith(full + "/")
            and isinstance(found, Parameter) and found.set_by_launch))
        if not keys:
            return None
    if not keys and isinstance(param, Parameter) and param.launch_conditions:
        return [call]  # empty only where the launch file's condition holds
    return [replace(call, name=f"{head}/{key}{rest}") for key in keys
            if key and "/" not in key and UNKNOWN_MARK not in key]


def _list_elements(call: PrimitiveCall, instance: NodeInstance, resources: Resources,
                   full: str) -> list[Any] | None:
    """The elements of the list parameter ``full`` in this configuration: the launch
    files' value, the ROS 2 parameters under its prefix (ROS 1: a dictionary's leaves),
    else the node's code default; None when none is known, and when the launch files set
    it to a value not known here (an argument nobody gave: the node reads that, not its
    default)."""
    param = resources.by_name.get((Parameter, full))
    value = param.value if isinstance(param, Parameter) and param.set_by_launch else None
    if value is None and isinstance(param, Parameter) and param.set_by_launch:
        return None
    if value is None:
        value = _dotted_groups(full, resources, "." if instance.ros_version == 2 else "/")
    if value is None and call.name_param is not None and _parameter_name(
            call.name_param, instance) == full:
        value = _code_default(call, instance, list)
    elements = list(value.values()) if isinstance(value, dict) else value
    return elements if isinstance(elements, list) else None


def _element_conditions(conditions: tuple[Condition, ...], listed: str | None, item: Any
                        ) -> tuple[Condition, ...]:
    """``conditions`` for the turn of the loop over the list parameter ``listed`` that
    handles ``item``: a name a condition uses for that element, or a field of it
    (``Condition.elements``), is given its value, as a constant the graph decides it
    with (``graph.conditions.decide``)."""
    out = []
    for condition in conditions:
        values = [(name, value) for name, lst, field in condition.elements or ()
                  if lst == listed and not field.startswith(ELEMENT_PARAMETER)
                  and (value := _element_value(item, field)) is not None]
        # a name holding the parameter the element names (``polygon_name + ".type"``):
        # that parameter, which the graph decides the condition by as any it holds
        held = [(name, field[len(ELEMENT_PARAMETER):].replace(UNKNOWN_MARK, item, 1))
                for name, lst, field in condition.elements or ()
                if lst == listed and field.startswith(ELEMENT_PARAMETER)
                and isinstance(item, str) and item]
        if not values and not held:
            out.append(condition)
            continue
        out.append(replace(
            condition, constants=(*(condition.constants or ()), *values) or None,
            parameters=(*(condition.parameters or ()), *held) or None,
            elements=tuple(e for e in condition.elements or () if e[1] != listed) or None))
    return tuple(out)


def _element_turns(call: PrimitiveCall, instance: NodeInstance, resources: Resources
                   ) -> list[PrimitiveCall]:
    """A call whose name is known, under a condition over each element of a list
    parameter in turn (costmap_2d copies ``~map_topic`` for each plugin ``if
    (plugin_type == "costmap_2d::StaticLayer")``): one call per element the list is
    known to hold, each under its turn's conditions (the same ones once); as it is when
    the conditions name several lists or the list's value is not known."""
    lists = {lst for c in call.conditions for _, lst, _ in c.elements or ()}
    if len(lists) != 1:
        return [call]
    listed = lists.pop()
    full = _parameter_name(listed, instance)
    elements = _list_elements(call, instance, resources, full)
    if elements is None:
        return [call]
    param = resources.by_name.get((Parameter, full))
    if not elements and isinstance(param, Parameter) and param.launch_conditions:
        return [call]  # empty only where the launch file's condition holds
    turns: dict[tuple[Condition, ...], PrimitiveCall] = {}
    for item in elements[:_NUMBERED_LIMIT]:
        conditions = _element_conditions(call.conditions, listed, item)
        turns.setdefault(conditions, replace(call, conditions=conditions))
    return list(turns.values())


def _element_value(item: Any, field: str) -> str | int | float | bool | None:
    """The value of ``item``'s ``field`` (``.``: the item itself), when it is a plain
    value."""
    value = item if field == "." else item.get(field) if isinstance(item, dict) else None
    return value if isinstance(value, str | int | float | bool) else None


def _word_calls(call: PrimitiveCall, instance: NodeInstance, param: Any, value: Any
                ) -> list[PrimitiveCall]:
    """A call named by each word of a string parameter (``WORDS``): one per word of the
    value the launch file gives it, else, when nothing sets it, of the one string default
    the node's code reads it with (none for an empty one: the loop over its words runs
    no turn); without either, the call as it is."""
    if value is None and isinstance(param, Parameter) and param.is_set:
        return [call]  # set to a value not known here, or under a condition
    if value is None:
        value = _code_default(call, instance, str)
        param = None  # a default: no launch conditions
    if not isinstance(value, str):
        return [call]
    words = value.split()[:_NUMBERED_LIMIT]
    if not words and isinstance(param, Parameter) and param.launch_conditions:
        return [call]  # empty only where the launch file's condition holds
    kept = tuple(c for c in call.conditions if c.statement != EACH_STATEMENT)
    written = call.name if call.name.count(UNKNOWN_MARK) == 1 else UNKNOWN_MARK
    return [replace(call, name=_filled(written, word), name_param=None,
                    name_default=None, name_each=None, conditions=kept) for word in words]


def _code_default(call: PrimitiveCall, instance: NodeInstance, kind: type) -> Any:
    """The value of ``kind`` a node's code gives the parameter that names ``call`` when
    nothing sets it: the one default of its declarations and reads with a known default
    of that kind (a list: ``declare_parameter("wheels", std::vector<std::string>{"left",
    "right"})``, ``declare_parameter('robots', ['r1'])``; a string whose words name the
    calls: costmap_2d's ``observation_sources``, ``""``); None when there is none or they
    disagree."""
    if instance.node is None:
        return None
    found = [c.default for c in instance.node.calls
             if c.kind in ("declare", "read") and c.name == call.name_param and c.has_default
             and isinstance(c.default, kind) and c.node_name == call.node_name]
    return found[0] if found and all(d == found[0] for d in found) else None


def _name_param_unset(instance: NodeInstance, call: PrimitiveCall,
                      resources: Resources) -> Diagnostic:
    """Why a name taken from a parameter stays unknown: the configuration sets none (of
    a name of several parameters, those it does not set)."""
    param = call.name_param
    named = [(param or "", _name_default(call, instance)), *((p or "", d) for p, d, *_ in (
        call.name_more or []))]
    values = [(p, _parameter_value(p, d, instance, resources)) for p, d in named]
    unset = [p for p, v in values if v is None]
    empty = [p for p, v in values if v == ""]
    why = "which the configuration does not set"
    if call.name_each is None and not unset and empty:
        # set to "": what the code makes of it is no name the graph resolves here
        pieces = call.name.split(UNKNOWN_MARK)
        shown = pieces[0] + "".join(
            (UNKNOWN_MARK if v is None else v) + piece
            for (_, v), piece in zip(values, pieces[1:], strict=False))
        why = ("which the configuration sets to the empty string, leaving "
               f"{shown!r} (an empty name, segment or last segment is not resolved here)")
        unset = empty
    elif unset and all(_set_not_known(p, instance, resources) for p in unset):
        why = "which the configuration sets to a value not known statically"
    elif unset and all(_set_not_text(p, instance, resources) for p in unset):
        # (a float, a bool: each language writes them its own way; an integer that would
        # be the whole name, no legal one)
        why = ("which the configuration sets to a value that is not text, not written "
               "into a name here")
    if len(named) > 1 and unset:
        param = ", ".join(unset)
    each = call.name_each or ""
    counter = ("" if not each.startswith(COUNTED)
               else f"counter of the loop over the elements of the list parameter {param}"
               if counts_length(each) else f"counter of the loop up to the parameter {param}")
    what = {None: f"parameter{'s' if len(unset) > 1 else ''} {param}",
            NUMBERED: f"parameters {param}0, {param}1, ...",
            WORDS: f"words of the parameter {param}"
            }.get(call.name_each, counter or f"elements of the list parameter {param}")
    return diag.make("NAME_PARAM_UNSET", call.location, node=instance.name,
                     kind=call.kind, what=what, why=why)


def _set_value(written: str, instance: NodeInstance, resources: Resources
               ) -> tuple[bool, Any]:
    """Whether a launch file (or the node itself, from its arguments) sets the
    instance's parameter ``written``, and to what (None or ``Unknown``: a value not
    known statically, an argument nobody gave)."""
    if written.startswith(ROS_ARGUMENT):
        return False, None
    param_name = _parameter_name(written, instance)
    own = _OWN_VALUES.get(instance, {}).get(param_name)
    if own is not None:  # its own, not another node's of the same name
        return True, own.value
    param = resources.by_name.get((Parameter, param_name))
    if isinstance(param, Parameter) and param.set_by_launch:
        return True, param.value
    return False, None


def _set_not_known(written: str, instance: NodeInstance, resources: Resources) -> bool:
    """Whether a launch file sets the instance's parameter ``written`` to a value not
    known statically (an argument nobody gave): set, though its value is not known."""
    found, value = _set_value(written, instance, resources)
    return found and (value is None or isinstance(value, Unknown))


def _set_not_text(written: str, instance: NodeInstance, resources: Resources) -> bool:
    """Whether a launch file sets the instance's parameter ``written`` to a known value
    that the graph does not write into a name (a float, a bool, a list of them)."""
    found, value = _set_value(written, instance, resources)
    return found and value is not None and not isinstance(value, str | Unknown)


def _name_arg_unset(instance: NodeInstance, call: PrimitiveCall) -> Diagnostic:
    """Why a name taken from a command-line argument stays unknown."""
    index = call.name_arg or 0
    which = f"argv[{index}]" if index > 0 else f"argv[argc - {-index}]"
    if program_views(instance) is None:
        why = f"and its args ({instance.args!r}) are not known statically"
    elif instance.ros_version == 1 and index > 0 and any(
            ":=" in word for word in instance.args.split()):
        why = "which differs before and after ros::init takes the ':=' words of its args"
    else:
        why = f"which its args ({instance.args!r}) do not give"
    return diag.make("NAME_ARG_UNSET", call.location, node=instance.name, kind=call.kind,
                     which=which, why=why)


def _numbered_calls(call: PrimitiveCall, full: str, resources: Resources
                    ) -> list[PrimitiveCall]:
    """One call per parameter ``<full>0``, ``<full>1``, ... that the configuration sets
    to a name, up to the first one it does not set (robot_localization's ``imu0``);
    none set: the call as it is."""
    names: list[str] = []
    while len(names) < _NUMBERED_LIMIT:
        param = resources.by_name.get((Parameter, f"{full}{len(names)}"))
        if not (isinstance(param, Parameter) and param.set_by_launch
                and isinstance(param.value, str) and param.value):
            break
        names.append(param.value)
    if not names:
        return [call]
    written = call.name if UNKNOWN_MARK in call.name else UNKNOWN_MARK
    return [replace(call, name=_filled(written, name), name_param=None,
                    name_default=None, name_each=None) for name in names]


def _dotted_groups(full: str, resources: Resources, separator: str = "."
                   ) -> dict[str, dict[str, Any]] | None:
    """ROS 2 parameters under a prefix, by their next segment (``topics.nav.topic`` and
    ``topics.nav.priority`` give ``{"nav": {"topic": ..., "priority": ...}}``), as
    ``list_parameters({prefix})`` lists them; None when the launch file sets none. ROS 1
    (``separator`` ``/``): a dictionary a launch file's ``rosparam`` sets is its leaves
    (``/mux/inputs/a/topic``) until a node reads it whole."""
    groups: dict[str, dict[str, Any]] = {}
    for (cls, name), found in resources.by_name.items():
        if cls is Parameter and name.startswith(full + separator) and isinstance(
                found, Parameter) and found.set_by_launch:
            key, _, field = name[len(full) + 1:].partition(separator)
            if key and field and separator not in field:
                groups.setdefault(key, {})[field] = found.value
    return groups or None


def _element_name(item: Any, field: str, part: bool) -> str | None:
    """The text an element (or its ``field``) puts in a name: a string; an integer in
    decimal when it is a part of the name (``part``), as Python's ``str`` / f-string /
    ``%d`` and C++'s ``std::to_string`` write it (tauv's thruster manager publishes
    ``f'vehicle/thrusters/{thruster_id}/target_thrust'`` for each of ``~thruster_ids``,
    ``[0, 1, ...]``); None for anything else (a float or a bool is written differently
    by each language; an integer alone is no legal name)."""
    value = item if field in (".", WORDS) else item.get(field) if isinstance(
        item, dict) else None
    if isinstance(value, str):
        return value
    return str(value) if part and type(value) is int else None


def _search(name: RosName, instance: NodeInstance, resources: Resources,
            handle: str | None = None) -> RosName:
    """searchParam: the closest set parameter from the node's namespace up to the root,
    else the name in the node's own namespace; a private key (``~x``) from the node's
    own name up, else its private name. A ROS 1 key given on a handle with a
    namespace (``handle``) is searched for from that handle's namespace, as roscpp's
    ``NodeHandle::searchParam`` does (gazebo_ros_control's ``model_nh_`` in
    ``<robotNamespace>``)."""
    if name.is_unresolved:
        return name
    key = name.given.lstrip("~/")
    namespace = instance.namespace.rstrip("/")
    prefix = (handle or "").rstrip("/") + "/"
    if (handle and handle != "~" and instance.ros_version == 1
            and name.given.startswith(prefix) and not name.given[len(prefix):].startswith(
                ("/", "~")) and name.full.endswith("/" + name.given[len(prefix):])):
        key = name.given[len(prefix):]
        namespace = name.full[:-len(key) - 1]
    elif name.is_global:
        return name
    elif name.given.startswith("~"):
        # a private key (NodeHandle("~").searchParam, ros::param::search(key, ..),
        # rospy.search_param): the master searches from the node's own name up, its
        # private namespace first (rosmaster's ParamDictionary.search_param)
        namespace = instance.name.rstrip("/")
    levels = []
    while True:
        levels.append(f"{namespace}/{key}")
        if not namespace:
            break
        namespace = namespace.rsplit("/", 1)[0]
    for full in levels:
        found = resources.by_name.get((Parameter, full))
        if isinstance(found, Parameter) and found.is_set:
            return RosName(name.given, full, namespace_of(full))
    return name


def _node_scoped(name: str) -> str:
    return "~/" + name.lstrip("~/")
