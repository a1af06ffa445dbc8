"""Give host node instances the calls of the plugins their parameters name.

For every node instance a launch file starts as a host of ``hosts.HOSTS``, each slot's
parameters (values from launch files and parameter files, as the configuration's
``Parameter`` objects hold them) say which plugin names it loads and which class each
one is. The class is looked up among the workspace's plugin nodes (pluginlib lookup name
or C++ type). Its calls then go

- to the host instance, with the plugin name put where the plugin's code builds names
  from it (``placement="name"``: an unknown first part ``?`` of a name, as in
  ``name + ".tolerance"`` or ``NodeHandle("~/" + name)``, is the plugin name), under the
  conditions of the parameters that chose it; or
- to a node instance of its own (``placement="node"``: a ros2_control controller is a
  lifecycle node named by the controller, in the manager's namespace), made here, with
  the parameters of the spawner's ``--param-file`` and the remaps of its
  ``--controller-ros-args``.

A class whose package has no source in the workspace is looked up in the interface
models (``models``: the plugin nodes of the package's model, ``haros_arch.models``), as a
host without source takes its model. A plugin whose class is not known, or found neither
in the workspace nor in a model, is a diagnostic at the parameter that names it, and the
host instance becomes partial (a modelled one too): it gets its own copy of its node
model (node models are shared by instances) marked partial with the reason.
"""

from __future__ import annotations

import copy
import fnmatch
import functools
import os
import re
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any, Protocol
from weakref import WeakKeyDictionary

import yaml

from .. import diagnostics as diag
from .. import safe_yaml
from ..files import read_text
from ..launch.model import NodeDecl, shell_words
from ..launch.ros1.params import flatten as ros1_flatten
from ..launch.ros2.naming import (
    flatten,
    for_every_node,
    node_patterns,
    params_for_node,
    parse_ros_args,
    pattern_matches,
)
from ..model.conditions import EACH_STATEMENT, Condition
from ..model.location import Location
from ..model.rosname import namespace_of, pattern_for, resolve
from ..model.runtime import Configuration, NodeInstance, Parameter, Resource
from ..model.source import (
    PLUGINLIB_CLASS,
    Node,
    Package,
    PrimitiveCall,
    class_load_base,
    is_class_load,
)
from ..model.values import UNKNOWN_MARK
from ..models.commands import cli_load
from ..share import file_setting, share_source
from ..workspace import Workspace
from . import behavior_trees
from .classes import _untemplated, registered_class, with_headers
from .hosts import (
    CHAINS,
    DESCRIBED,
    EXPORTED,
    EXTENDS,
    KEYED,
    LOOKUP_PACKAGES,
    PLUGIN_SLOTS,
    RUNS_AS,
    SPAWNER,
    Child,
    Host,
    RunsAs,
    Slot,
    Sources,
    host_of,
    sources_of,
    tree_host_of,
)
from .inherit import HEADER_DEPTH, base_argument, chain, direct_bases

SPAWNERS = (("controller_manager", "spawner"), ("controller_manager", "spawner.py"))
ROS1_SPAWNERS = (("controller_manager", "spawner"), ("controller_manager", "controller_manager"))
MANAGER_NAME = "controller_manager"
MANAGER_NODE = ("controller_manager", "ros2_control_node")  # the manager's own executable
MANAGER_SERVICE = "controller_manager_msgs/srv/LoadController"
_ROS_ARG_FLAGS = ("-r", "--remap", "-p", "--param", "--params-file")
MAX_PLUGINS = 200  # per slot: a hostile list stays bounded
MAX_PARAM_VALUES = 100_000  # values in one spawner parameter file, aliases counted out


# a plugin class (lookup name or C++ type) to its node in an interface model, if any
PluginModels = Callable[[str], Node | None]


# ROS 2: the process each node instance runs in, as the launch declaration that starts
# it and the instance made of it (``graph.build`` gives the launched ones; a node a
# host's code makes, a controller it loads, is in the host's): where a library's own node
# of that process (``PrimitiveCall.handle_origin`` ``process``) takes its namespace and
# remaps
PROCESSES: WeakKeyDictionary[NodeInstance, tuple[NodeDecl, NodeInstance]] = (
    WeakKeyDictionary())


def _add_hosted(instance: NodeInstance, host: NodeInstance, config: Configuration) -> None:
    """Add a node instance its host makes (a controller, a plugin's own node) to the
    configuration: its id, another of its name counted, and its host's process."""
    taken = sum(1 for n in config.nodes if n.name == instance.name)
    instance.id = f"node:{instance.name}" + (f"#{taken + 1}" if taken else "")
    config.nodes.append(instance)
    if host in PROCESSES:
        PROCESSES[instance] = PROCESSES[host]


class Params(Protocol):
    """The configuration's parameters by name (``graph.build.Resources`` is one)."""

    by_name: dict[tuple[type[Resource], str], Resource]

    def get(self, cls: type[Resource], name: str) -> Resource: ...


@dataclass(frozen=True)
class Choice:
    """One plugin a host loads: its name, class, and why (the parameters that say so,
    by full name: the host, or the plugin's own node, reads them to load it)."""

    name: str
    cls: str | None
    location: Location
    conditions: tuple[Condition, ...] = ()
    reads: tuple[str, ...] = ()
    remaps: tuple[tuple[str, str], ...] = ()  # a spawner's --controller-ros-args
    node: Node | None = None  # the class's node when the choice was made from it
    # the host's namespace (relative to it) its code moves this plugin's parameters from
    # before loading it (a pre-Hydro costmap's ``observation_sources`` and sources)
    moved_from: str | None = None
    # why the class is not known where no parameter names it (the robot description a
    # controller manager reads: HARDWARE_UNKNOWN)
    why: str | None = None
    # the host's namespace (relative to its private one) the plugin's private names
    # move to (``Slot.rebase``)
    moved_to: str | None = None


def attach(config: Configuration, started: Sequence[tuple[NodeDecl, NodeInstance]],
           nodes: Mapping[str, Node], params: Params, workspace: Workspace,
           models: PluginModels | None = None,
           hardware: Mapping[int, list[Choice]] | None = None,
           ) -> list[tuple[NodeInstance, list[PrimitiveCall]]]:
    """The plugin calls each host instance (or a plugin's own instance) makes; plugin
    instances are added to ``config.nodes``, problems to ``config.diagnostics``;
    ``models`` finds the classes of packages without source; ``hardware`` the hardware
    plugins of each controller manager, by ``id`` of its instance (``robot.attach``)."""
    index = plugin_index(nodes)
    owned: set[int] = set()  # instances that have their own copy of their node model
    made: dict[int, set[tuple[Any, ...]]] = {}  # per host instance: calls it has
    loaded: set[tuple[int, str]] = set()  # (instance, parameter) read to load a plugin
    out: list[tuple[NodeInstance, list[PrimitiveCall]]] = []
    hosted: set[tuple[object, ...]] = set()  # launch nodes whose process hosts already
    served: set[int] = set()  # spawner declarations whose manager is a host here
    for decl, started_instance in started:
        top = host_of(decl.package, decl.executable, decl.ros_version) or _manager_host(
            started_instance)
        if top is None:
            if tree_host_of(decl.package, decl.executable, decl.ros_version) is None:
                # (a tree host registers its tree nodes' libraries by name: the trees
                # read make their calls, ``behavior_trees.attach`` says what is not read)
                _unhosted(started_instance, owned)
            continue
        process = (decl.package, decl.executable, decl.namespace, decl.location)
        if process in hosted:
            # a process of several nodes (mavros_node makes mavros, mavros_router and
            # mavros_node, each an instance of the one launch node): its plugins are
            # loaded once, by the first it makes
            continue
        hosted.add(process)
        hosts = [(top, started_instance)]
        for child in top.children:
            own, node = _child_instance(decl, started_instance, child, nodes, models,
                                        params, config)
            out.append((own, [_constructed(c, child.name) for c in node.calls] if node
                           else []))
            inner = host_of(child.package, child.executable, decl.ros_version)
            if inner is not None:
                hosts.append((inner, own))
        for host, instance in hosts:
            instance.hosted = True
            for slot in host.slots:
                if slot.since is not None and instance.node is not None and \
                        _older(_version(instance.node, workspace), slot.since):
                    continue  # a release that does not load them
                unseen: str | None = None
                if slot.names == SPAWNER:
                    choices = list(_spawned(instance, started, params, workspace, config,
                                            unnamed=decl.name_guessed, served=served))
                elif slot.names == EXPORTED:
                    choices = list(_exported(instance, slot, params, nodes, models,
                                             workspace, decl.package))
                    # an installed host of every class it finds offers its own
                    # interface as it offers theirs (ROS 1 mavros' raw MAVLink bridge,
                    # ``mavlink/to`` and ``mavlink/from``): its model's links
                    instance.offered = instance.offered or (
                        instance.node is not None and instance.node.model is not None)
                    # a deny or allow list not set as far as we see, which a parameter
                    # file not known statically may set (mavros' own
                    # px4_pluginlists.yaml where mavros is not installed here and its
                    # model holds no launch files)
                    for key in slot.lists or ():
                        unseen = unseen or _may_be_set(
                            instance.name.rstrip("/") + "/" + key, params,
                            "chooses the plugins it loads")
                elif slot.names == DESCRIBED:
                    choices = list((hardware or {}).get(id(instance), ()))
                elif slot.names == KEYED:
                    choices = list(_keyed(instance, slot, params))
                else:
                    choices = list(_chosen(instance, slot, params))
                    unseen = _unseen_choice(instance, slot, params)
                if unseen is not None:
                    own_partial(instance, unseen, owned)
                if slot.kept is not None:
                    # the plugin objects the host's code keeps (``Slot.kept``): all of
                    # them known unless a parameter not seen may choose others
                    instance.kept[slot.kept] = (unseen is None, [
                        (slot.prefix + _given(choice, slot), choice.conditions,
                         _class_chain(_lookup(choice, index, workspace, models), workspace))
                        for choice in choices])
                for choice in choices:
                    out.extend(_load(choice, slot, instance, index, workspace, models,
                                     params, config, owned, made, loaded, decl,
                                     frozenset(s.site for s in host.slots if s.site)))
    out.extend(ros1_controllers(config, started, index, params, workspace, models, owned))
    out.extend(unmanaged_controllers(config, started, served, index, params, workspace,
                                     models, owned))
    out.extend(behavior_trees.attach(config, started, params, workspace,
                                     lambda instance, reason: own_partial(
                                         instance, reason, owned, first=True),
                                     getattr(models, "package", None)))
    return out


def _class_chain(node: Node | None, workspace: Workspace) -> tuple[str, ...] | None:
    """A plugin node's class and its base classes, most derived first, plain names, as
    the declarations in its sources give them (``inherit.chain``); None when not known
    (no node, no source of it here, no base class found: a plugin class has one)."""
    if node is None or not node.plugin_class or not node.sources:
        return None
    own = registered_class(node.plugin_class, node.sources, workspace)
    found = chain(own, list(node.sources), workspace)
    return tuple(found) if len(found) > 1 else None


def _manager_host(instance: NodeInstance) -> Host | None:
    """ros2_control's host row for a ROS 2 node of the workspace whose code makes the
    controller manager itself (KUKA's control_node, as ros2_control_node does): its model
    serves ``~load_controller`` as the manager's constructor does (the C++ API row)."""
    node = instance.node
    if instance.ros_version != 2 or node is None or not any(
            call.kind == "server" and call.name == "~load_controller"
            and call.type == MANAGER_SERVICE for call in node.calls):
        return None
    return host_of(*MANAGER_NODE, 2)


