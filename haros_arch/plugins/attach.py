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

A plugin whose class is not known, or not found in the workspace, is a diagnostic at the
parameter that names it, and the host instance becomes partial: it gets its own copy of
its node model (node models are shared by instances) marked partial with the reason.
"""

from __future__ import annotations

import copy
import os
import shlex
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any, Protocol

import yaml

from .. import diagnostics as diag
from .. import safe_yaml
from ..files import read_text
from ..launch.model import NodeDecl
from ..launch.ros2.naming import params_for_node, parse_ros_args
from ..model.conditions import Condition
from ..model.location import Location
from ..model.rosname import namespace_of
from ..model.runtime import Configuration, NodeInstance, Parameter, Resource
from ..model.source import Node, PrimitiveCall
from ..model.values import UNKNOWN_MARK
from ..share import share_source
from ..workspace import Workspace
from .hosts import SPAWNER, Slot, host_of

SPAWNERS = (("controller_manager", "spawner"), ("controller_manager", "spawner.py"))
MANAGER_NAME = "controller_manager"
_ROS_ARG_FLAGS = ("-r", "--remap", "-p", "--param", "--params-file")
MAX_PLUGINS = 200  # per slot: a hostile list stays bounded
MAX_PARAM_VALUES = 100_000  # values in one spawner parameter file, aliases counted out


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


def attach(config: Configuration, started: Sequence[tuple[NodeDecl, NodeInstance]],
           nodes: Mapping[str, Node], params: Params, workspace: Workspace,
           ) -> list[tuple[NodeInstance, list[PrimitiveCall]]]:
    """The plugin calls each host instance (or a plugin's own instance) makes; plugin
    instances are added to ``config.nodes``, problems to ``config.diagnostics``."""
    index = plugin_index(nodes)
    owned: set[int] = set()  # instances that have their own copy of their node model
    made: dict[int, set[tuple[Any, ...]]] = {}  # per host instance: calls it has
    out: list[tuple[NodeInstance, list[PrimitiveCall]]] = []
    for decl, instance in started:
        host = host_of(decl.package, decl.executable, decl.ros_version)
        if host is None:
            continue
        for slot in host.slots:
            if slot.names == SPAWNER:
                choices = list(_spawned(instance, started, params, workspace, config,
                                        unnamed=decl.name_guessed))
            else:
                choices = list(_chosen(instance, slot, params))
            for choice in choices:
                node = _lookup(choice, index)
                reader = instance
                if node is None:
                    _missing(config, instance, choice, owned)
                elif slot.placement == "node":
                    reader = _plugin_instance(instance, choice, node, config)
                    out.append((reader, list(node.calls)))
                else:
                    calls = [_under(call, slot.prefix + _given(choice, slot),
                                    choice.conditions) for call in node.calls]
                    out.append((instance, _new(calls, instance, made)))
                out.extend(_loading_reads(choice, instance, reader))
    return out


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


def plugin_index(nodes: Mapping[str, Node]) -> dict[str, Node]:
    """Plugin nodes by pluginlib lookup name and by C++ type."""
    index: dict[str, Node] = {}
    for node in nodes.values():
        if node.kind != "plugin":
            continue
        index.setdefault(node.executable, node)
        if node.plugin_class:
            index.setdefault(node.plugin_class.lstrip(":"), node)
    return index


def _lookup(choice: Choice, index: Mapping[str, Node]) -> Node | None:
    """The plugin node of the chosen class, by its lookup name or its C++ type."""
    if not choice.cls or UNKNOWN_MARK in choice.cls:
        return None
    return index.get(choice.cls.strip().lstrip(":"))


def _given(choice: Choice, slot: Slot) -> str:
    """The plugin name the host initialises the plugin with."""
    if slot.name_from_class and choice.cls:
        return choice.cls.rsplit("/", 1)[-1].rsplit("::", 1)[-1]
    return choice.name


def _missing(config: Configuration, instance: NodeInstance, choice: Choice,
             owned: set[int]) -> None:
    if not choice.cls or UNKNOWN_MARK in choice.cls:
        found = diag.make("PLUGIN_CLASS_UNKNOWN", choice.location, plugin=choice.name,
                          host=instance.name)
    else:
        found = diag.make("PLUGIN_NOT_FOUND", choice.location, plugin=choice.cls,
                          host=instance.name)
    config.diagnostics.append(found)
    where = choice.location
    own_partial(instance, f"{found.message} ({where.file}:{where.line})", owned)


def own_partial(instance: NodeInstance, reason: str, owned: set[int]) -> None:
    """Mark ``instance`` partial without touching the node model other instances share:
    the instance gets its own copy first (``owned`` holds the ids of those that have)."""
    if instance.node is None:
        return
    if id(instance) not in owned:
        node = copy.copy(instance.node)
        node.completeness_reasons = list(node.completeness_reasons)
        instance.node = node
        owned.add(id(instance))
    instance.node.mark_partial(reason)


def _parameter(params: Params, name: str) -> Parameter | None:
    found = params.by_name.get((Parameter, name))
    if isinstance(found, Parameter) and found.set_by_launch:
        return found
    return None


def _chosen(instance: NodeInstance, slot: Slot, params: Params) -> Iterator[Choice]:
    """The plugins a host slot names, from the instance's parameters or the defaults."""
    base = instance.name.rstrip("/") + "/"
    if slot.names is None:
        assert slot.type_of is not None
        given = _parameter(params, base + slot.type_of)
        if given is not None:
            yield Choice("", _text(given.value), given.launch_location,
                         given.launch_conditions, (given.name,))
        else:
            for default, default_cls in slot.defaults:
                yield Choice(default, default_cls, instance.location)
        return
    listed = _parameter(params, base + slot.names)
    where: Location
    conditions: tuple[Condition, ...]
    if listed is None:
        entries: list[Any] = [name for name, _ in slot.defaults]
        where, conditions = instance.location, ()
    else:
        value = listed.value
        entries = list(value) if isinstance(value, list) else [value]
        where, conditions = listed.launch_location, listed.launch_conditions
    listing = (listed.name,) if listed is not None else ()
    for entry in entries[:MAX_PLUGINS]:
        if isinstance(entry, dict):  # ROS 1: {name: ..., type: ...}
            yield Choice(_text(entry.get("name")) or UNKNOWN_MARK, _text(entry.get("type")),
                         where, conditions, listing)
            continue
        name = _text(entry) or UNKNOWN_MARK
        cls = dict(slot.defaults).get(name)
        parameter = base + (slot.type_of or "").format(name=name)
        typed = _parameter(params, parameter) if slot.type_of else None
        if typed is not None:
            yield Choice(name, _text(typed.value), typed.launch_location,
                         (*conditions, *typed.launch_conditions), (*listing, parameter))
        else:
            yield Choice(name, cls, where, conditions, listing)


def _text(value: Any) -> str | None:
    return value if isinstance(value, str) and value else None


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
    try:
        words = shlex.split(decl.args)
    except ValueError:
        words = decl.args.split()
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
             config: Configuration, unnamed: bool = False) -> Iterator[Choice]:
    """The controllers the spawners of the configuration load into ``host``."""
    for decl, instance in started:
        if (decl.package, decl.executable) not in SPAWNERS:
            continue
        spawn = spawn_args(decl)
        if not _serves(host, _manager_name(decl, spawn.manager), unnamed):
            continue
        documents = [doc for path in spawn.param_files
                     if (doc := _param_file(path, decl, workspace, config)) is not None]
        namespace = host.namespace.rstrip("/")
        manager = host.name if UNKNOWN_MARK not in host.name and not unnamed else \
            _manager_name(decl, spawn.manager)
        for controller in spawn.controllers[:MAX_PLUGINS]:
            node_name = f"{namespace}/{controller}"
            own: dict[str, Any] = {}
            managed: dict[str, Any] = {}  # the spawner sets <name>.type on the manager
            for document, _ in documents:
                own.update(params_for_node(document, node_name))
                managed.update((key, value) for key, value in params_for_node(
                    document, manager) if key == f"{controller}.type")
            where = documents[0][1] if documents else decl.location
            _set_params(params, node_name, own, where, instance.conditions)
            if manager == host.name:  # else no instance has the manager's real name
                _set_params(params, manager, managed, where, instance.conditions)
            typed = _parameter(params, f"{manager}/{controller}.type")
            cls = spawn.controller_type or _text(own.get("type")) or _text(
                managed.get(f"{controller}.type")) or (_text(typed.value) if typed else None)
            reads = (f"{node_name}/type",) if "type" in own else (
                (typed.name,) if typed else ())
            if typed is not None and not _text(own.get("type")) and not managed:
                where = typed.launch_location
            remaps = parse_ros_args(spawn.ros_args, controller).remaps
            yield Choice(controller, cls, where, instance.conditions, reads, tuple(remaps))