def _load(choice: Choice, slot: Slot, instance: NodeInstance, index: Mapping[str, Node],
          workspace: Workspace, models: PluginModels | None, params: Params,
          config: Configuration, owned: set[int], made: dict[int, set[tuple[Any, ...]]],
          loaded: set[tuple[int, str]], decl: NodeDecl | None,
          sites: frozenset[str] = frozenset(),
          ) -> list[tuple[NodeInstance, list[PrimitiveCall]]]:
    """The calls one chosen plugin adds: to the host, or to a node of its own; ``sites``:
    the places loading plugins whose classes the host's slots attach (``Slot.site``)."""
    out: list[tuple[NodeInstance, list[PrimitiveCall]]] = []
    node = _lookup(choice, index, workspace, models)
    reader = instance
    # a class of an installed package's model its host loads because it loads every one
    # it finds: what it makes is the interface the host offers (``NodeInstance.offered``)
    offered = slot.names == EXPORTED and node is not None and node.model is not None
    if node is None and slot.placement == "node" and _named_class(choice):
        # a controller of a class known by name that no package here or model exports
        # (ros2_controllers' JointStateBroadcaster without its source): still a node of
        # its own, of unknown interface; the host's own interface is whole
        config.diagnostics.append(_not_found(choice, instance.name))
        reader = _plugin_instance(instance, choice, None, config)
        if slot.declares:
            out.append((reader, [PrimitiveCall(
                "declare", name, location=choice.location, conditions=choice.conditions,
                has_default=True, origin="plugin") for name in slot.declares]))
    elif node is None:
        _missing(config, instance, choice, owned)
    elif slot.placement == "code" and node.rosname and UNKNOWN_MARK not in node.rosname:
        # a class whose code makes a node of its own (xarm's hardware: ``rclcpp::Node::
        # make_shared("ufactory_driver")``), in the host's process: its calls are that
        # node's, and the process's parameter files name it
        reader = _plugin_instance(instance, replace(
            choice, name=node.rosname.strip("/"), remaps=()), node, config)
        if decl is not None:
            process_file_params(decl, reader, params)
        _unhosted(reader, owned)
        out.append((reader, _not_hosts(node.calls, instance)))
    elif slot.placement == "node":
        renamed = decl.name.rstrip("/").rsplit("/", 1)[-1] if (
            slot.global_rules and decl is not None and decl.name_given) else ""
        reader = _plugin_instance(
            instance, replace(choice, name=renamed) if renamed else choice, node, config,
            slot.beneath_host and (decl is None or not (
                decl.namespace_given or decl.namespace.strip("/"))))
        reader.offered = offered
        if slot.names in (EXPORTED, SPAWNER) and decl is not None:
            # a node the process makes: its files apply by name (a controller's section
            # of the file given to ros2_control_node, after its spawner's file, whose
            # values win: rcl's global arguments reach every node of the process)
            process_file_params(decl, reader, params,
                                host=instance if slot.names == SPAWNER else None)
        _unhosted(reader, owned)  # a controller that loads plugins of its own
        out.append((reader, _not_hosts(_with_base(node, index, workspace, models),
                                       instance)))
        if slot.declares:  # the host's loading code declares them on the plugin's node
            out.append((reader, [PrimitiveCall(
                "declare", name, location=choice.location, conditions=choice.conditions,
                has_default=True, origin="plugin") for name in slot.declares]))
    else:
        plugin = slot.prefix + _given(choice, slot)
        inner_slots = PLUGIN_SLOTS.get((node.plugin_class or "").lstrip(":"), ())
        if node.completeness in ("partial", "unknown"):  # its calls on the host: some unseen
            reasons = node.completeness_reasons[:1] or [node.completeness]
            own_partial(instance, f"plugin {node.name}: {reasons[0]}", owned)
        elif _uncovered(node.plugin_loads,
                        {*sites, *(s.site for s in inner_slots if s.site)}):
            # a plugin that loads plugins no row attaches (MPPI's critics)
            own_partial(instance, f"plugin {node.name}: {_loads(node)}", owned)
        # the code the plugin runs once per plugin of its own (a base's inline method in
        # a header its unit includes: dwb's TrajectoryCritic::initialize declares
        # ``<plugin>.<critic>.scale``): made for each of them, below
        each_inner: list[PrimitiveCall] = []
        calls = []
        for call in _with_base(node, index, workspace, models):
            if inner_slots and _per_inner(call):
                each_inner.append(call)
            else:
                calls.append(_under(_host_handled(call, instance.node), plugin,
                                    choice.conditions, slot.bases,
                                    slot.inner and not slot.joined))
        if choice.moved_to:
            calls = [replace(call, name=_moved(call.name, choice.moved_to))
                     for call in calls]
        if offered:
            calls = [replace(call, offered=True) for call in calls]
        row = sources_of(choice.cls or "", instance.ros_version) or sources_of(
            node.plugin_class or "", instance.ros_version) or _base_sources(
                node, instance.ros_version, workspace)
        if row is not None:
            calls = _per_source(calls, row, plugin, choice, instance, node, params,
                                workspace)
        out.append((instance, _new(calls, instance, made)))
        for inner_slot in inner_slots:
            out.extend(_inner(choice, inner_slot, plugin, instance, index, workspace, models,
                              params, config, owned, made, loaded, decl, each_inner))
    for own, reads in _loading_reads(choice, instance, reader):
        kept = [r for r in reads if (id(own), r.name) not in loaded]
        loaded.update((id(own), r.name) for r in kept)
        if kept:
            out.append((own, kept))
    return out


def _base_sources(node: Node, ros_version: int, workspace: Workspace) -> Sources | None:
    """The ``Sources`` row of the class a workspace plugin class derives from, whose
    code it runs (rtabmap's ``VoxelLayer : public nav2_costmap_2d::ObstacleLayer`` calls
    ``ObstacleLayer::onInitialize()``, which subscribes to each observation source)."""
    if not node.plugin_class or not node.sources:
        return None
    for base in direct_bases(node.plugin_class, node.sources, workspace):
        for name in dict.fromkeys([base, *_qualified(base, node, workspace)]):
            row = sources_of(name, ros_version)
            if row is not None:
                return row
    return None


def _qualified(base: str, node: Node, workspace: Workspace) -> list[str]:
    """The names a base class written in a workspace plugin class's declaration may
    have: itself when written with a namespace, else itself under each namespace C++
    looks it up in, those that enclose the class innermost first (fetch's
    ``costmap_2d::FetchDepthLayer : public VoxelLayer`` derives from
    ``costmap_2d::VoxelLayer``), then those the class's files bring in with ``using
    namespace``."""
    if "::" in _untemplated(base).strip().lstrip(":"):
        return [base]
    parts = _untemplated(node.plugin_class or "").strip().lstrip(":").split("::")[:-1]
    spaces = ["::".join(parts[:depth]) for depth in range(len(parts), 0, -1)]
    for text in _class_texts(node, workspace):
        for space in _namespaces_used(text):
            if space not in spaces:
                spaces.append(space)
    return [f"{space}::{base.strip()}" for space in spaces]


# ``using namespace a::b;`` (the namespace's name, spaces and all)
_USING_NAMESPACE = re.compile(r"\busing\s+namespace\s+((?:::)?\s*\w+(?:\s*::\s*\w+)*)\s*;")


@functools.lru_cache(maxsize=512)
def _namespaces_used(text: str) -> tuple[str, ...]:
    """The namespaces a file's text brings in with ``using namespace``, in order: read
    once per text, not for each base of each plugin class that includes it (navigation2's
    2,910 look-ups read the same headers again)."""
    return tuple(re.sub(r"\s+", "", found.group(1)).lstrip(":")
                 for found in _USING_NAMESPACE.finditer(text))


def _uncovered(loads: list[str], sites: set[str]) -> bool:
    """Whether a load site (``file:line``) is none of ``sites``: a ``file:line``, or a
    file (its end) whose every load a row attaches."""
    return any(load not in sites and not any(
        load.rsplit(":", 1)[0].endswith(site) for site in sites) for load in loads)


def _inner(choice: Choice, slot: Slot, plugin: str, instance: NodeInstance,
           index: Mapping[str, Node], workspace: Workspace, models: PluginModels | None,
           params: Params, config: Configuration, owned: set[int],
           made: dict[int, set[tuple[Any, ...]]], loaded: set[tuple[int, str]],
           decl: NodeDecl | None, each_inner: Sequence[PrimitiveCall] = (),
           ) -> list[tuple[NodeInstance, list[PrimitiveCall]]]:
    """The calls of the plugins that the plugin ``plugin`` (chosen by ``choice``) loads
    from its host's parameters (``hosts.PLUGIN_SLOTS``), on the host; ``each_inner``, the
    outer plugin's calls made once per such plugin (``_per_inner``), with each."""
    def relative(text: str | None) -> str | None:
        return None if text is None else text.replace("{plugin}", plugin)

    nested = replace(slot, names=relative(slot.names), type_of=relative(slot.type_of),
                     prefix=plugin + ".", resolve=None if slot.resolve is None else (
                         slot.resolve[0], relative(slot.resolve[1]) or "",
                         slot.resolve[2]))
    out: list[tuple[NodeInstance, list[PrimitiveCall]]] = []
    for each in list(_chosen(instance, nested, params)):
        cls = each.cls or (each.name if slot.class_is_name and UNKNOWN_MARK not in (
            each.name) else None)
        each = replace(each, cls=_completed(cls, nested, instance, params, index,
                                            workspace, models),
                       conditions=(*choice.conditions, *each.conditions))
        out.extend(_load(each, nested, instance, index, workspace, models, params, config,
                         owned, made, loaded, decl))
        if each_inner and UNKNOWN_MARK not in each.name:
            out.append((instance, _new([
                _under(call, f"{plugin}.{each.name}", each.conditions, inner=True)
                for call in each_inner], instance, made)))
    return out


def _per_inner(call: PrimitiveCall) -> bool:
    """Whether a plugin's call is named by its name and one of its own plugins' (two
    unknown parts first, ``?.?.scale``), which its code makes once per such plugin."""
    return call.name.startswith(f"{UNKNOWN_MARK}.{UNKNOWN_MARK}.") and not (
        call.name_param or call.handle_namespace)


def _completed(cls: str | None, slot: Slot, instance: NodeInstance, params: Params,
               index: Mapping[str, Node], workspace: Workspace,
               models: PluginModels | None) -> str | None:
    """A class written short, completed as the loading code does (``Slot.resolve``):
    its suffix added, then the first of the namespaces the list parameter gives (or its
    defaults) under which a class is found."""
    if cls is None or slot.resolve is None or UNKNOWN_MARK in cls:
        return cls
    suffix, listing, defaults = slot.resolve
    if suffix not in cls:
        cls += suffix
    if "::" in cls:
        return cls
    given = _parameter(params, instance.name.rstrip("/") + "/" + listing)
    namespaces = [str(n) for n in given.value] if given is not None and isinstance(
        given.value, list) and given.value else list(defaults)
    for namespace in namespaces:
        full = f"{namespace}::{cls}"
        if _lookup(Choice("", full, instance.location), index, workspace, models):
            return full
    return cls


def _with_base(node: Node, index: Mapping[str, Node], workspace: Workspace,
               models: PluginModels | None) -> list[PrimitiveCall]:
    """A plugin's calls and those of the exported class whose code it runs (``EXTENDS``),
    or of a base class of a package without source here that an interface model
    describes (``_modelled_base``)."""
    base = EXTENDS.get((node.plugin_class or "").lstrip(":")) or EXTENDS.get(node.executable)
    found = _lookup(Choice("", base, node.location), index, workspace, models) if base else None
    if found is node:
        return list(node.calls)
    inherited = (list(found.calls) if found is not None
                 else _modelled_base(node, index, workspace, models))
    own = {_key(c) for c in node.calls}
    return [*node.calls, *(c for c in inherited if _key(c) not in own)]


def _modelled_base(node: Node, index: Mapping[str, Node], workspace: Workspace,
                   models: PluginModels | None) -> list[PrimitiveCall]:
    """The calls of the base class a workspace plugin class derives from, when the base's
    package has no source here, as an interface model shows them: the model of the
    exported base class itself, whose code runs in the derived class's node (UR's
    ``ScaledJointTrajectoryController : public joint_trajectory_controller::
    JointTrajectoryController`` calls the base's ``on_init``, ``on_configure``, ...: the
    action server and topics are the base's); or, for a base no package exports
    (``RUNS_AS``: nav2's ``TimedBehavior<ActionT>``), what the model of an exported class
    that runs only the base's code shows of it. A base of the workspace is read from its
    source (``inherit.inherited_sources``)."""
    if node.model is not None or not node.plugin_class or not node.sources:
        return []
    for base in direct_bases(node.plugin_class, node.sources, workspace):
        if UNKNOWN_MARK in base:
            continue
        runs = _runs_as(base, node, workspace)
        if runs is not None:
            found = _lookup(Choice("", runs.model_class, node.location), index, workspace,
                            models)
            if found is not None and found.model is not None:
                return _base_code(found, runs, base, node, workspace)
            continue
        for name in _qualified(base, node, workspace):
            found = _lookup(Choice("", name, node.location), index, workspace, models)
            if found is not None and found is not node and found.model is not None:
                return list(found.calls)
    return []


def _runs_as(base: str, node: Node, workspace: Workspace) -> RunsAs | None:
    """The ``RUNS_AS`` row of a base class as the derived class's declaration writes it:
    qualified, or by its own name in a namespace C++ looks it up in (``_qualified``:
    ``using namespace nav2_behaviors;``, the namespace the class is declared in)."""
    name = _untemplated(base).strip().lstrip(":")
    return next((RUNS_AS[each] for each in (name, *_qualified(name, node, workspace))
                 if each in RUNS_AS), None)


def _class_texts(node: Node, workspace: Workspace) -> list[str]:
    """The texts of a plugin class's sources and the headers they include (as
    ``direct_bases`` reads them)."""
    return [text for source in node.sources
            for text in with_headers(source, workspace, HEADER_DEPTH)]


MAX_ALIASES = 4  # aliases followed from a base's template argument to its type


def _base_code(model: Node, runs: RunsAs, base: str, node: Node,
               workspace: Workspace) -> list[PrimitiveCall]:
    """The calls ``model`` makes outside its class's own files (the base's code), those
    of the kinds ``runs`` types by the base's template argument typed by the derived
    class's (unknown when the text does not tell it)."""
    typed = _argument_type(base, node, workspace) if runs.typed else None
    named = (_returned_name(node, workspace) or UNKNOWN_MARK) if runs.named else None
    out = []
    for call in model.calls:
        if call.location.file in model.sources:
            continue
        if call.kind in runs.typed:
            call = replace(call, type=typed)
        if named is not None and call.name == runs.named:
            call = replace(call, name=named)
        out.append(call)
    return out


# ``getName()`` defined to return a literal: ``std::string getName() override {return
# std::string("navigate_complete_coverage");}``, in the class body or out of it
_GET_NAME = re.compile(r"\bgetName\s*\(\s*\)[^{;]*\{\s*return\s+(?:std::string\s*[({]\s*)?"
                       r"\"([^\"\\]*)\"")


def _returned_name(node: Node, workspace: Workspace) -> str | None:
    """The literal the plugin class's ``getName()`` returns, from its files' text; None
    when they define none or several."""
    found = {match.group(1) for text in _class_texts(node, workspace)
             for match in _GET_NAME.finditer(text)}
    return found.pop() if len(found) == 1 else None


def _argument_type(base: str, node: Node, workspace: Workspace) -> str | None:
    """The ROS 2 interface a base class's template argument names (``TimedBehavior<
    Action>`` with ``using Action = nav2_msgs::action::Wait;``: ``nav2_msgs/action/Wait``),
    through the aliases the class's files declare."""
    argument = base_argument(node.plugin_class or "", base, node.sources, workspace)
    texts: list[str] | None = None
    for _ in range(MAX_ALIASES):
        if argument is None:
            return None
        parts = re.sub(r"^typename\s+", "", argument.strip()).lstrip(":").split("::")
        if len(parts) >= 3 and parts[-2] in ("msg", "srv", "action"):
            return "/".join(parts[-3:])
        if texts is None:
            texts = _class_texts(node, workspace)
        alias = re.escape(parts[-1])
        pattern = re.compile(rf"\busing\s+{alias}\s*=\s*(?:typename\s+)?([\w:]+)\s*;"
                             rf"|\btypedef\s+(?:typename\s+)?([\w:]+)\s+{alias}\s*;")
        found = next((m for m in map(pattern.search, texts) if m is not None), None)
        argument = (found.group(1) or found.group(2)) if found is not None else None
    return None


def _child_instance(decl: NodeDecl, host: NodeInstance, child: Child,
                    nodes: Mapping[str, Node], models: PluginModels | None, params: Params,
                    config: Configuration) -> tuple[NodeInstance, Node | None]:
    """The node ``child`` the host's code makes in its process: in the host's namespace
    plus the child's, with the host's remaps (arguments of the process) and the entries
    of the process's parameter files that name it."""
    key = f"{child.package}/{child.executable}"
    node = nodes.get(key) or (models(key) if models is not None else None)
    namespace = host.namespace.rstrip("/") + "/" + child.namespace + "/"
    name = namespace + child.name
    instance = NodeInstance(name, node, namespace=namespace, remaps=list(host.remaps),
                            args=host.args, conditions=host.conditions,
                            location=host.location, origin="plugin",
                            ros_version=host.ros_version)
    _add_hosted(instance, host, config)
    process_file_params(decl, instance, params)
    return instance, node


def _constructed(call: PrimitiveCall, name: str) -> PrimitiveCall:
    """A call of the node a host's code constructs with the name ``name``: a name made
    of the name the node was constructed with (``PrimitiveCall.name_built``) has
    ``name`` there, not the name the node's own program constructs it with (nav2's
    controller server builds its Costmap2DROS as ``local_costmap``, which serves
    ``clear_entirely_local_costmap``; the costmap program's node is ``costmap``)."""
    if call.name_built is None or call.name_built.count(UNKNOWN_MARK) != 1:
        return call
    return replace(call, name=call.name_built.replace(UNKNOWN_MARK, name), name_built=None)


def process_file_params(decl: NodeDecl, instance: NodeInstance, params: Params,
                        host: NodeInstance | None = None) -> None:
    """The entries of the process's parameter files that name a node it makes; the
    ``/**`` ones too when the node declares every override it is given (a ``host``:
    ros2_control's controllers, made with ``automatically_declare_parameters_from_
    overrides(true)``, get the ``robot_description`` a launch file gives the manager as
    a dictionary, which launch_ros writes under ``/**``); else not, a node the code makes
    having those only where it declares them.

    A ``/**`` value reaches the host and each of its controllers alike: a setting for
    several nodes (``Parameter.setting``), unread only when none of them reads it (UR's
    driver gives its manager ``verify_payload_on_set``, which one controller reads)."""
    for document, where, keys in decl.param_files:
        values: dict[str, Any] = {}
        shared: dict[str, str] = {}
        placed: dict[str, Location] = {}  # at the entry's own line in the file
        for pattern, entries in node_patterns(document):
            if pattern == "/**" and host is None:
                continue
            if pattern != "/**" and not pattern_matches(pattern, instance.name):
                continue
            for name, value in flatten(entries):
                values[name] = value
                at = keys.get((pattern, name))
                if at is not None:
                    placed[f"{instance.name.rstrip('/')}/{name}"] = at
                else:
                    placed.pop(f"{instance.name.rstrip('/')}/{name}", None)
                if pattern == "/**":
                    shared[name] = _host_setting(params, host, name, where)
                else:
                    shared.pop(name, None)
        _set_params(params, instance.name, values, where, instance.conditions,
                    placed=placed, settings=shared)


def _host_setting(params: Params, host: NodeInstance | None, name: str,
                  where: Location) -> str:
    """The setting a ``/**`` value of the host's parameter files is: the one the host's
    own copy has (a file given to several nodes), else the place of the entry, which the
    host's copy then takes when it came from that entry."""
    setting = f"{where.file}:{where.line}:{where.column}"
    if host is None:
        return setting
    own = params.by_name.get((Parameter, f"{host.name.rstrip('/')}/{name}"))
    if not isinstance(own, Parameter) or not own.set_by_launch:
        return setting
    if own.setting is None and own.launch_location == where:
        own.setting = setting
    return own.setting or setting


def _exported(instance: NodeInstance, slot: Slot, params: Params,
              nodes: Mapping[str, Node], models: PluginModels | None = None,
              workspace: Workspace | None = None, host: str | None = None
              ) -> Iterator[Choice]:
    """Every plugin class exported with one of the slot's bases that the host's deny and
    allow lists let through (mavros' is_plugin_allowed: fnmatch, case folded): those of
    the workspace's packages, and those the interface models of the slot's
    ``exporters`` without source here give. Another exporter than the host's own
    package (``host``) loads only where it is installed: its classes are under that
    condition, not decided, unless a package of the workspace depends on it."""
    assert slot.lists is not None
    base = instance.name.rstrip("/") + "/"
    deny, allow = (_parameter(params, base + key) for key in slot.lists)
    denied, allowed = _patterns(deny), _patterns(allow)
    if denied is None or allowed is None:  # a list whose value is not known
        unknown = deny if denied is None else allow
        assert unknown is not None
        yield Choice("", UNKNOWN_MARK, unknown.launch_location, unknown.launch_conditions)
        return
    if not denied and allowed:
        denied = ["*"]
    conditions = tuple(c for p in (deny, allow) if p for c in p.launch_conditions)
    given = deny or allow
    where = given.launch_location if given is not None else instance.location
    reads = tuple(p.name for p in (deny, allow) if p)
    found: list[tuple[Node, tuple[Condition, ...]]] = [
        (n, ()) for n in sorted((n for n in nodes.values() if n.kind == "plugin"
                                 and (n.plugin_base in slot.bases)), key=lambda n: n.name)]
    unseen = not found  # its plugins' packages have no source here: what it loads is unknown
    modelled = getattr(models, "exported", None)
    here = workspace.packages if workspace is not None else {}
    for package in slot.exporters:
        if package in here or modelled is None:
            continue
        classes = modelled(package, slot.bases)
        if classes is None:  # no model of it: its classes are not known
            unseen = unseen or package == host
            continue
        unseen = False
        installed = () if package == host or _depended(package, here.values()) else (
            Condition(f"{package} is installed", kind="launch", location=where),)
        found.extend((n, installed) for n in sorted(classes, key=lambda n: n.name))
    if unseen:
        yield Choice("*", None, where, conditions, reads)
    for node, more in found[:MAX_PLUGINS * 5]:
        name = node.executable.casefold()
        if any(fnmatch.fnmatchcase(name, p) for p in denied) and not any(
                fnmatch.fnmatchcase(name, p) for p in allowed):
            continue
        yield Choice(node.rosname or node.executable, node.executable, where,
                     (*conditions, *more), reads, node=node)


def _depended(package: str, packages: Iterable[Package]) -> bool:
    """Whether a package of ``packages`` depends on ``package`` (a dependency whose
    condition holds, or cannot be decided)."""
    return any(d.name == package and d.active for p in packages for d in p.dependencies)