def _param_file(path: str, decl: NodeDecl, workspace: Workspace,
                config: Configuration) -> tuple[Any, Location] | None:
    """A spawner's parameter file, read with the safe loader from the workspace only."""
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
    try:
        document = safe_yaml.load(text)  # bounded: aliases, nesting, flow brackets
    except yaml.YAMLError:
        document = None
    if document is None or not _bounded(document):
        config.diagnostics.append(diag.make("PLUGIN_PARAM_FILE", decl.location, path=path))
        return None
    return document, where


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
                where: Location, conditions: tuple[Condition, ...]) -> None:
    """The controller's parameters from the spawner's file, set as launch sets them."""
    for key, value in values.items():
        parameter = params.get(Parameter, f"{node_name}/{key}")
        assert isinstance(parameter, Parameter)
        if parameter.set_by_launch:
            continue
        parameter.value = value
        parameter.set_by_launch = True
        parameter.launch_location = where
        parameter.launch_conditions = conditions


def _plugin_instance(host: NodeInstance, choice: Choice, node: Node,
                     config: Configuration) -> NodeInstance:
    """A node instance of its own for a controller loaded into ``host``."""
    namespace = host.namespace if host.namespace.endswith("/") else host.namespace + "/"
    name = namespace + choice.name
    instance = NodeInstance(name, node, namespace=namespace, remaps=list(choice.remaps),
                            conditions=(*host.conditions, *choice.conditions),
                            location=choice.location, origin="plugin",
                            ros_version=host.ros_version)
    taken = sum(1 for n in config.nodes if n.name == name)
    instance.id = f"node:{name}" + (f"#{taken + 1}" if taken else "")
    config.nodes.append(instance)
    return instance


def _under(call: PrimitiveCall, plugin: str, conditions: tuple[Condition, ...],
           ) -> PrimitiveCall:
    """The call as the plugin named ``plugin`` makes it on its host: an unknown first
    part of its name (and handle namespace, and the parameter its name comes from) is
    the plugin name; the conditions of the choice come first. A name taken from a
    parameter keeps its ``?`` for the value (the graph fills it from the renamed
    parameter) unless the ``?`` is its handle's namespace."""
    name = call.name
    if not call.name_param or (call.handle_namespace and name.startswith(
            call.handle_namespace + "/")):
        name = _named(name, plugin)
    return replace(call, name=name, handle_namespace=_named(call.handle_namespace, plugin),
                   name_param=_named(call.name_param, plugin),
                   conditions=(*conditions, *call.conditions))


def _named(name: str | None, plugin: str) -> Any:
    if name is None or not plugin:
        return name
    for lead in ("~/", "~", ""):
        if name.startswith(lead + UNKNOWN_MARK):
            rest = name[len(lead) + 1:]
            # a prefix only: a name that is wholly unknown is not the plugin name
            if rest[:1] in ("/", ".") and len(rest) > 1:
                return lead + plugin + rest
    return name