def _patterns(parameter: Parameter | None) -> list[str] | None:
    """A list parameter's glob patterns, case folded; [] when not set, None when its
    value is not known."""
    if parameter is None:
        return []
    value = parameter.value
    if isinstance(value, str):
        value = [value]
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        return None
    return [v.casefold() for v in value]


def _new(calls: list[PrimitiveCall], host: NodeInstance,
         made: dict[int, set[tuple[Any, ...]]]) -> list[PrimitiveCall]:
    """The calls the host does not make already: a header of the host's framework that a
    plugin includes (nav2's LifecycleNode) is code the host runs once, not once more per
    plugin."""
    seen = made.get(id(host))
    if seen is None:
        seen = made[id(host)] = {_key(c) for c in (host.node.calls if host.node else ())}
    out = []
    for call in calls:
        key = _key(call)
        if key not in seen:
            seen.add(key)
            out.append(call)
    return out


def _not_hosts(calls: list[PrimitiveCall], host: NodeInstance) -> list[PrimitiveCall]:
    """A plugin node's calls but those its host's node model makes at the same place: a
    header of the host's framework that the plugin includes (mavros' UAS members) is
    code of the host's node, not of the plugin's."""
    hosts = {(c.kind, c.location) for c in (host.node.calls if host.node else ())}
    return [c for c in calls if (c.kind, c.location) not in hosts]


def _key(call: PrimitiveCall) -> tuple[Any, ...]:
    return (call.kind, call.name, call.type, call.location, call.name_param)


def _loading_reads(choice: Choice, host: NodeInstance, own: NodeInstance,
                   ) -> Iterator[tuple[NodeInstance, list[PrimitiveCall]]]:
    """The reads of the parameters that chose a plugin: the host reads its own (plugin
    lists, ``<name>.plugin``), a controller's node the ``type`` in its parameters."""
    for full in choice.reads:
        for reader in (own, host):
            prefix = reader.name.rstrip("/") + "/"
            if full.startswith(prefix):
                key = full[len(prefix):]
                yield reader, [PrimitiveCall(
                    "read", key if reader.ros_version == 2 else "~" + key,
                    location=choice.location, conditions=choice.conditions,
                    origin="plugin")]
                break
        else:
            if host.ros_version == 1:  # found outside its namespace (``searchParam``)
                yield host, [PrimitiveCall("read", full, location=choice.location,
                                           conditions=choice.conditions, origin="plugin")]


def plugin_index(nodes: Mapping[str, Node]) -> dict[str, Node]:
    """Plugin nodes by pluginlib lookup name and by C++ type."""
    index: dict[str, Node] = {}
    for node in nodes.values():
        if node.kind != "plugin":
            continue
        index.setdefault(node.executable, node)
        for each in plugin_types(node):
            index.setdefault(each, node)
    return index


def plugin_types(node: Node) -> tuple[str, ...]:
    """A plugin node's C++ type, and the class template's name where the type takes its
    template's defaults (nav2 humble's ``nav2_behaviors::DriveOnHeading<>``: the same
    class written ``nav2_behaviors::DriveOnHeading``, as later versions export it)."""
    cls = (node.plugin_class or "").lstrip(":")
    if not cls:
        return ()
    return (cls, cls[:-2]) if cls.endswith("<>") else (cls,)


def _lookup(choice: Choice, index: Mapping[str, Node], workspace: Workspace,
            models: PluginModels | None) -> Node | None:
    """The plugin node of the chosen class, by its lookup name or its C++ type: from the
    workspace, else, when no workspace package can hold it, from an interface model."""
    if choice.node is not None:
        return choice.node
    if not choice.cls or UNKNOWN_MARK in choice.cls:
        return None
    cls = choice.cls.strip().lstrip(":")
    found = index.get(cls)
    if found is None and models is not None and not any(
            package in workspace.packages for package in class_packages(cls)):
        found = models(cls)
    return found


def class_packages(cls: str) -> list[str]:
    """The packages that may export a plugin class, by pluginlib's naming convention: the
    first part of a lookup name ``pkg/Name``, else the first namespace of ``pkg::Class``."""
    cls = cls.strip().lstrip(":")
    first = cls.split("/", 1)[0] if "/" in cls else cls.split("::", 1)[0]
    if not first or first == cls:
        return []
    return [first, *LOOKUP_PACKAGES.get(first, ())]


def _given(choice: Choice, slot: Slot) -> str:
    """The plugin name the host initialises the plugin with."""
    if slot.name_from_class and choice.cls:
        return choice.cls.rsplit("/", 1)[-1].rsplit("::", 1)[-1]
    return choice.name


def _named_class(choice: Choice) -> bool:
    """A choice whose plugin name and class are both known (PLUGIN_NOT_FOUND, not
    PLUGIN_CLASS_UNKNOWN)."""
    return bool(choice.name) and UNKNOWN_MARK not in choice.name and bool(
        choice.cls) and UNKNOWN_MARK not in (choice.cls or "")


def _not_found(choice: Choice, host: str) -> diag.Diagnostic:
    if choice.why is not None:
        return diag.make("HARDWARE_UNKNOWN", choice.location, host=host, detail=choice.why)
    if not choice.cls or UNKNOWN_MARK in choice.cls:
        return diag.make("PLUGIN_CLASS_UNKNOWN", choice.location, plugin=choice.name,
                         host=host)
    return diag.make("PLUGIN_NOT_FOUND", choice.location, plugin=choice.cls, host=host)


def _missing(config: Configuration, instance: NodeInstance, choice: Choice,
             owned: set[int]) -> None:
    found = _not_found(choice, instance.name)
    config.diagnostics.append(found)
    where = choice.location
    own_partial(instance, f"{found.message} ({where.file}:{where.line})", owned)


def _unhosted(instance: NodeInstance, owned: set[int]) -> None:
    """An instance whose code loads plugins (``Node.plugin_loads``) that no host row
    attaches: their calls are unknown, so it is partial (unknown is not empty)."""
    node = instance.node
    if node is not None and node.plugin_loads:
        own_partial(instance, _loads(node), owned)


def _loads(node: Node) -> str:
    """Why a node that loads plugins by name is partial, with its first site."""
    more = f" and {len(node.plugin_loads) - 1} more" if len(node.plugin_loads) > 1 else ""
    return (f"{node.plugin_loads[0]}{more}: loads plugin classes by name whose "
            "calls are not known here")


def own_partial(instance: NodeInstance, reason: str, owned: set[int],
                first: bool = False) -> None:
    """Mark ``instance`` partial without touching the node model other instances share:
    the instance gets its own copy first (``owned`` holds the ids of those that have).
    ``first``: the reason goes before those the node model has (which keep only a few):
    what the configuration adds to a node already partial is said."""
    if instance.node is None:
        return
    if id(instance) not in owned:
        node = copy.copy(instance.node)
        node.completeness_reasons = list(node.completeness_reasons)
        instance.node = node
        owned.add(id(instance))
    if first and reason not in instance.node.completeness_reasons:
        instance.node.completeness_reasons.insert(0, reason)
        del instance.node.completeness_reasons[5:]  # as mark_partial keeps them
    instance.node.mark_partial(reason)


def _parameter(params: Params, name: str) -> Parameter | None:
    found = params.by_name.get((Parameter, name))
    if isinstance(found, Parameter) and found.set_by_launch:
        return found
    return None


def _unseen_choice(instance: NodeInstance, slot: Slot, params: Params) -> str | None:
    """Why the plugins ``slot`` loads on ``instance`` are not known, when the
    parameter that names them is not set as far as we see but a launch parameter not
    known statically may be it (``/move_base/?`` of a parameter file that is not read:
    it may name ``base_local_planner``, which would load another class than the
    default); None otherwise."""
    base = instance.name.rstrip("/") + "/"
    written = slot.type_of if slot.names is None else slot.names
    if not written or "{" in written:
        return None
    return _may_be_set(base + written, params)


def _may_be_set(name: str, params: Params,
                role: str = "names the plugins it loads") -> str | None:
    """Why the plugins the parameter ``name`` names (or, as ``role`` says, chooses) are
    not known, when it is not set as far as we see but a launch parameter not known
    statically may be it; else None."""
    if _parameter(params, name) is not None:
        return None
    for (kind, full), each in params.by_name.items():
        if kind is Parameter and UNKNOWN_MARK in full and isinstance(each, Parameter) and (
            each.set_by_launch and re.match(pattern_for(full), name)
        ):
            where = each.launch_location
            return (f"{name}, which {role}, may be set by the launch "
                    f"parameter {full} not known statically ({where.file}:{where.line}): "
                    "they may be others than those seen (its defaults, or none)")
    return None


def _chosen(instance: NodeInstance, slot: Slot, params: Params,
            base: str | None = None) -> Iterator[Choice]:
    """The plugins a host slot names, from the instance's parameters or the defaults;
    ``base`` is put before the slot's parameter names (the instance's private
    namespace unless given)."""
    if base is None:
        base = instance.name.rstrip("/") + "/"
    if slot.names is None:
        assert slot.type_of is not None
        if slot.unless is not None and _keys(instance, slot.unless, params):
            return
        given = _parameter(params, base + slot.type_of)
        if given is not None:
            yield from _typed(Choice(slot.given or "", None, given.launch_location,
                                     given.launch_conditions, (given.name,)),
                              given, slot)
        else:
            for default, default_cls in slot.defaults:
                yield Choice(slot.given or default, default_cls, instance.location)
        return
    listed = _parameter(params, base + slot.names)
    where: Location
    conditions: tuple[Condition, ...]
    if listed is None and slot.pre_hydro:
        yield from _pre_hydro(instance, slot, params)
        return
    if slot.disable is not None:
        yield from _added(instance, slot, params, listed)
        return
    if listed is None:
        entries: list[Any] = [name for name, _ in slot.defaults]
        where, conditions = instance.location, ()
    else:
        value = listed.value
        entries = list(value) if isinstance(value, list) else [value]
        where, conditions = listed.launch_location, listed.launch_conditions
    listing = (listed.name,) if listed is not None else ()
    if slot.typed_only and listed is not None and isinstance(listed.value, list):
        entries = [entry for entry in entries if _typed_entry(entry, slot.type_key)]
    for entry in entries[:MAX_PLUGINS]:
        if isinstance(entry, dict):  # ROS 1: {name: ..., type: ...}
            yield Choice(_text(entry.get("name")) or UNKNOWN_MARK,
                         _text(entry.get(slot.type_key)), where, conditions, listing)
            continue
        name = _text(entry) or UNKNOWN_MARK
        cls = dict(slot.defaults).get(name)
        if listed is None:  # a default: under the tests of the host's code, if any
            conditions = _default_tests(slot, name)
        parameter = base + (slot.type_of or "").format(name=name)
        typed = _parameter(params, parameter) if slot.type_of else None
        if typed is not None:
            yield Choice(name, _text(typed.value), typed.launch_location,
                         (*conditions, *typed.launch_conditions), (*listing, parameter))
        else:
            yield Choice(name, cls, where, conditions, listing)


def _default_tests(slot: Slot, name: str) -> tuple[Condition, ...]:
    """The source conditions of the host's code a default plugin ``name`` of ``slot``
    is loaded under (``Slot.default_if``), decided by the graph from the host's
    parameter (``Condition.parameters``)."""
    return tuple(
        Condition(test.text, "source", "if", Location(test.package, test.file, test.line, 0),
                  parameters=((test.text, test.parameter),))
        for test in slot.default_if if test.plugin == name)


def _typed_entry(entry: Any, key: str) -> bool:
    """Whether a list element names a class to load (``Slot.typed_only``): a mapping
    with a class under ``key`` that is not empty and does not start with ``~``; one whose
    class is not known statically may be."""
    if not isinstance(entry, dict) or key not in entry:
        return False
    cls = entry[key]
    return not (isinstance(cls, str) and (not cls or cls.startswith("~")))


def _keyed(instance: NodeInstance, slot: Slot, params: Params) -> Iterator[Choice]:
    """The plugins of a KEYED slot: for each name its ``keys`` finds, the classes of
    ``type_of`` for that name, in the namespace where the name was found."""
    assert slot.keys is not None and slot.type_of is not None
    for name, scope in _keys(instance, slot.keys, params, slot.search)[:MAX_PLUGINS]:
        typed = _parameter(params, scope + slot.type_of.format(name=name))
        if typed is None:
            continue
        given = ("{name}" if slot.given is None else slot.given).format(name=name)
        moved = slot.rebase.format(name=name) if slot.rebase else None
        yield from _typed(Choice(given, None, typed.launch_location,
                                 typed.launch_conditions, (typed.name,), moved_to=moved),
                          typed, slot)


def _keys(instance: NodeInstance, pattern: str, params: Params,
          search: bool = False) -> list[tuple[str, str]]:
    """The names ``{name}`` stands for in the launch parameters ``pattern`` matches,
    with the namespace each was found in: the host's private one, or with ``search``
    the nearest of it and its parents that has the parameter (``searchParam``)."""
    scopes = [instance.name.rstrip("/") + "/"]
    if search:
        parts = scopes[0].strip("/").split("/")
        scopes += ["/" + "/".join(parts[:n]) + "/" if n else "/"
                   for n in range(len(parts) - 1, -1, -1)]
    head, _, tail = pattern.partition("{name}")
    found: dict[str, str] = {}
    for scope in scopes:
        start, end = scope + head, tail
        for (kind, full), each in params.by_name.items():
            if kind is not Parameter or not isinstance(each, Parameter) or not (
                    each.set_by_launch and full.startswith(start) and full.endswith(end)):
                continue
            name = full[len(start):len(full) - len(end)]
            if name and "/" not in name and UNKNOWN_MARK not in name:
                found.setdefault(name, scope)
    return sorted(found.items())


def _typed(choice: Choice, typed: Parameter, slot: Slot) -> Iterator[Choice]:
    """The choices of one class parameter: its class, or with ``slot.words`` each of
    the white-space separated classes of its string (one unknown class when the value
    is not known)."""
    if not slot.words:
        yield replace(choice, cls=_text(typed.value))
        return
    words = _words(typed.value)
    if words is None:
        yield replace(choice, cls=UNKNOWN_MARK)
    for word in (words or [])[:MAX_PLUGINS]:
        yield replace(choice, cls=word)


def _added(instance: NodeInstance, slot: Slot, params: Params,
           listed: Parameter | None) -> Iterator[Choice]:
    """A slot whose classes are its defaults plus those of a string parameter, less
    those of its ``disable`` string (move_group's capabilities). A string not known
    statically loads classes nobody can name: one unknown choice (the host is partial)."""
    base = instance.name.rstrip("/") + "/"
    disabled = _parameter(params, base + slot.disable) if slot.disable else None
    dropped = _words(disabled.value) if disabled is not None else []
    chosen: dict[str, Choice] = {}
    for name, _ in slot.defaults:
        chosen[name] = Choice(name, name, instance.location)
    if listed is not None:
        words = _words(listed.value)
        if words is None:
            chosen[UNKNOWN_MARK] = Choice(UNKNOWN_MARK, None, listed.launch_location,
                                          listed.launch_conditions, (listed.name,))
        for word in words or []:
            chosen.setdefault(word, Choice(word, word, listed.launch_location,
                                           listed.launch_conditions, (listed.name,)))
    if dropped is None:  # an unknown disable list: each choice may be left out
        assert disabled is not None
        for name in list(chosen):
            chosen[name] = replace(chosen[name], conditions=(
                *chosen[name].conditions, Condition(
                    f"{name} not in {disabled.name}", "launch", "if",
                    disabled.launch_location)))
    for name in dropped or []:
        chosen.pop(name, None)
    yield from list(chosen.values())[:MAX_PLUGINS]


def _words(value: Any) -> list[str] | None:
    """The classes a white-space separated string names; None when not known."""
    return value.split() if isinstance(value, str) else None


def _pre_hydro(instance: NodeInstance, slot: Slot, params: Params) -> Iterator[Choice]:
    """A ROS 1 costmap without ``plugins`` makes its layers from the older parameters
    (costmap_2d_ros.cpp, ``Costmap2DROS::loadOldParameters``, lines 192-262 in noetic):
    ``static_layer`` when ``static_map`` is true (:203), ``obstacle_layer`` a VoxelLayer
    when ``map_type`` is ``voxel``, else an ObstacleLayer (:218-237), and
    ``inflation_layer`` (:252-258); it moves ``observation_sources`` and each source's
    parameters from the costmap's namespace into the obstacle layer's (:244-250)."""
    costmap = instance.name.rstrip("/") + "/" + slot.prefix
    static = _parameter(params, costmap + "static_map")
    if static is not None and static.value is not False:
        known = static.value is True
        yield Choice("static_layer", "costmap_2d::StaticLayer", static.launch_location,
                     (*static.launch_conditions, *(() if known else (Condition(
                         f"{static.name} is true", "source", "if",
                         static.launch_location),))), (static.name,))
    kind = _parameter(params, costmap + "map_type")
    voxel = kind is not None and kind.value == "voxel"
    yield Choice("obstacle_layer", "costmap_2d::VoxelLayer" if voxel
                 else "costmap_2d::ObstacleLayer",
                 kind.launch_location if kind is not None else instance.location,
                 kind.launch_conditions if kind is not None else (),
                 (kind.name,) if kind is not None else (),
                 moved_from=slot.prefix.rstrip("/"))
    yield Choice("inflation_layer", "costmap_2d::InflationLayer", instance.location)


def _text(value: Any) -> str | None:
    return value if isinstance(value, str) and value else None


# -- plugins a node's own code loads by a parameter (filters' FilterChain) ----------------


MAX_CHAIN = 100  # ROS 2 filters of one chain (filter1, filter2, ...)


def chains(config: Configuration, nodes: Mapping[str, Node], params: Params,
           workspace: Workspace, models: PluginModels | None = None,
           done: set[tuple[int, str]] | None = None,
           ) -> list[tuple[NodeInstance, list[PrimitiveCall]]]:
    """The calls of the classes that node instances' own code loads by the value of a
    parameter it names (a linked call marked ``loads``, ``hosts.CHAINS``: filters'
    FilterChain), as a host's slot loads them: ROS 1 the list that parameter holds, of
    ``{name, type, params}`` entries (as move_base's ``recovery_behaviors``), each
    filter's calls made with its ``name``; ROS 2 ``<prefix>filterN.type`` and ``.name``
    from 1 up to the first not set, each filter's calls with ``<prefix>filterN.params``
    (its ``getParam`` declares below it), plus the declarations and reads of the names
    and types the chain looks for. A chain not set loads nothing (the libraries take it
    as empty), unless a launch parameter not known statically may set it: then the
    instance is partial. A class not set or found is ``PLUGIN_CLASS_UNKNOWN`` /
    ``PLUGIN_NOT_FOUND`` and the instance partial, as for a host. ``done``: the chains
    (instance, parameter) an earlier call attached, not attached again (a filter's own
    chain, laser_filters' LaserArrayFilter's, is linked after the call that loads that
    filter)."""
    index = plugin_index(nodes)
    owned: set[int] = set()
    made: dict[int, set[tuple[Any, ...]]] = {}
    loaded: set[tuple[int, str]] = set()
    out: list[tuple[NodeInstance, list[PrimitiveCall]]] = []
    done = set() if done is None else done
    for instance in list(config.nodes):
        for each in list(instance.links):
            call = each.call
            if call is None or call.loads is None or (
                    call.loads not in CHAINS and not is_class_load(call.loads)) or (
                    call.kind not in ("read", "declare")):
                continue
            full = each.resource.name
            if (id(instance), full) in done:
                continue
            done.add((id(instance), full))
            if is_class_load(call.loads) and _host_slot_reads(instance, full):
                # the host's row loads it, with the plugin name it knows (nav2's
                # waypoint_follower reads ``<id>.plugin`` of the id its parameter names)
                continue
            if UNKNOWN_MARK in full:  # a chain named at run time: its classes unknown
                where = call.location
                own_partial(instance, f"{where.file}:{where.line}: loads the plugin classes "
                            f"the parameters {full} name, whose name is not known "
                            "statically", owned)
                continue
            if is_class_load(call.loads):
                out.extend(_class_load(instance, call, full, params, index, workspace,
                                       models, config, owned, made, loaded))
                continue
            slot = Slot(full, None, (call.loads,))
            if instance.ros_version == 2:
                choices, calls = _numbered_filters(instance, call, full, params, owned)
                if calls:
                    out.append((instance, calls))
            else:
                unseen = _may_be_set(full, params)
                if unseen is not None:
                    own_partial(instance, unseen, owned)
                choices = [replace(c, reads=(), conditions=(*call.conditions, *c.conditions))
                           for c in _chosen(instance, slot, params, base="")]
            for choice in choices:
                out.extend(_load(choice, slot, instance, index, workspace, models, params,
                                 config, owned, made, loaded, None))
    return out


def _class_load(instance: NodeInstance, call: PrimitiveCall, full: str, params: Params,
                index: Mapping[str, Node], workspace: Workspace,
                models: PluginModels | None, config: Configuration, owned: set[int],
                made: dict[int, set[tuple[Any, ...]]], loaded: set[tuple[int, str]],
                ) -> list[tuple[NodeInstance, list[PrimitiveCall]]]:
    """The calls of the one class a pluginlib ClassLoader of the instance's code creates,
    named by the value of the parameter ``full`` (``PLUGINLIB_CLASS``): the value the
    configuration sets, else the default the code gives it; its calls are the node's.
    Neither: the instance is partial, as it is where a launch parameter not known
    statically may set it."""
    if _host_slot_reads(instance, full):
        return []  # the host's row loads it, with the plugin name and placement it knows
    default = call.default if isinstance(call.default, str) and call.default else None
    if default is None and instance.ros_version == 2:
        # a ROS 2 read without a default gets what the node's declarations of that
        # parameter give it (navigation2's ``declare_parameter_if_not_declared(node,
        # name + ".trajectory_generator_name", ParameterValue(std::string("dwb_plugins::
        # StandardTrajectoryGenerator")))``, then ``get_parameter(name, out)``)
        declared = {link.call.default for link in instance.links
                    if link.call is not None and link.call.kind == "declare"
                    and link.resource is not None and link.resource.name == full
                    and isinstance(link.call.default, str) and link.call.default}
        default = declared.pop() if len(declared) == 1 else None
    # the name the parameter's name is made of (an element of a list, nav2's
    # ``<id>.plugin``; a plugin's name) is the one the class is given
    # (``plugin->configure(node, ids[i])``)
    slot = Slot(None, full, (class_load_base(call.loads) or PLUGINLIB_CLASS,),
                defaults=(("", default),) if default else (), given=call.loads_given)
    unseen = _may_be_set(full, params)
    if unseen is not None:
        own_partial(instance, unseen, owned)
    choices = [replace(c, reads=(), conditions=(*call.conditions, *c.conditions))
               for c in _chosen(instance, slot, params, base="")]
    if not choices:
        where = call.location
        own_partial(instance, f"{where.file}:{where.line}: loads the plugin class the "
                    f"parameter {full} names, which is not set and has no default", owned)
    out: list[tuple[NodeInstance, list[PrimitiveCall]]] = []
    own = instance.node.package if instance.node is not None else ""
    for choice in choices:
        if own and choice.cls and models is not None and _lookup(
                choice, index, workspace, models) is None:
            # a class of the loading node's own package, whatever its namespace
            # (slam_toolbox's ``solver_plugins::CeresSolver``), in that package's model
            choice = replace(choice, node=models(f"{own}/{choice.cls.strip().lstrip(':')}"))
        out.extend(_load(choice, slot, instance, index, workspace, models, params, config,
                         owned, made, loaded, None))
    return out


def _host_slot_reads(instance: NodeInstance, full: str) -> bool:
    """Whether a slot of the host row of the instance's node names its plugins by the
    parameter ``full`` (move_base's ``base_local_planner``): the row attaches them."""
    node = instance.node
    host = host_of(node.package, node.executable, instance.ros_version) if (
        node is not None) else None
    if host is None:
        return False
    own = instance.name.rstrip("/")
    relative = full[len(own) + 1:] if full.startswith(own) and full[len(own):len(own) + 1] in (
        "/", ".") else None
    return relative is not None and any(
        written is not None and re.fullmatch(
            re.escape(written).replace(re.escape("{name}"), "[^/]+"), relative)
        for slot in host.slots for written in (slot.type_of, slot.names))


def _numbered_filters(instance: NodeInstance, call: PrimitiveCall, full: str,
                      params: Params, owned: set[int],
                      ) -> tuple[list[Choice], list[PrimitiveCall]]:
    """ROS 2 filters' chain (filter_chain.hpp, ``load_chain_config``): the filters its
    ``<prefix>filterN.name`` / ``.type`` parameters give, N from 1 until neither is set,
    and the declarations and reads of filter2 on (the code's call makes filter1's)."""
    prefix = full[:-len("filter1.type")] if full.endswith("filter1.type") else None
    own = instance.name.rstrip("/") + "/"
    if prefix is None or not prefix.startswith(own):
        return [], []
    unseen = _may_be_set(full, params)
    if unseen is not None:
        own_partial(instance, unseen, owned)
    relative = prefix[len(own):]
    choices: list[Choice] = []
    calls: list[PrimitiveCall] = []
    for number in range(1, MAX_CHAIN + 1):
        keys = [f"filter{number}.{field}" for field in ("type", "name")]
        if number > 1:
            calls.extend(replace(call, kind=kind, name=relative + key, loads=None,
                                 has_default=True, origin="plugin")
                         for key in keys for kind in ("declare", "read"))
        typed, named = (_parameter(params, prefix + key) for key in keys)
        if typed is None and named is None:
            break
        given = typed or named
        assert given is not None
        choices.append(Choice(
            f"{relative}filter{number}.params", _text(typed.value) if typed else None,
            given.launch_location, (*call.conditions, *given.launch_conditions)))
    return choices, calls


# -- ros2_control -----------------------------------------------------------------------


@dataclass
class Spawn:
    """What one ``controller_manager spawner`` declaration asks for."""

    controllers: list[str]
    manager: str
    param_files: list[str]
    controller_type: str | None
    ros_args: list[str]


def spawn_args(decl: NodeDecl) -> Spawn:
    """The spawner's command line, as its argparse reads it."""
    words = shell_words(decl.args)
    spawn = Spawn([], MANAGER_NAME, [], None, [])
    takes_value = {"-c", "--controller-manager", "-p", "--param-file", "-n", "--namespace",
                   "-t", "--controller-type", "--controller-manager-timeout",
                   "--switch-timeout", "--service-call-timeout", "--controller-ros-args"}
    index = 0
    while index < len(words):
        word = words[index]
        value = words[index + 1] if index + 1 < len(words) else ""
        if word in takes_value:
            index += 2
            if word in ("-c", "--controller-manager"):
                spawn.manager = value
            elif word in ("-p", "--param-file"):
                spawn.param_files.append(value)
            elif word in ("-t", "--controller-type"):
                spawn.controller_type = value
            elif word == "--controller-ros-args":
                # launch joins arguments with spaces: "-r a:=b" arrives as two words
                spawn.ros_args.extend(value.split())
                while (spawn.ros_args and spawn.ros_args[-1] in _ROS_ARG_FLAGS
                       and index < len(words)):
                    spawn.ros_args.append(words[index])
                    index += 1
            continue
        if not word.startswith("-"):
            spawn.controllers.append(word)
        index += 1
    return spawn


def _spawn_of(decl: NodeDecl) -> Spawn | None:
    """What a declaration that loads ROS 2 controllers asks for: a spawner's command
    line, or ``ros2 control load_controller NAME [PARAM_FILE]`` (``commands.cli_load``),
    the one controller and its file; None for any other."""
    if (decl.package, decl.executable) in SPAWNERS:
        return spawn_args(decl)
    load = cli_load(decl)
    if load is None:
        return None
    return Spawn([load.controller], load.manager,
                 [load.param_file] if load.param_file else [], None, [])


def _manager_name(spawner: NodeDecl, manager: str) -> str:
    """The controller manager a spawner talks to: ``-c`` resolved in its namespace."""
    if manager.startswith("/"):
        return manager
    namespace = spawner.namespace.rstrip("/")
    return f"{namespace}/{manager}"


def _serves(instance: NodeInstance, manager: str, unnamed: bool = False) -> bool:
    if instance.name == manager:
        return True
    # a manager the launch file does not name runs under the name its code gives it,
    # controller_manager (ros2_control_node's): ``/ns/?`` when that is not known, or a
    # name guessed from its executable
    return ((unnamed or instance.name.rsplit("/", 1)[-1] == UNKNOWN_MARK)
            and namespace_of(instance.name) == namespace_of(manager)
            and manager.rsplit("/", 1)[-1] == MANAGER_NAME)


def _spawned(host: NodeInstance, started: Sequence[tuple[NodeDecl, NodeInstance]],
             params: Params, workspace: Workspace,
             config: Configuration, unnamed: bool = False,
             served: set[int] | None = None) -> Iterator[Choice]:
    """The controllers the spawners of the configuration load into ``host``; ``served``
    gets the ``id`` of each spawner declaration that loads into it."""
    for decl, instance in started:
        spawn = _spawn_of(decl)
        if spawn is None or not _serves(host, _manager_name(decl, spawn.manager), unnamed):
            continue
        if served is not None:
            served.add(id(decl))
        manager = host.name if UNKNOWN_MARK not in host.name and not unnamed else \
            _manager_name(decl, spawn.manager)
        yield from _spawn_choices(decl, instance, spawn, host.namespace, manager,
                                  manager == host.name, params, workspace, config)


def _spawn_choices(decl: NodeDecl, instance: NodeInstance, spawn: Spawn, namespace: str,
                   manager: str, manager_seen: bool, params: Params,
                   workspace: Workspace, config: Configuration) -> Iterator[Choice]:
    """The controllers one spawner loads into the manager ``manager``, whose namespace
    is ``namespace``, with the parameters its files give each set as launch sets them
    (and the manager's ``<name>.type`` on the manager when ``manager_seen``: an
    instance has its name)."""
    # each with the file read (``share.file_setting``), as a node's parameter file's
    # setting is named (``launch.ros2.nodes``: ``/**`` entries are a setting for
    # every node the file is given to)
    documents = [(*doc, file_setting(workspace, path)) for path in spawn.param_files
                 if (doc := _param_file(path, decl, workspace, config)) is not None]
    namespace = namespace.rstrip("/")
    for controller in spawn.controllers[:MAX_PLUGINS]:
        node_name = f"{namespace}/{controller}"
        own: dict[str, Any] = {}
        managed: dict[str, Any] = {}  # the spawner sets <name>.type on the manager
        placed: dict[str, Location] = {}
        # a ``/**`` entry of a file the spawner gives is a setting for every node the
        # file is given to, as a launch file's (by the file: elkapod_core's
        # controllers.launch.py gives elkapod_motion_manager.yaml to its manager's
        # node and, by ``--param-file``, to elkapod_gait_controller)
        shared: dict[str, str] = {}
        for document, at, keys, source in documents:
            given = params_for_node(document, node_name)
            own.update(given)
            every = for_every_node(document, node_name)
            for key, _ in given:
                if key in every:
                    shared[key] = source
                else:
                    shared.pop(key, None)
            managed.update((key, value) for key, value in params_for_node(
                document, manager) if key == f"{controller}.type")
            for owner in (node_name, manager):
                placed.update((f"{owner}/{key}", replace(at, line=line))
                              for key, line in params_for_node(keys, owner)
                              if isinstance(line, int))
        where = documents[0][1] if documents else decl.location
        _set_params(params, node_name, own, where, instance.conditions, placed,
                    settings=shared)
        if manager_seen:  # else no instance has the manager's real name
            _set_params(params, manager, managed, where, instance.conditions, placed)
        # the controller's class is said where its type is written
        where = placed.get(f"{node_name}/type") or placed.get(
            f"{manager}/{controller}.type") or where
        typed = _parameter(params, f"{manager}/{controller}.type")
        cls = spawn.controller_type or _text(own.get("type")) or _text(
            managed.get(f"{controller}.type")) or (_text(typed.value) if typed else None)
        reads = (f"{node_name}/type",) if "type" in own else (
            (typed.name,) if typed else ())
        if typed is not None and not _text(own.get("type")) and not managed:
            where = typed.launch_location
        remaps = parse_ros_args(spawn.ros_args, controller).remaps
        yield Choice(controller, cls, where, instance.conditions, reads, tuple(remaps))


def unmanaged_controllers(config: Configuration,
                          started: Sequence[tuple[NodeDecl, NodeInstance]],
                          served: set[int], index: Mapping[str, Node], params: Params,
                          workspace: Workspace, models: PluginModels | None,
                          owned: set[int]) -> list[tuple[NodeInstance, list[PrimitiveCall]]]:
    """The ROS 2 controllers spawners load into a manager no host instance of the
    configuration is (Gazebo's gz_ros2_control started by a launch file not read here,
    as elkapod_core's simulation does; a ros2_control_node another launch file runs; a
    manager of unknown interface): the controller runs all the same once that manager
    is up, so it is a node instance of its own, ``<manager's namespace>/<name>``, as a
    ROS 1 controller is (``ros1_controllers``), with the spawner's parameter files and
    remaps, its class's calls (of unknown interface when its class is not found or not
    known: the manager's own files, not seen, may name it), and a launch parameter
    ``<name>/?``: those files may give it parameters not seen. Not so when a node of
    the manager's name is in the configuration, its interface wholly known, and no
    manager: the spawner finds no manager there."""
    out: list[tuple[NodeInstance, list[PrimitiveCall]]] = []
    host = host_of(*MANAGER_NODE, 2)
    slot = next((s for s in host.slots if s.names == SPAWNER), None) if host else None
    for decl, spawner in started:
        spawn = _spawn_of(decl)
        if spawn is None or decl.ros_version != 2 or id(decl) in served:
            continue
        manager = _manager_name(decl, spawn.manager)
        if any(n.name == manager and n.is_complete for n in config.nodes):
            # a node of that name whose interface is wholly known, and no manager: the
            # spawner finds no ``load_controller`` there, and nothing is loaded
            continue
        for choice in list(_spawn_choices(decl, spawner, spawn, namespace_of(manager),
                                          manager, False, params, workspace, config)):
            full = f"{namespace_of(manager).rstrip('/')}/{choice.name}"
            node = _lookup(choice, index, workspace, models)
            if node is None and choice.cls and UNKNOWN_MARK not in choice.cls:
                config.diagnostics.append(_not_found(choice, manager))
            reader = _controller_instance(config, full, node, manager, choice,
                                          ros_version=2)
            reader.remaps = list(choice.remaps)
            unseen = params.get(Parameter, f"{full}/{UNKNOWN_MARK}")
            assert isinstance(unseen, Parameter)
            if not unseen.set_by_launch:
                unseen.set_by_launch = True
                unseen.launch_location = decl.location
                unseen.launch_conditions = choice.conditions
            if node is not None:
                _unhosted(reader, owned)
                out.append((reader, list(_with_base(node, index, workspace, models))))
            if slot is not None and slot.declares:
                out.append((reader, [PrimitiveCall(
                    "declare", name, location=choice.location,
                    conditions=choice.conditions, has_default=True, origin="plugin")
                    for name in slot.declares]))
            out.extend(_loading_reads(choice, reader, reader))
    return out


def _param_file(path: str, decl: NodeDecl, workspace: Workspace,
                config: Configuration) -> tuple[Any, Location, Any] | None:
    """A spawner's parameter file, read with the safe loader from the workspace only,
    with where it is and the line of each of its keys (``safe_yaml.load_with_lines``: a
    finding about a controller's parameter points at its key)."""
    if UNKNOWN_MARK in path or not os.path.isabs(path):
        return None
    if not os.path.isfile(path):  # a path in a package's share folder, as installed
        path = share_source(workspace, path)
    where = workspace.location(path, 1, 0)
    if not os.path.isfile(path) or not workspace.readable(path):
        config.diagnostics.append(diag.make("PLUGIN_PARAM_FILE", decl.location, path=path))
        return None
    text, problems = read_text(path, where)
    config.diagnostics.extend(problems)
    if text is None:
        return None
    try:  # bounded: aliases, nesting, flow brackets; one read gives both
        document, lines = safe_yaml.load_with_lines(text)
    except yaml.YAMLError:
        document = lines = None
    if document is None or not _bounded(document):
        config.diagnostics.append(diag.make("PLUGIN_PARAM_FILE", decl.location, path=path))
        return None
    return document, where, lines


def _bounded(document: Any, limit: int = MAX_PARAM_VALUES) -> bool:
    """Whether the document has at most ``limit`` values when walked as a tree: YAML
    aliases share a value, and a file of aliases to aliases is huge once flattened."""
    stack, seen = [document], 0
    while stack:
        value = stack.pop()
        seen += 1
        if seen > limit:
            return False
        if isinstance(value, dict):
            stack.extend(value.values())
        elif isinstance(value, list):
            stack.extend(value)
    return True


def _set_params(params: Params, node_name: str, values: Mapping[str, Any],
                where: Location, conditions: tuple[Condition, ...],
                placed: Mapping[str, Location] | None = None,
                settings: Mapping[str, str] | None = None) -> None:
    """The controller's parameters from the spawner's file, set as launch sets them;
    ``placed``: where each is written, by full name (else ``where``); ``settings``: the
    setting for several nodes each key comes from, if any (``Parameter.setting``)."""
    for key, value in values.items():
        parameter = params.get(Parameter, f"{node_name}/{key}")
        assert isinstance(parameter, Parameter)
        if parameter.set_by_launch:
            continue
        parameter.value = value
        parameter.set_by_launch = True
        parameter.launch_location = (placed or {}).get(parameter.name, where)
        parameter.launch_conditions = conditions
        parameter.setting = (settings or {}).get(key)


def _plugin_instance(host: NodeInstance, choice: Choice, node: Node | None,
                     config: Configuration, beneath: bool = False) -> NodeInstance:
    """A node instance of its own for a controller loaded into ``host``. It takes the
    remaps of the host's process (launch_ros gives a node's remappings as ``-r from:=to``,
    which rcl applies to every node of the process: open_manipulator remaps the arm
    controller's ``/arm_controller/joint_trajectory`` on ros2_control_node), its own
    (``--controller-ros-args``) over them: they are the controller node's local rules,
    which rcl tries before the process's (remap.c), and it applies the first that
    matches. ``beneath``: the node is made in the namespace of the host's full name
    (``Slot.beneath_host``, in a process without a namespace of its own)."""
    namespace = host.name if beneath else host.namespace
    namespace = namespace if namespace.endswith("/") else namespace + "/"
    name = namespace + choice.name
    remaps = [*choice.remaps, *host.remaps]
    instance = NodeInstance(name, node, namespace=namespace, remaps=remaps,
                            conditions=(*host.conditions, *choice.conditions),
                            location=choice.location, origin="plugin",
                            ros_version=host.ros_version)
    _add_hosted(instance, host, config)
    return instance


def _under(call: PrimitiveCall, plugin: str, conditions: tuple[Condition, ...],
           bases: tuple[str, ...] = (), inner: bool = False) -> PrimitiveCall:
    """The call as the plugin named ``plugin`` makes it on its host: an unknown first
    part of its name (and handle namespace, and the parameter its name comes from) is
    the plugin name, and so is a name that is wholly the string the host passes the
    plugin (``host_named`` by a class of the host's ``bases``: the host calls the plugin
    only through them); the conditions of the choice come first. A name taken from a
    parameter keeps its ``?`` for the value (the graph fills it from the renamed
    parameter) unless the ``?`` is its handle's namespace."""
    name = call.name
    loaded = {base.lstrip(":") for base in bases}
    if call.host_named and plugin and name.lstrip("~/") == UNKNOWN_MARK and (
            loaded & set(call.host_named.split())):
        # wholly the string the host passes the plugin's entry method: its name
        name = name[:-1] + plugin
    elif not call.name_param or (call.handle_namespace and name.startswith(
            call.handle_namespace + "/")):
        name = _named(name, plugin, inner)
    given = call.loads_given
    if call.loads is not None and given is None and name != call.name and (
            call.name.count(UNKNOWN_MARK) == 1):
        given = plugin  # the class this read loads is given the plugin's name
    return replace(call, name=name, host_named=None, host_handle=None, loads_given=given,
                   handle_namespace=_named(call.handle_namespace, plugin, inner),
                   name_param=_named(call.name_param, plugin, inner),
                   conditions=(*conditions, *call.conditions))


def _host_handled(call: PrimitiveCall, host: Node | None) -> PrimitiveCall:
    """The call of a plugin made on the handle its host's call of an entry method gives
    it (``host_handle``: ``initialize(ros::NodeHandle nh, ...)``, which the host calls
    through the base class it loads it by), in the namespace of the handle the host
    passes there (``Node.handles_given``: ``plugin->initialize(nh_, nhp_)``, ``nh_`` the
    node's public handle, ``nhp_`` its private one): its ``?`` is that namespace. Kept
    when the host passes no handle known there, or handles of several namespaces."""
    if not call.host_handle or host is None or not host.handles_given:
        return call
    values = {value for key in call.host_handle.split()
              for value in host.handles_given.get(key, ())}
    if len(values) != 1 or call.name.count(UNKNOWN_MARK) < 1 or not (
            call.name == UNKNOWN_MARK or call.name.startswith(UNKNOWN_MARK + "/")):
        return call
    value = values.pop()
    if UNKNOWN_MARK in value:
        return call

    def placed(name: str | None) -> str | None:
        if name is None or not (name == UNKNOWN_MARK or name.startswith(UNKNOWN_MARK + "/")):
            return name
        rest = name[len(UNKNOWN_MARK) + 1:]
        if not rest:
            return value or None
        if not value:
            return rest
        return value + rest if value == "~" or value.endswith("/") else f"{value}/{rest}"

    name = placed(call.name) or call.name
    return replace(call, name=name, host_handle=None,
                   handle_namespace=placed(call.handle_namespace) if (
                       call.handle_namespace) else call.handle_namespace)


def _moved(name: str, namespace: str) -> str:
    """A private name (``~x``, ``~/x``) moved into ``namespace`` of the host's private
    one; other names as they are."""
    if not name.startswith("~"):
        return name
    return "~" + namespace.strip("/") + "/" + name[1:].lstrip("/")


def _named(name: str | None, plugin: str, inner: bool = False) -> Any:
    """``name`` with its unknown first part the plugin name; a plugin name in the host's
    private namespace (``~ns``, ``~``: a MoveIt pipeline's) is that whether the call's
    handle was private or not (the namespace the host passes is absolute). ``inner``:
    the plugin is ``<outer>.<own>`` of a plugin's own slot (``Slot.inner``), whose
    names' first unknown part is the outer plugin's name and the next its own."""
    if name is None or not plugin:
        return name
    if inner and "." in plugin:
        outer, own = plugin.rsplit(".", 1)
        first = _named(name, outer)
        if first == name:
            return name
        cut = first.index(outer) + len(outer)
        rest = first[cut:]
        if rest[:1] in (".", "/") and rest[1:2] == UNKNOWN_MARK and rest[2:3] in (
                ".", "/") and len(rest) > 3:
            return first[:cut] + rest[0] + own + rest[2:]
        return first
    for lead in ("~/", "~", ""):
        if name.startswith(lead + UNKNOWN_MARK):
            rest = name[len(lead) + 1:]
            # a prefix only: a name that is wholly unknown is not the plugin name
            if rest[:1] in ("/", ".") and len(rest) > 1:
                if plugin.startswith("~"):
                    below = plugin.lstrip("~/")
                    return "~" + (below + rest if below else rest[1:])
                return lead + plugin + rest
    return name



# -- names taken from a plugin's source list (costmap observation sources) ---------------


def _per_source(calls: list[PrimitiveCall], row: Sources, plugin: str, choice: Choice,
                instance: NodeInstance, node: Node, params: Params, workspace: Workspace,
                ) -> list[PrimitiveCall]:
    """The plugin's calls with one copy per listed source of those made under
    ``<plugin>.<source>`` (``obstacle_layer.?.topic``), and a subscription per source
    instead of the plugin's subscriptions to topics it could not name. Without a value
    for the list the calls stay as they are; with an unknown one a subscription to an
    unknown topic says so."""
    base = instance.name.rstrip("/") + "/"
    keys = choice.moved_from or plugin  # where the launch files set the sources
    listed = _parameter(params, base + row.names.format(plugin=keys))
    if listed is None:
        return calls
    conditions = (*choice.conditions, *listed.launch_conditions)
    if not isinstance(listed.value, str):
        return [*calls, PrimitiveCall("subscribe", UNKNOWN_MARK, location=listed.launch_location,
                                      conditions=conditions, origin="plugin")]
    sources = listed.value.split()[:MAX_PLUGINS]
    separator = "." if instance.ros_version == 2 else "/"
    marks = [lead + plugin + separator + UNKNOWN_MARK + separator for lead in ("", "~", "~/")]
    out: list[PrimitiveCall] = []
    for call in calls:
        if call.kind == "subscribe" and call.name.lstrip("~/") == UNKNOWN_MARK:
            continue  # a source's subscription, named by its topic below
        mark = next((m for m in marks if call.name.startswith(m)), None)
        if mark is None:
            out.append(call)
            continue
        # each copy is one turn of the loop over the sources: made, not under the loop
        # (obstacle_layer.cpp's ``while (ss >> source)``)
        turn = tuple(c for c in call.conditions if c.statement not in _LOOPS)
        for source in sources:  # an empty list: the code reads none of them
            out.append(replace(call, name=_source_named(call.name, mark, source),
                               handle_namespace=_source_named(call.handle_namespace, mark,
                                                              source),
                               name_param=_source_named(call.name_param, mark, source),
                               conditions=turn))
    parent = _parent_rule(row, node, workspace)
    for source in sources:
        topic_key = base + row.topic.format(plugin=keys, source=source)
        type_key = base + row.data_type.format(plugin=keys, source=source)
        topic_param, type_param = _parameter(params, topic_key), _parameter(params, type_key)
        topic = source if topic_param is None else _text(topic_param.value) or UNKNOWN_MARK
        data_type = row.default_type if type_param is None else _text(type_param.value)
        if parent and not topic.startswith(("/", UNKNOWN_MARK)):
            namespace = instance.namespace.rstrip("/")
            topic = namespace[:namespace.rfind("/")] + "/" + topic
        given = topic_param or listed
        out.append(PrimitiveCall(
            "subscribe", topic, dict(row.types).get(data_type or ""),
            location=given.launch_location,
            conditions=(*conditions, *(topic_param.launch_conditions if topic_param else ())),
            origin="plugin"))
        # the plugin reads them where it is, after a pre-Hydro costmap moved them there
        # (the host's read of the source's namespace whole is what reads them where the
        # launch files set them)
        for read in (row.topic.format(plugin=plugin, source=source),
                     row.data_type.format(plugin=plugin, source=source)):
            name = read if instance.ros_version == 2 else "~" + read
            if not any(c.kind == "read" and c.name == name for c in out):
                out.append(PrimitiveCall("read", name, location=given.launch_location,
                                         conditions=conditions, origin="plugin"))
    return out


_LOOPS = frozenset({"while", "for", EACH_STATEMENT})


def _source_named(name: str | None, mark: str, source: str) -> Any:
    """``layer.?.topic`` (or the handle ``~layer/?``) with ``?`` the source's name."""
    if name is not None and name == mark[:-1]:
        return mark[:-2] + source
    if name is None or not name.startswith(mark):
        return name
    return mark[:-2] + source + name[len(mark) - 1:]


def _parent_rule(row: Sources, node: Node, workspace: Workspace) -> bool:
    """Whether the plugin's version resolves relative topics in the parent namespace."""
    if row.parent_since is None:
        return False
    numbers = _version(node, workspace)
    return bool(numbers) and numbers >= row.parent_since


def _version(node: Node, workspace: Workspace) -> tuple[int, ...]:
    """The version of the node's package: the workspace's package.xml, else its
    interface model's; () when neither tells."""
    package = workspace.packages.get(node.package)
    version = package.version if package is not None else (
        node.model.split()[1] if node.model and len(node.model.split()) > 1 else "")
    return tuple(int(part) for part in (version or "").split(".")[:3] if part.isdigit())


def _older(version: tuple[int, ...], since: tuple[int, ...]) -> bool:
    """A version known and older than ``since``."""
    return bool(version) and version < since


# -- ROS 1 ros_control ------------------------------------------------------------------


def ros1_spawn_args(decl: NodeDecl) -> tuple[list[str], str]:
    """The controllers a ROS 1 ``spawner`` (or ``controller_manager spawn|load``) names,
    and its ``--namespace`` (the controller manager's, "" when not given)."""
    words = shell_words(decl.args)
    if decl.executable == "controller_manager":
        if not words or words[0] not in ("spawn", "load"):
            return [], ""
        words = words[1:]
    takes_value = {"--wait-for", "--namespace", "--timeout", "--shutdown-timeout"}
    controllers: list[str] = []
    namespace = ""
    index = 0
    while index < len(words):
        word = words[index]
        option, _, value = word.partition("=")
        if option in takes_value:
            if not value:
                value = words[index + 1] if index + 1 < len(words) else ""
                index += 1
            if option == "--namespace":
                namespace = value
        elif not word.startswith("-"):
            controllers.append(word)
        index += 1
    return controllers, namespace


def ros1_controllers(config: Configuration, started: Sequence[tuple[NodeDecl, NodeInstance]],
                     index: Mapping[str, Node], params: Params, workspace: Workspace,
                     models: PluginModels | None, owned: set[int],
                     ) -> list[tuple[NodeInstance, list[PrimitiveCall]]]:
    """The controllers ROS 1 spawners load. The controller manager answers at
    ``<namespace>/controller_manager/load_controller`` (the spawner's ``--namespace``,
    in its own namespace) and loads controller ``c`` with the class ``<namespace>/c/type``
    and the handle ``<namespace>/c``. The instance that serves that service hosts the
    controller's calls; when the configuration has none (the manager lives in Gazebo or
    in a hardware node started elsewhere) the controller is a node instance of its own,
    ``<namespace>/c``, standing for its part of that unknown process."""
    out: list[tuple[NodeInstance, list[PrimitiveCall]]] = []
    for decl, spawner in started:
        if decl.ros_version != 1 or (decl.package, decl.executable) not in ROS1_SPAWNERS:
            continue
        words, given = ros1_spawn_args(decl)
        controllers = _ros1_spawn_files(words, decl, spawner, params, workspace, config)
        manager = resolve(given, spawner.namespace, spawner.name)
        host = _serving(config, manager.rstrip("/") + "/controller_manager/load_controller")
        for controller in controllers[:MAX_PLUGINS]:
            full = f"{manager.rstrip('/')}/{controller}"
            typed = _parameter(params, full + "/type")
            if typed is None and host is not None and _set_nowhere(config, params,
                                                                   full + "/type"):
                # no class, and nothing we could miss may give one: the manager reads
                # ``<c>/type``, finds none and refuses to load the controller ("the type
                # was not specified", controller_manager.cpp loadController), so it
                # makes no calls and leaves its host as it was; the read stays, for
                # parameter-read-not-set to say (UR's velocity_based_... controller of a
                # YAML file that names it vel_based_...), beside PLUGIN_CLASS_UNKNOWN
                config.diagnostics.append(_not_found(
                    Choice(controller, None, decl.location, spawner.conditions), host.name))
                out.append((host, [PrimitiveCall(
                    "read", _relative(full + "/type", host.namespace),
                    location=decl.location, conditions=spawner.conditions,
                    origin="plugin")]))
                continue
            choice = Choice(controller, _text(typed.value) if typed else None,
                            typed.launch_location if typed else decl.location,
                            (*spawner.conditions, *(typed.launch_conditions if typed else ())),
                            (typed.name,) if typed else ())
            node = _lookup(choice, index, workspace, models)
            reader = host
            if node is None and host is not None:
                _missing(config, host, choice, owned)
                if typed is not None:  # the manager reads the class below its namespace,
                    # on its root handle, as for a class found (UR's driver, whose
                    # scaled_controllers are not in the workspace: no global name)
                    out.append((host, [_class_read(typed, host, choice)]))
                continue
            if node is None:
                config.diagnostics.append(_not_found(choice, spawner.name))
                # a type named but not found: its own instance all the same, of unknown
                # interface, as the controller runs and reads its parameters (unknown
                # is not empty: they are not "set but never read"); with no type the
                # manager refuses to load it (controller_manager.cpp, loadController)
                if typed is not None:
                    reader = _controller_instance(config, full, None, manager, choice)
            elif host is not None:
                # its handle is ``<manager>/<name>``, whatever the host's own namespace
                # (Gazebo's plugin managers live in /gazebo, in the robot's namespace)
                out.append((host, [_under(_on_root(c, manager, host), _relative(
                    full, host.namespace), choice.conditions) for c in node.calls]))
                if typed is not None:  # the manager reads the class, below its namespace
                    out.append((host, [_class_read(typed, host, choice)]))
                continue
            else:
                reader = _controller_instance(config, full, node, manager, choice)
                out.append((reader, [_under(c, controller, ()) for c in node.calls]))
            if reader is not None:
                out.extend(_loading_reads(choice, reader, reader))
    return out


def _set_nowhere(config: Configuration, params: Params, name: str) -> bool:
    """Whether the ROS 1 parameter ``name`` is set by nothing the configuration shows
    and by nothing it could miss: no launch parameter or code sets it, no launch
    parameter not known statically may be it (``_may_be_set``), and no include was left
    unread (roslaunch's files may set any name; a node's code writing it would be a
    parameter of that name, set)."""
    if params.by_name.get((Parameter, name)) is not None or _may_be_set(name, params):
        return False
    return not any(item.kind == "include" and not item.skipped
                   for tree in config.launch_tree for item in tree.walk())


def _ros1_spawn_files(words: list[str], decl: NodeDecl, spawner: NodeInstance,
                      params: Params, workspace: Workspace,
                      config: Configuration) -> list[str]:
    """The controllers a ROS 1 spawner's words name. A word that is a file (the spawner
    tests ``os.path.exists``; here an absolute path to a YAML file) is loaded into the
    spawner's namespace (``rosparam.set_param("", file)``) and each of its top-level keys
    is a controller to load (controller_manager/scripts/spawner, noetic): AutoRally's
    simulation spawns ``$(find autorally_gazebo)/config/...JointCtrlrParams.yaml``. Its
    parameters are set as a launch file sets them, each at its key's line."""
    out: list[str] = []
    for word in words:
        if UNKNOWN_MARK in word or not os.path.isabs(word) or not word.endswith(
                (".yaml", ".yml")):
            out.append(word)
            continue
        loaded = _param_file(word, decl, workspace, config)
        if loaded is None:
            continue  # said (PLUGIN_PARAM_FILE)
        document, where, keys = loaded
        if not isinstance(document, dict):
            config.diagnostics.append(diag.make("PLUGIN_PARAM_FILE", decl.location,
                                                path=word))
            continue
        prefix = spawner.namespace.rstrip("/")
        placed = {f"{prefix}/{key}": replace(where, line=line)
                  for key, line in ros1_flatten("", keys or {}) if isinstance(line, int)}
        _set_params(params, prefix, dict(ros1_flatten("", document)), where,
                    spawner.conditions, placed)
        out.extend(str(key) for key in document)
    return out


def _controller_instance(config: Configuration, full: str, node: Node | None, manager: str,
                         choice: Choice, ros_version: int = 1) -> NodeInstance:
    """The node instance ``full`` a controller loaded by a manager the configuration
    does not start stands for (of unknown interface when its class is not found): in
    the manager's namespace (ROS 1: the manager's own name is the namespace of its
    controllers' handles; ROS 2: ``manager`` is the manager node's full name)."""
    namespace = (manager if ros_version == 1 else namespace_of(manager)).rstrip("/") + "/"
    instance = NodeInstance(full, node, namespace=namespace, conditions=choice.conditions,
                            location=choice.location, origin="plugin",
                            ros_version=ros_version, host_unseen=ros_version == 1)
    taken = sum(1 for n in config.nodes if n.name == full)
    instance.id = f"node:{full}" + (f"#{taken + 1}" if taken else "")
    config.nodes.append(instance)
    return instance


def _on_root(call: PrimitiveCall, manager: str, host: NodeInstance) -> PrimitiveCall:
    """A controller's call on its root handle (``PrimitiveCall.root_handle``) as its
    host makes it: a relative name is in the manager's namespace, which need not be the
    host's (Gazebo's ``/gazebo`` hosts ``/uav1``'s manager)."""
    manager = manager.rstrip("/")
    if not call.root_handle or call.name.startswith(("/", "~")) or (
            manager == host.namespace.rstrip("/")):
        return call
    prefix = _relative(manager or "/", host.namespace)
    return replace(call, name=prefix.rstrip("/") + "/" + call.name)


def _class_read(typed: Parameter, host: NodeInstance, choice: Choice) -> PrimitiveCall:
    """A controller manager's read of a controller's ``type``, on its root handle."""
    return PrimitiveCall("read", _relative(typed.name, host.namespace),
                         location=choice.location, conditions=choice.conditions,
                         origin="plugin")


def _relative(full: str, namespace: str) -> str:
    """``full`` as a name relative to ``namespace`` when it is below it, as the
    controller manager writes ``<controller>/type`` on its root handle; else ``full``."""
    prefix = namespace.rstrip("/") + "/"
    return full[len(prefix):] if full.startswith(prefix) and len(full) > len(prefix) else full


def _serving(config: Configuration, service: str) -> NodeInstance | None:
    """The node instance that serves ``service``, if the configuration has one."""
    return next((link.node for link in config.links
                 if link.kind == "server" and link.resource.name == service), None)
