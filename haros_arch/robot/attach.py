"""Give the Gazebo node instance the calls of the plugins of the descriptions it spawns.

A configuration that starts a spawner (ROS 1 ``gazebo_ros spawn_model``, ROS 2
``gazebo_ros spawn_entity.py``) hands Gazebo a robot description: the parameter its
``-param`` names (set by launch with ``command="xacro file.urdf.xacro args"``), or the
file its ``-file`` names. The description is expanded by ``robot.xacro`` (never run) and
each ``<plugin filename=...>`` in it looked up in ``robot.gazebo_plugins``:

- ROS 1: the plugin's topics and services become calls of the gazebo node instance,
  named in the namespace the plugin's ``<robotNamespace>`` gives (the spawner's
  ``-robot_namespace``, its own namespace by default, fills it where absent);
- ROS 2: each plugin is a node of its own (``gazebo_ros::Node``), named by the plugin,
  in ``<ros><namespace>`` with the ``<ros><remapping>`` rules; a node instance is made.

The gazebo instance is the ``gazebo_ros`` gzserver / gazebo node the configuration
starts, or, when it starts none (Gazebo launched from an installed package), one named
``/gazebo`` made here with an unknown interface. A plugin library not in the table is a
diagnostic at the plugin's element and leaves the gazebo instance partial; so do parts
of the description that cannot be known. The description as read is kept in
``Configuration.robot_descriptions``.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field, replace
from functools import partial
from typing import Any, NamedTuple, cast

import yaml
from lxml import etree

from .. import diagnostics as diag
from .. import safe_yaml
from ..extract.cpp.api import CONTROLLER_MANAGER_SERVICES
from ..extract.cpp.headers import FALLBACK
from ..files import read_text
from ..launch.model import LaunchModel, NodeDecl, ParamDecl, shell_words
from ..launch.ros2.naming import (
    MAX_PARAM_DEPTH,
    PARAMS_KEY,
    ParamFileLoader,
    params_for_node,
    pattern_matches,
    split_rule,
)
from ..model.conditions import Condition, undecided
from ..model.location import NOWHERE, Location
from ..model.robot import DescribedControl, DescribedPlugin, RobotDescription
from ..model.rosname import as_namespace, clean, is_ros2_node_name, namespace_of, resolve
from ..model.runtime import Configuration, NodeInstance, Parameter
from ..model.source import SDF_ELEMENT, CallKind, Node, PrimitiveCall
from ..model.values import UNKNOWN_MARK, Value
from ..models.commands import split_options
from ..plugins.attach import Choice, Params, own_partial, process_file_params
from ..plugins.classes import INCLUDE, remembered
from ..share import share_source
from ..workspace import Workspace
from . import xacro
from .bridge import bridges
from .gazebo_plugins import (
    MULTICAMERA_SIDES,
    Entity,
    Plugin,
    classic_builtin,
    gz_system,
    library_base,
    plugin_row,
)

FILE = xacro.FILE
SPAWNERS = {("gazebo_ros", "spawn_model"): 1, ("gazebo_ros", "spawn_entity.py"): 2,
            ("ros_gz_sim", "create"): 2, ("ros_ign_gazebo", "create"): 2}
GZ_SPAWNERS = (("ros_gz_sim", "create"), ("ros_ign_gazebo", "create"))
GAZEBO_EXECUTABLES = ("gzserver", "gazebo", "debug", "gzserver_with_gdb", "perf")
GAZEBO_NAME = "/gazebo"
GZSERVER = "gazebo_ros/gzserver"  # what gazebo_ros' launch files start as ``gazebo``
MANAGER = "controller_manager"  # the node ros2_control's Gazebo plugins start
GZ_MANAGERS = ("gz_ros2_control-system", "ign_ros2_control-system")
MAX_PLUGINS = 500  # per description
# spawner options that take a value (``-J`` takes two)
_VALUED = {"-file", "-param", "-topic", "-database", "-model", "-entity", "-robot_namespace",
           "-gazebo_namespace", "-reference_frame", "-x", "-y", "-z", "-R", "-P", "-Y",
           "-timeout", "-package_to_model", "-spawn_service_timeout", "-name", "-world",
           "-string"}


@dataclass
class Spawn:
    decl: NodeDecl
    ros_version: int
    file: str | None = None
    param: str | None = None
    topic: str | None = None
    model: str | None = None
    robot_namespace: str | None = None
    # ``-string``: the command line whose output it is (``Command(["xacro ", file])``)
    command: str | None = None
    string: bool = False


def spawn_args(decl: NodeDecl, ros_version: int) -> Spawn:
    """What a spawner's command line asks for."""
    words = shell_words(decl.args)
    spawn = Spawn(decl, ros_version)
    index = 0
    while index < len(words):
        word = words[index]
        value = words[index + 1] if index + 1 < len(words) else None
        if word == "-J":
            index += 3
            continue
        if word in _VALUED:
            index += 2
            if word == "-file":
                spawn.file = value
            elif word == "-param":
                spawn.param = value
            elif word == "-topic":
                spawn.topic = value
            elif word in ("-model", "-entity", "-name"):
                spawn.model = value
            elif word == "-robot_namespace":
                spawn.robot_namespace = value
            elif word == "-string":
                spawn.string = True
                spawn.command = decl.arg_commands.get(index - 1)
            continue
        index += 1
    return spawn


@dataclass
class Attached:
    """What the descriptions of a configuration add: calls by node instance, and the
    controller managers their ros2_control plugins start (as if a launch file started
    ``ros2_control_node``: the plugin host table then loads their controllers)."""

    calls: list[tuple[NodeInstance, list[PrimitiveCall]]]
    managers: list[tuple[NodeDecl, NodeInstance]]
    # by ``id`` of a controller manager the launch files start: the hardware plugins its
    # robot description names (``hardware``), for the plugin host table's ``DESCRIBED``
    hardware: dict[int, list[Choice]] = field(default_factory=dict)


def attach(config: Configuration, launch: LaunchModel,
           started: Sequence[tuple[NodeDecl, NodeInstance]], workspace: Workspace,
           params: Params, given: Sequence[ParamDecl] = (),
           gzserver: Callable[[], Node | None] | None = None) -> Attached:
    """The calls of the Gazebo plugins of the spawned descriptions, by node instance;
    instances made here are added to ``config.nodes``, the parameters a ros2_control
    plugin's ``<parameters>`` files set to ``params``; and the hardware plugins of the
    descriptions the controller managers read (``given``: the launch parameters by the
    names of the nodes that take them, ``graph.processes.process_params``). ``gzserver``
    finds the node (model) of gazebo_ros' gzserver, the interface of a ``/gazebo`` made
    here for an unread include of gazebo_ros' launch files (ROS 1): its calls come first."""
    out = Attached([], [])
    out.hardware = hardware(config, started, given, workspace)
    owned: set[int] = set()
    made: list[NodeInstance] = []
    for decl, _ in started:
        ros_version = SPAWNERS.get((decl.package, decl.executable))
        if ros_version is None:
            continue
        spawn = spawn_args(decl, ros_version)
        out.calls.extend(diag.per_file(  # a bug of ours in one description: the run goes on
            decl.location, decl.location.file or "", config.diagnostics,
            partial(_spawned, spawn, started, launch, workspace, config, owned, params,
                    out.managers, (gzserver, made)), []))
    out.calls[:0] = [(instance, list(instance.node.calls)) for instance in made
                     if instance.node is not None]
    for decl, instance in started:
        if (decl.package, decl.executable) == WEBOTS_DRIVER and decl.ros_version == 2:
            diag.per_file(decl.location, decl.location.file or "", config.diagnostics,
                          partial(_webots, decl, instance, given, workspace, config,
                                  params, out.managers), None)
    out.calls.extend((instance, list(instance.node.calls)) for _, instance in out.managers
                     if instance.node is not None)
    out.calls.extend(bridges(config, launch, started, workspace))
    _unmade(config, launch, workspace)
    return out


def _unmade(config: Configuration, launch: LaunchModel, workspace: Workspace) -> None:
    """A launch parameter whose xacro (or ``cat``) command names a file of the workspace
    that is not there: the command fails, and roslaunch (or launch, which runs a
    ``Command`` substitution as it gives the node its parameters) stops, whether or not a
    node read here takes the description (kuka_experimental's load_kr60_ha.launch runs
    xacro on ``urdf/kr60_ha.xacro``, the package's file being ``kr60ha.xacro``).
    ROBOT_DESCRIPTION_COMMAND_FAILS at the parameter's line (ROBOT_DESCRIPTION_FILE,
    a warning, under a condition not known), once, unless a description made from it
    said so already, or the launch's reader said roslaunch refuses the element there
    (``textfile=`` of a file that is not there: LAUNCH_BAD_VALUE)."""
    said = {(d.location.file, d.location.line) for d in config.diagnostics
            if d.code in _FILE_CODES} | {(d.location.file, d.location.line)
                                         for d in launch.diagnostics
                                         if d.code == "LAUNCH_BAD_VALUE"}
    for param in launch.params:
        parsed = xacro_command(param.command) if param.command is not None else None
        if parsed is None or UNKNOWN_MARK in parsed.path or not os.path.isabs(parsed.path):
            continue
        path = os.path.abspath(parsed.path)
        where = (param.location.file, param.location.line)
        if not workspace.holds(path) or where in said or os.path.exists(path) or \
                os.path.exists(share_source(workspace, path)):
            continue
        said.add(where)
        config.diagnostics.append(diag.make(
            "ROBOT_DESCRIPTION_COMMAND_FAILS" if _runs(param.conditions)
            else "ROBOT_DESCRIPTION_FILE", param.location, path=workspace.relpath(path),
            detail="no such file"))


# what says that a description file cannot be read
_FILE_CODES = ("ROBOT_DESCRIPTION_FILE", "ROBOT_DESCRIPTION_COMMAND_FAILS")


def _runs(conditions: tuple[Condition, ...]) -> bool:
    """Whether what is under ``conditions`` is loaded wherever the launch runs (no
    condition the configuration leaves undecided)."""
    return not undecided(conditions)


def _spawned(spawn: Spawn, started: Sequence[tuple[NodeDecl, NodeInstance]],
             launch: LaunchModel, workspace: Workspace, config: Configuration,
             owned: set[int], params: Params, managers: list[tuple[NodeDecl, NodeInstance]],
             gazebo: tuple[Callable[[], Node | None] | None, list[NodeInstance]],
             ) -> list[tuple[NodeInstance, list[PrimitiveCall]]]:
    decl = spawn.decl
    if (decl.package, decl.executable) in GZ_SPAWNERS:
        _gz(spawn, launch, workspace, config, params, managers)
        return []
    host = _host(config, started, decl, spawn.ros_version, launch, gazebo)
    made = _description(spawn, launch, workspace, config)
    if made is None:
        own_partial(host, f"the robot description spawned at {decl.location.file}:"
                          f"{decl.location.line} is not known", owned)
        return []
    record, expanded = made
    config.robot_descriptions.append(record)
    for reason in expanded.unknown[:3]:
        own_partial(host, f"robot description: {reason}", owned)
    out: list[tuple[NodeInstance, list[PrimitiveCall]]] = []
    if expanded.root is not None:
        for element in _plugins(expanded.root):
            out.extend(_plugin(element, spawn, host, record, config, workspace, owned,
                               params, managers))
    return out


def _gz(spawn: Spawn, launch: LaunchModel, workspace: Workspace, config: Configuration,
        params: Params, managers: list[tuple[NodeDecl, NodeInstance]]) -> None:
    """A description spawned into gz sim: its systems talk gz transport, not ROS (a
    ros_gz bridge makes their topics ROS topics), so none is a node of the graph; the
    description is kept, and a library that is not a gz system is a diagnostic."""
    made = _description(spawn, launch, workspace, config)
    if made is None:
        return
    record, expanded = made
    config.robot_descriptions.append(record)
    if expanded.root is None:
        return
    for element in _plugins(expanded.root):
        filename = element.get("filename") or ""
        where = _where(element, workspace)
        record.plugins.append(DescribedPlugin(element.get("name") or "", filename, where,
                                              conditions=[c.text for c in _conditions(
                                                  element, where)]))
        reason = gz_system(filename)
        if reason is None:
            reason = workspace_gz_system(filename, workspace)
        if reason is not None and library_base(filename) in GZ_MANAGERS:
            managers.append(_manager(element, spawn, where, _conditions(element, where),
                                     workspace, config, params, gz=True))
        if reason is None:
            found = diag.make("GAZEBO_PLUGIN_UNKNOWN", where, filename=filename,
                              host="gz sim")
            config.diagnostics.append(found)
            _record_partial(record, f"{found.message} ({where.file}:{where.line})")
        elif reason:
            _record_partial(record, f"{filename}: {reason} ({where.file}:{where.line})")


# gz-plugin's registration macros: a library whose sources use one is a gz sim system
_GZ_REGISTRATION = re.compile(r"\b(?:GZ|IGNITION)_ADD_PLUGIN(?:_ALIAS)?\s*\(")
MAX_SYSTEM_SOURCES = 64


def workspace_gz_system(filename: str, workspace: Workspace) -> str | None:
    """For a ``<plugin filename=...>`` that a workspace package builds as a gz sim system
    (a library whose sources register it with ``GZ_ADD_PLUGIN`` / ``IGNITION_ADD_PLUGIN``):
    "" when no source of it uses rclcpp (it talks gz transport only, as the systems gz
    sim ships: leo_gz_plugins' differential system), else why its ROS interface is not
    known; None when no workspace package builds it so."""
    return remembered("gz system", library_base(filename), workspace,
                      lambda: _workspace_gz_system(library_base(filename), workspace))


def _workspace_gz_system(base: str, workspace: Workspace) -> str | None:
    from ..cmake import CMAKE_BUILD_TYPES, targets_of

    for package in workspace.packages.values():
        if package.build_type not in CMAKE_BUILD_TYPES:
            continue
        targets, _ = targets_of(package, workspace)
        for target in targets:
            if target.kind != "library" or (target.output_name or target.name) != base:
                continue
            registered = uses_ros = False
            for source in target.sources[:MAX_SYSTEM_SOURCES]:
                path = source if os.path.isabs(source) else os.path.join(package.root, source)
                if not os.path.isfile(path):
                    continue
                text, _ = read_text(path, workspace.location(path))
                registered = registered or bool(text and _GZ_REGISTRATION.search(text))
                uses_ros = uses_ros or bool(text and "rclcpp" in text)
            if registered:
                return (f"a gz system {package.name} builds that makes ROS calls is not "
                        "read" if uses_ros else "")
    return None


# -- the description --------------------------------------------------------------------
def _description(spawn: Spawn, launch: LaunchModel, workspace: Workspace,
                 config: Configuration,
                 ) -> tuple[RobotDescription, xacro.Description] | None:
    decl = spawn.decl
    if spawn.file is not None:
        path = spawn.file
        if UNKNOWN_MARK in path or not os.path.isabs(path):
            _note(config, decl.location, f"file {path} of the spawner is not known")
            return None
        # the simulator reads the file itself, not through xacro
        return _file_description(path, None, decl.location, workspace, config,
                                 by_xacro=False)
    if spawn.param is not None:
        name = resolve(spawn.param, decl.namespace)
        param = _last_param(launch.params, name)
        if param is None or param.command is None:
            what = "is not set by the launch files" if param is None else \
                "is not given by a xacro command"
            _note(config, decl.location, f"parameter {name} {what}")
            return None
        return _from_command(param.command, name, param.location, workspace, config,
                             _runs(param.conditions))
    if spawn.command is not None:  # ros_gz_sim's -string: the output of a xacro command
        return _from_command(spawn.command, spawn.command, decl.location, workspace, config,
                             _runs(decl.conditions))
    if spawn.topic is not None:  # ROS 2: robot_state_publisher's latched description
        topic = resolve(spawn.topic, decl.namespace)
        for param in reversed(launch.params):
            if (param.key == "robot_description" and param.node is not None
                    and clean(namespace_of(param.node) + "robot_description") == topic):
                if param.command is None:
                    break
                return _from_command(param.command, topic, param.location, workspace,
                                     config, _runs(param.conditions))
        _note(config, decl.location, f"no node of the configuration is given the "
                                     f"description published on {topic} by a xacro command")
        return None
    _note(config, decl.location, "the spawner's description ("
          + ("-string, not a command's output" if spawn.string else "-database, -stdin")
          + ") is not read")
    return None


# -- the hardware of a controller manager ---------------------------------------------
HARDWARE_HOSTS = (("controller_manager", "ros2_control_node"),)
DESCRIPTION_KEY = "robot_description"


def hardware(config: Configuration, started: Sequence[tuple[NodeDecl, NodeInstance]],
             given: Sequence[ParamDecl], workspace: Workspace) -> dict[int, list[Choice]]:
    """The hardware plugins of each controller manager the launch files start, by ``id``
    of its instance: the classes of the ``<hardware><plugin>`` of each ``<ros2_control>``
    in the robot description it reads, under the element's xacro conditions. ros2_control
    (humble, jazzy) reads its ``robot_description`` parameter (humble, deprecated) or the
    ``robot_description`` its subscription receives (``~/robot_description`` in humble,
    ``robot_description`` in jazzy; robot_state_publisher publishes its own parameter
    there). A description that is not known is one choice of unknown class (the
    manager's hardware, and what its code does with ROS, is not known)."""
    found: dict[int, list[Choice]] = {}
    for decl, instance in started:
        if (decl.package, decl.executable) not in HARDWARE_HOSTS or decl.ros_version != 2:
            continue
        param = _description_param(instance, config, given)
        made = _from_param(param, workspace, config) if param is not None else None
        if param is None or made is None:
            what = (f"its {DESCRIPTION_KEY} parameter is not given by a xacro (or cat) "
                    "command whose file is known") if param is not None else (
                f"no {DESCRIPTION_KEY} parameter, nor topic it reads, is given a value "
                "known statically")
            found[id(instance)] = [Choice("hardware", None, decl.location, why=what)]
            continue
        record, expanded = made
        config.robot_descriptions.append(record)
        choices = []
        if expanded.root is not None:
            for element in expanded.root.iter("ros2_control"):
                where = _where(element, workspace)
                cls = (element.findtext("hardware/plugin") or "").strip() or None
                choices.append(Choice(element.get("name") or "hardware", cls, where,
                                      _conditions(element, where)))
        if not choices and (expanded.root is None or expanded.unknown):
            # parts not read may hold them (a value unknown elsewhere leaves the
            # systems read as they are: a plugin whose own text is not known is said)
            reason = expanded.unknown[0] if expanded.unknown else "it is not read"
            choices.append(Choice("hardware", None, param.location,
                                  why=f"its robot description: {reason}"))
        found[id(instance)] = choices
    return found


def _description_param(instance: NodeInstance, config: Configuration,
                       given: Sequence[ParamDecl]) -> ParamDecl | None:
    """The launch parameter a controller manager takes its description from: its own
    ``robot_description`` (the one a ``ros2 param get`` command in it reads), else that
    of a node publishing a topic it subscribes to under that name (remaps applied: the
    graph's links)."""
    own = _last_param(given, instance.name.rstrip("/") + "/" + DESCRIPTION_KEY)
    if own is not None:
        return _copied(own, given)
    for link in config.links:
        if link.node is not instance or link.kind != "subscribe" or (
                (link.call.name if link.call else "").rsplit("/", 1)[-1].lstrip("~")
                != DESCRIPTION_KEY):  # ``~robot_description`` (humble's manager) too
            continue
        for other in config.links:
            if other.kind == "publish" and other.resource is link.resource:
                found = _last_param(given, other.node.name.rstrip("/") + "/" + DESCRIPTION_KEY)
                if found is not None:
                    return found
    return None


MAX_COPIES = 8  # ``ros2 param get`` commands followed, one to the next


def _copied(param: ParamDecl, given: Sequence[ParamDecl]) -> ParamDecl:
    """The launch parameter whose value ``param`` takes when its command is ``ros2 param
    get NODE NAME`` (articubot_one's controller manager: ``Command(['ros2 param get
    --hide-type /robot_state_publisher robot_description'])``, run as the manager
    starts): that node's parameter as the launch files give it; else ``param``."""
    seen = {id(param)}
    for _ in range(MAX_COPIES):
        named = param_get_command(param.command) if param.command is not None else None
        other = _last_param(given, named[0].rstrip("/") + "/" + named[1]) \
            if named is not None else None
        if other is None or id(other) in seen:
            break
        seen.add(id(other))
        param = other
    return param


# ``ros2 param get``'s options that take a value (the rest are flags)
_PARAM_GET_VALUED = {"--spin-time", "--parameter-file"}


def param_get_command(command: str) -> tuple[str, str] | None:
    """The node (its full name, as the CLI makes a relative one absolute) and the
    parameter a ``ros2 param get [OPTIONS] NODE NAME`` command line reads."""
    words = shell_words(command)
    for index in range(len(words) - 2):
        if os.path.basename(words[index]) != "ros2" or words[index + 1:index + 3] != [
                "param", "get"]:
            continue
        positional, _values, _flags = split_options(words[index + 3:], _PARAM_GET_VALUED)
        if len(positional) != 2 or any(UNKNOWN_MARK in w for w in positional):
            return None
        node, name = positional
        return (node if node.startswith("/") else "/" + node), name
    return None


def _from_param(param: ParamDecl, workspace: Workspace, config: Configuration,
                ) -> tuple[RobotDescription, xacro.Description] | None:
    """The description a launch parameter's xacro (or ``cat``) command makes, if known."""
    parsed = xacro_command(param.command) if param.command is not None else None
    if parsed is None or UNKNOWN_MARK in parsed.path:
        return None
    values = {key: xacro.partial_text(value, f"xacro argument {key} is not known")
              for key, value in parsed.args.items()}
    return _expanded(parsed.path, values, param.name, param.location, workspace, config,
                     by_xacro=parsed.by_xacro, command=_runs(param.conditions))


def _last_param(params: Sequence[ParamDecl], name: str) -> ParamDecl | None:
    found = None
    for param in params:
        if param.name == name:
            found = param
    return found


class XacroCommand(NamedTuple):
    """A ``xacro`` (or ``cat``) command line: its file, ``name:=value`` arguments and
    tool (``cat`` gives the file as it is, to a reader that does not run xacro)."""

    path: str
    args: dict[str, str]
    tool: str

    @property
    def by_xacro(self) -> bool:
        return self.tool != "cat"


def xacro_command(command: str) -> XacroCommand | None:
    """The file and ``name:=value`` arguments of a ``xacro`` (or ``cat``) command line."""
    words = shell_words(command)
    for index, word in enumerate(words):
        tool = os.path.basename(word)
        if tool not in ("xacro", "xacro.py", "cat"):
            continue
        path: str | None = None
        args: dict[str, str] = {}
        rest = iter(words[index + 1:])
        for each in rest:
            if each in ("-o", "--output"):
                next(rest, None)
            elif ":=" in each:
                key, _, value = each.partition(":=")
                args[key] = value
            elif not each.startswith("-") and path is None:
                path = each
        return XacroCommand(path, args, tool) if path else None
    return None


def _from_command(command: str | None, name: str, where: Location, workspace: Workspace,
                  config: Configuration, runs: bool = False,
                  ) -> tuple[RobotDescription, xacro.Description] | None:
    """The description the launch's ``command`` makes; ``runs``: the launch runs it
    wherever it is loaded (``_runs``), so a file it cannot read stops the launch."""
    assert command is not None
    parsed = xacro_command(command)
    if parsed is None:
        _note(config, where, f"command \"{command}\" is not a xacro command")
        return None
    if UNKNOWN_MARK in parsed.path:
        _note(config, where, f"the xacro file {parsed.path} is not known")
        return None
    values = {key: xacro.partial_text(value, f"xacro argument {key} is not known")
              for key, value in parsed.args.items()}
    return _expanded(parsed.path, values, name, where, workspace, config,
                     by_xacro=parsed.by_xacro, command=runs)


def _file_description(path: str, name: str | None, where: Location, workspace: Workspace,
                      config: Configuration, by_xacro: bool,
                      ) -> tuple[RobotDescription, xacro.Description]:
    """The description a file gives as it is named (an installed path: the source file
    installed there), read as its reader reads it (xacro or not); named ``name``, else
    by the file's path."""
    if not os.path.isfile(path):
        path = share_source(workspace, path)
    return _expanded(path, {}, name if name is not None else workspace.relpath(path), where,
                     workspace, config, by_xacro=by_xacro)


def _expanded(path: str, args: Mapping[str, str | Value], name: str, where: Location,
              workspace: Workspace, config: Configuration, by_xacro: bool = True,
              command: bool = False,
              ) -> tuple[RobotDescription, xacro.Description]:
    expanded = xacro.expand(path, args, workspace, named_at=where, by_xacro=by_xacro,
                            command=command)
    config.diagnostics.extend(expanded.diagnostics)
    record = RobotDescription(
        name, workspace.relpath(path) if expanded.files else None, where,
        [workspace.relpath(f) for f in expanded.files])
    if expanded.root is not None:
        record.links, record.joints = _links_joints(expanded.root)
        record.ros2_control = [
            DescribedControl(element.get("name") or "", element.findtext("hardware/plugin"),
                             [j.get("name") or "" for j in element.iterfind("joint")],
                             _where(element, workspace))
            for element in expanded.root.iter("ros2_control")]
    if expanded.root is None and not expanded.unknown:
        expanded.unknown.append(f"{workspace.relpath(path)} is not read")
    for reason in expanded.unknown:
        _record_partial(record, reason)
    return record, expanded


def _links_joints(root: etree._Element) -> tuple[list[str], list[str]]:
    """The robot's (or SDF model's) links and joints, not a ros2_control's joints."""
    links: list[str] = []
    joints: list[str] = []
    for element in root.iter("link", "joint"):
        name = element.get("name")
        parent = element.getparent()
        if name is None or parent is None or parent.tag not in ("robot", "model"):
            continue
        (links if element.tag == "link" else joints).append(name)
    return links, joints


def _plugins(root: etree._Element) -> Iterator[etree._Element]:
    count = 0
    for element in root.iter("plugin"):
        if element.get("filename") is None:
            continue
        count += 1
        if count > MAX_PLUGINS:
            return
        yield element


def _record_partial(record: RobotDescription, reason: str) -> None:
    record.completeness = "partial"
    if len(record.completeness_reasons) < 5 and reason not in record.completeness_reasons:
        record.completeness_reasons.append(reason)


def _note(config: Configuration, where: Location, detail: str) -> None:
    config.diagnostics.append(diag.make("ROBOT_DESCRIPTION_UNKNOWN", where, detail=detail))


# -- the gazebo node --------------------------------------------------------------------
def _host(config: Configuration, started: Sequence[tuple[NodeDecl, NodeInstance]],
          spawner: NodeDecl, ros_version: int, launch: LaunchModel,
          gazebo: tuple[Callable[[], Node | None] | None, list[NodeInstance]] = (None, []),
          ) -> NodeInstance:
    """The gazebo instance a spawner's description goes to: the one the launch files
    start, else one made here, named ``/gazebo`` in the namespace of an unread include
    of gazebo_ros' launch files, whose gzserver (``gazebo``: the node and the list of
    the instances made with it) it runs; else of unknown interface."""
    for decl, instance in started:
        if decl.package == "gazebo_ros" and decl.executable in GAZEBO_EXECUTABLES:
            return instance
    unread = _unread_gazebo(launch) if ros_version == 1 else None
    namespace, remaps, conditions = unread if unread is not None else ("/", [], ())
    name = clean(namespace + GAZEBO_NAME[1:])
    for instance in config.nodes:
        if instance.name == name and instance.origin == "description":
            return instance
    find, made = gazebo
    instance = NodeInstance(name, find() if unread is not None and find else None,
                            namespace=namespace, remaps=list(remaps),
                            conditions=conditions, location=spawner.location,
                            origin="description", ros_version=ros_version)
    if instance.node is not None:
        made.append(instance)
    instance.id = f"node:{name}"
    if any(n.name == name for n in config.nodes):
        instance.id += f"#{sum(1 for n in config.nodes if n.name == name) + 1}"
    config.nodes.append(instance)
    config.diagnostics.append(diag.make("GAZEBO_NOT_STARTED", spawner.location, name=name))
    return instance


_GAZEBO_ROS_FILE = re.compile(r"^\s*\$\(find\s+gazebo_ros\s*\)/")


def _unread_gazebo(launch: LaunchModel,
                   ) -> tuple[str, list[tuple[str, str]], tuple[Condition, ...]] | None:
    """Where a ROS 1 configuration starts Gazebo through one of gazebo_ros' own launch
    files (``$(find gazebo_ros)/launch/empty_world.launch``) that was not read, the
    package not being found: the namespace, remaps and conditions in effect at that
    include, which its gazebo node (named ``gazebo``, no ``ns`` of its own) takes
    (mir_gazebo remaps joint_states to mir/joint_states there). None when no such
    include is there, or several disagree."""
    found = {(u.namespace, tuple(u.remaps), u.conditions)
             for u in launch.unread_includes if _GAZEBO_ROS_FILE.match(u.file)}
    if len(found) != 1:
        return None
    namespace, remaps, conditions = found.pop()
    return namespace, list(remaps), conditions


# -- one plugin -------------------------------------------------------------------------
def _plugin(element: etree._Element, spawn: Spawn, host: NodeInstance,
            record: RobotDescription, config: Configuration, workspace: Workspace,
            owned: set[int], params: Params, managers: list[tuple[NodeDecl, NodeInstance]],
            ) -> list[tuple[NodeInstance, list[PrimitiveCall]]]:
    filename = element.get("filename") or ""
    name = element.get("name") or ""
    where = _where(element, workspace)
    conditions = _conditions(element, where)
    described = DescribedPlugin(name, filename, where,
                                conditions=[c.text for c in conditions])
    record.plugins.append(described)
    row = plugin_row(filename, spawn.ros_version)
    built = workspace_plugin(filename, workspace) if row is None else None
    if built is not None:
        return _built(element, built, spawn, host, record, described, where, conditions,
                      config, workspace, owned)
    if row is None and classic_builtin(filename):
        return []  # Gazebo classic's own: Gazebo transport only, no ROS interface
    if row is None:
        found = diag.make("GAZEBO_PLUGIN_UNKNOWN", where, filename=filename, host=host.name)
        config.diagnostics.append(found)
        reason = f"{found.message} ({where.file}:{where.line})"
        own_partial(host, reason, owned)
        _record_partial(record, reason)
        return []
    if row.partial:
        own_partial(host, f"Gazebo plugin {name}: {row.partial} ({where.file}:{where.line})",
                    owned)
    conditions = (*spawn.decl.conditions, *conditions)
    if spawn.ros_version == 1:
        namespace = _ros1_namespace(element, row, spawn, host)
        calls = list(_calls(element, row, where, conditions, namespace,
                            as_namespace(host.namespace)))
        described.node = host.name
        return [(host, calls)]
    if row.manager:
        managers.append(_manager(element, spawn, where, conditions, workspace, config,
                                 params))
    instance, unknown = _ros2_instance(element, name, spawn, host, where, conditions,
                                       workspace, config)
    calls = list(_calls(element, row, where, conditions, None))
    instance.node = Node("gazebo_plugins", library_base(filename), kind="plugin", calls=calls,
                         location=where)
    if row.partial:
        instance.node.mark_partial(f"{row.partial} ({where.file}:{where.line})")
    for reason in unknown:
        instance.node.mark_partial(reason)
    described.node = instance.name
    taken = sum(1 for n in config.nodes if n.name == instance.name)
    if taken:  # two robots' plugins of one name in one namespace: kept apart by id
        instance.id += f"#{taken + 1}"
    config.nodes.append(instance)
    return [(instance, calls)]


def workspace_plugin(filename: str, workspace: Workspace) -> Node | None:
    """The Gazebo classic plugin a workspace package builds as the library ``filename``
    (``cmake.nodes.gazebo_plugins``: registered with ``GZ_REGISTER_<KIND>_PLUGIN``), its
    calls read from its C++ like any node's; None when no package read builds it."""
    base = library_base(filename)
    for package in workspace.packages.values():
        for node in package.nodes:
            if node.kind == "plugin" and node.executable == base and (
                    node.plugin_base or "").startswith("gazebo::"):
                return node
    return None


def _built(element: etree._Element, built: Node, spawn: Spawn, host: NodeInstance,
           record: RobotDescription, described: DescribedPlugin, where: Location,
           conditions: tuple[Condition, ...],
           config: Configuration, workspace: Workspace, owned: set[int],
           ) -> list[tuple[NodeInstance, list[PrimitiveCall]]]:
    """A plugin the workspace builds: its code's calls, with the names it takes from
    its SDF element's children filled from the description (``sdf_filled``). ROS 1: calls
    of the gazebo node, as the code's handles name them relative to it; ROS 2: those of
    the plugin's own node (``gazebo_ros::Node::Get(sdf)``), made as a table plugin's."""
    conditions = (*spawn.decl.conditions, *conditions)
    # ROS 1's spawner gives a plugin with no <robotNamespace> its -robot_namespace (its
    # own namespace by default), as for the table's plugins (``_ros1_namespace``)
    given = {"robotNamespace": spawn.robot_namespace if spawn.robot_namespace is not None
             else spawn.decl.namespace} if spawn.ros_version == 1 else {}
    calls = [sdf_filled(call, element, conditions, given) for call in built.calls]
    reasons = [f"Gazebo plugin {described.name or described.filename} ({built.name}): "
               f"{reason}" for reason in built.completeness_reasons[:3]]
    if not built.is_complete and not reasons:
        reasons = [f"Gazebo plugin {described.name or described.filename} ({built.name}) "
                   f"is {built.completeness}"]
    helper = remembered("gazebo helper", built.name, workspace,
                        lambda: _unread_helper(built, workspace))
    if helper is not None:
        reasons.append(f"Gazebo plugin {described.name or described.filename} "
                       f"({built.name}): {helper}")
    for reason in reasons:
        _record_partial(record, f"{reason} ({where.file}:{where.line})")
    if spawn.ros_version == 1:
        for reason in reasons:
            own_partial(host, f"{reason} ({where.file}:{where.line})", owned)
        for base in remembered("gazebo base", built.name, workspace,
                               lambda: _base_rows(built, workspace)):
            row = plugin_row(base, 1)
            if row is not None:
                calls.extend(_calls(element, row, where, conditions,
                                    _ros1_namespace(element, row, spawn, host),
                                    as_namespace(host.namespace)))
        described.node = host.name
        return [(host, calls)]
    if built.rosname is not None:
        # its code makes a node of its own (``rclcpp::Node("control", ns)``), not
        # gazebo_ros's: named as the code names it, no <ros> element applies
        full = clean(built.rosname if built.rosname.startswith("/") else
                     "/" + built.rosname)
        instance = NodeInstance(full, None, namespace=namespace_of(full),
                                conditions=(*host.conditions, *conditions), location=where,
                                origin="description", ros_version=2)
        instance.id = f"node:{full}"
        unknown: list[str] = []
    else:
        instance, unknown = _ros2_instance(element, described.name, spawn, host, where,
                                           conditions, workspace, config)
    instance.node = Node(built.package, built.executable, kind="plugin", calls=calls,
                         sources=list(built.sources), location=built.location,
                         plugin_class=built.plugin_class, plugin_base=built.plugin_base)
    for reason in [*reasons, *unknown]:
        instance.node.mark_partial(reason)
    described.node = instance.name
    taken = sum(1 for n in config.nodes if n.name == instance.name)
    if taken:
        instance.id += f"#{taken + 1}"
    config.nodes.append(instance)
    return [(instance, calls)]


# gazebo_ros_pkgs' plugin library (ROS 1 gazebo_plugins' GazeboRosCameraUtils, ROS 2's
# gazebo_plugins helpers): a plugin that builds on it makes calls its own code does not
# show (hector's thermal camera, uuv's underwater camera publish through it)
HELPER_LIBRARY = "gazebo_plugins"


def _unread_helper(built: Node, workspace: Workspace) -> str | None:
    """Why the calls of a workspace plugin are not all in its code: it includes a header
    of ``HELPER_LIBRARY`` (from its sources or the headers of its package they
    include), which the workspace does not build. None when it does not."""
    if HELPER_LIBRARY in workspace.packages:
        return None
    for path, header in _included(built, workspace):
        # a header our stand-ins write the calls of (gazebo_ros_utils.h's GazeboRos:
        # its handle and SDF reads) is read with the plugin's code
        if header.startswith(HELPER_LIBRARY + "/") and not os.path.isfile(
                os.path.join(FALLBACK, os.path.normpath(header))):
            return (f"{workspace.relpath(path)} includes {header}, whose classes make "
                    "calls that are not read")
    return None


# the header that declares the plugin class of a table row: a workspace plugin that
# includes it derives from that class, whose Load its own Load runs first (baxter_gazebo's
# BaxterGazeboRosControlPlugin calls GazeboRosControlPlugin::Load), so it makes the
# row's calls beside those of its code
ROW_BASES = {"gazebo_ros_control/gazebo_ros_control_plugin.h": "gazebo_ros_control"}


def _base_rows(built: Node, workspace: Workspace) -> list[str]:
    """The rows of ``ROW_BASES`` whose header a workspace plugin includes."""
    rows: list[str] = []
    for _, header in _included(built, workspace):
        row = ROW_BASES.get(header)
        if row is not None and row not in rows:
            rows.append(row)
    return rows


def _included(built: Node, workspace: Workspace) -> Iterator[tuple[str, str]]:
    """Each ``#include`` of a workspace plugin's sources and of the headers of its
    package they include (bounded), as (the file that includes it, the header)."""
    package = workspace.packages.get(built.package)
    roots = [os.path.join(package.root, "include")] if package is not None else []
    seen: set[str] = set()
    files = [os.path.join(workspace.root, s) for s in built.sources[:MAX_SYSTEM_SOURCES]]
    while files and len(seen) < 4 * MAX_SYSTEM_SOURCES:
        path = files.pop(0)
        if path in seen or not os.path.isfile(path):
            continue
        seen.add(path)
        text, _ = read_text(path, workspace.location(path))
        for header in INCLUDE.findall(text or ""):
            yield path, header
            files.extend(os.path.join(folder, header)
                         for folder in [*roots, os.path.dirname(path)])


def sdf_filled(call: PrimitiveCall, element: etree._Element,
               conditions: tuple[Condition, ...],
               given: Mapping[str, str] | None = None) -> PrimitiveCall:
    """``call`` of a plugin's code under the description's ``conditions``, the ``?`` its
    name takes from a child element of the plugin's SDF (``name_param`` ``sdf:key``)
    filled with that child's text, else with what the host ``given`` puts there, else
    with the default the code gives; left ``?`` when none is there. The ``sdf:``
    parameter is no ROS parameter: it goes."""
    param = call.name_param or ""
    if not param.startswith(SDF_ELEMENT) and not call.namespace_param:
        return replace(call, conditions=(*conditions, *call.conditions), origin="description")
    name, namespace = call.name, call.handle_namespace
    # the handle namespace's unknown runs, in order, each a child element's text
    outers = [_sdf_value(element, key, given) for key in (call.namespace_param or "").split()]
    if outers and None not in outers and namespace and len(outers) <= namespace.count(
            UNKNOWN_MARK) and name.startswith(namespace.rstrip("/") + "/"):
        rest = name[len(namespace.rstrip("/")) + 1:]
        for outer in outers:
            head, _, tail = namespace.partition(UNKNOWN_MARK)
            namespace = clean_join(head, cast(str, outer), tail)
        name = f"{namespace.rstrip('/')}/{rest}" if namespace.strip("/") else (
            namespace + rest)
    value = _sdf_value(element, param, given) if param.startswith(SDF_ELEMENT) else None
    if value is None and param.startswith(SDF_ELEMENT):
        value = call.name_default
    if value is not None and UNKNOWN_MARK not in value:
        name = _one_filled(name, namespace, value)
    return replace(call, name=name, name_param=None, name_default=None, default_param=None,
                   namespace_param=None, handle_namespace=namespace,
                   conditions=(*conditions, *call.conditions), origin="description")


def _sdf_value(element: etree._Element, param: str | None,
               given: Mapping[str, str] | None) -> str | None:
    """The text of the child element ``param`` (``sdf:key``) names, else what the host
    ``given`` puts there; None when neither (or its text has unknown parts)."""
    if param is None or not param.startswith(SDF_ELEMENT):
        return None
    key = param[len(SDF_ELEMENT):]
    value = _child(element, key)
    if value is None:
        value = (given or {}).get(key)
    return value if value is None or UNKNOWN_MARK not in value else None


def _one_filled(name: str, namespace: str | None, value: str) -> str:
    """``name`` with the ``?`` a value stands for put in its place: the one ``?`` of the
    call's own part (after the handle's ``namespace``; a global value there is the whole
    name, as roscpp resolves it), else the one ``?`` of the name (the namespace's)."""
    cut = 0
    if namespace and name.startswith(namespace.rstrip("/") + "/"):
        cut = len(namespace.rstrip("/")) + 1
    rest = name[cut:]
    if rest.count(UNKNOWN_MARK) == 1:
        head, _, tail = rest.partition(UNKNOWN_MARK)
        if not head and value.startswith("/"):
            return clean_join("", value, tail)
        return name[:cut] + clean_join(head, value, tail)
    if name.count(UNKNOWN_MARK) == 1:
        head, _, tail = name.partition(UNKNOWN_MARK)
        return clean_join(head, value, tail)
    return name


def clean_join(head: str, value: str, tail: str) -> str:
    """``head + value + tail`` as roscpp joins a name's parts: an empty value leaves no
    empty segment (``?/scan`` with "" is ``scan``), a global value stays global."""
    if value.startswith("/") and head.endswith("/"):
        head = head[:-1]
    text = head + value + tail
    text = re.sub(r"/+", "/", text)
    if not value and tail.startswith("/") and (not head or head.endswith("/")):
        text = head + tail[1:]
    return text


def _manager(element: etree._Element, spawn: Spawn, where: Location,
             conditions: tuple[Condition, ...], workspace: Workspace,
             config: Configuration, params: Params,
             gz: bool = False) -> tuple[NodeDecl, NodeInstance]:
    """The controller manager a gazebo_ros2_control / gz_ros2_control plugin starts:
    ``controller_manager`` in the plugin's ``<ros><namespace>``, with the parameters of
    its ``<parameters>`` files, as a launch file's ``ros2_control_node`` would be (each
    node a section of a file names, ``/**/controller_manager`` as rcl matches it, gets
    its parameters: the files are ``--params-file`` arguments of the process). The gz
    plugin (``gz``: gz_ros2_control / ign_ros2_control, gz_ros2_control_plugin.cpp) names
    it ``<controller_manager_prefix_node_name>_controller_manager`` when that element is
    given, and gives its ``<ros><remapping>`` rules to ``rclcpp::init``: rules of the
    whole process, the manager's and its controllers' (the instance's remaps, which the
    controllers take). Both plugins make it as ``ControllerManager(resource_manager,
    executor, name, namespace)``: it serves the manager's services (those the C++ API
    row gives a node of the workspace that makes one, ``api.CONTROLLER_MANAGER_
    SERVICES``); what else it makes is not described (ros2_control_node's model is not
    its interface: that constructor does not subscribe to the robot description once
    the plugin has loaded the URDF into the resource manager), so the node is partial."""
    namespace = as_namespace(spawn.robot_namespace or _child(element, "ros/namespace") or "/")
    prefix = _child(element, "controller_manager_prefix_node_name") if gz else None
    name = clean(namespace + (f"{prefix}_{MANAGER}" if prefix else MANAGER))
    remaps: list[tuple[str, str]] = []
    for rule in element.iterfind("ros/remapping") if gz else ():
        found = split_rule((rule.text or "").strip())
        if found is not None and found[0] is None:
            remaps.append((found[1], found[2]))
    decl, instance = _made_manager(name, namespace, (*spawn.decl.conditions, *conditions),
                                   where, remaps, library_base(element.get("filename") or ""),
                                   config)
    for file in element.iterfind("parameters"):
        named = (file.text or "").strip()
        read = _yaml_file_lines(named, where, workspace, config)
        if read is None or read[0] is None:
            continue
        document, lines = read
        source = share_source(workspace, named)
        for node in _node_names(document, namespace):
            # each at its key's line (rosbot_ros' gazebo controllers' settings were all
            # at line 1 of their file)
            at = {key: line for key, line in params_for_node(lines, node)
                  if isinstance(line, int)} if isinstance(lines, dict) else {}
            for key, value in params_for_node(document, node):
                parameter = params.get(Parameter, f"{node}/{key}")
                assert isinstance(parameter, Parameter)
                if not parameter.set_by_launch:
                    parameter.value, parameter.set_by_launch = value, True
                    parameter.launch_location = workspace.location(source, at.get(key, 1))
                    parameter.launch_conditions = decl.conditions
    return decl, instance


def _made_manager(name: str, namespace: str, conditions: tuple[Condition, ...],
                  where: Location, remaps: list[tuple[str, str]], starter: str,
                  config: Configuration) -> tuple[NodeDecl, NodeInstance]:
    """A controller manager a simulator's plugin starts in its own process (``starter``
    names the plugin), as a launch file's ``ros2_control_node`` would be: it serves the
    manager's services; the rest it makes is not described (the node is partial). Its
    instance is added to the configuration."""
    decl = NodeDecl(name, "controller_manager", "ros2_control_node", namespace=namespace,
                    conditions=conditions, location=where, ros_version=2,
                    remaps=list(remaps))
    served = Node("controller_manager", "ControllerManager", kind="plugin", location=where,
                  calls=[PrimitiveCall("server", service, kind, conditions=decl.conditions,
                                       location=where)
                         for service, kind in CONTROLLER_MANAGER_SERVICES])
    served.mark_partial(f"the controller manager {starter} starts: its services are "
                        f"known, not the rest it makes ({where.file}:{where.line})")
    instance = NodeInstance(name, served, namespace=namespace, conditions=decl.conditions,
                            location=where, origin="description", ros_version=2,
                            remaps=list(remaps))
    taken = sum(1 for n in config.nodes if n.name == name)
    instance.id = f"node:{name}" + (f"#{taken + 1}" if taken else "")
    config.nodes.append(instance)
    return decl, instance


# webots_ros2_driver's driver and the plugin of a robot description's ``<webots>`` that
# runs ros2_control in it (webots_ros2_control's Ros2Control.cpp)
WEBOTS_DRIVER = ("webots_ros2_driver", "driver")
WEBOTS_ROS2_CONTROL = "webots_ros2_control::Ros2Control"


def _webots(decl: NodeDecl, driver: NodeInstance, given: Sequence[ParamDecl],
            workspace: Workspace, config: Configuration, params: Params,
            managers: list[tuple[NodeDecl, NodeInstance]]) -> None:
    """The controller manager a Webots robot's driver runs: the driver reads its robot
    description from its ``robot_description`` parameter (a ``.urdf`` file it loads, a
    ``.xacro`` file it runs xacro on, or the text itself; WebotsNode.cpp) and loads the
    plugins of its ``<webots>`` element; webots_ros2_control's ``Ros2Control`` makes
    ``ControllerManager(..., "controller_manager", <driver's namespace>)`` in the
    driver's process, whose parameter files and remapping rules (the launch's, given to
    the process) are its own and its controllers' (webots_ros2_turtlebot's
    ``ros2control.yml``, the driver's remaps of ``/diffdrive_controller/cmd_vel_unstamped``
    to ``/cmd_vel``)."""
    param = _last_param(given, driver.name.rstrip("/") + "/" + DESCRIPTION_KEY)
    if param is None:
        return
    value = param.value.text if isinstance(param.value, Value) else param.value
    made = None
    if param.command is not None:
        made = _from_param(param, workspace, config)
    elif isinstance(value, str) and value.strip().endswith((".urdf", ".xacro")) and (
            UNKNOWN_MARK not in value):
        path = value.strip()
        made = _file_description(path, param.name, param.location, workspace, config,
                                 by_xacro=path.endswith(".xacro"))
    if made is None or made[1].root is None:
        return
    record, expanded = made
    config.robot_descriptions.append(record)
    assert expanded.root is not None
    for element in expanded.root.iter("plugin"):
        if (element.get("type") or "").strip() != WEBOTS_ROS2_CONTROL or not any(
                parent.tag == "webots" for parent in element.iterancestors()):
            continue
        where = _where(element, workspace)
        namespace = as_namespace(driver.namespace or "/")
        made_decl, instance = _made_manager(
            clean(namespace + MANAGER), namespace,
            (*decl.conditions, *_conditions(element, where)), where, list(decl.remaps),
            WEBOTS_ROS2_CONTROL, config)
        made_decl.param_files = decl.param_files
        process_file_params(made_decl, instance, params)
        managers.append((made_decl, instance))
        return


def _node_names(document: Any, namespace: str) -> list[str]:
    """The nodes a ROS 2 parameter file names, in ``namespace`` (its own ``/`` keys
    as they are); a key with wildcards names the node of its last name in
    ``namespace`` when it matches it as rcl matches (``/**/controller_manager``, the
    manager or a controller of this process in any namespace: rosbot_ros' controller
    files); ``/**`` is for every node and names none. Keys nest as rcl joins them
    down to ``ros__parameters`` (``/**:`` then ``controller_manager:``, as
    open_manipulator's gz_ros2_control files write it, is ``/**/controller_manager``)."""
    if not isinstance(document, dict):
        return []
    names: list[str] = []
    for text in _node_keys(document)[:MAX_PLUGINS]:
        if "*" not in text:
            node = text if text.startswith("/") else clean(namespace + text)
        else:
            last = text.rstrip("/").rsplit("/", 1)[-1]
            node = clean(namespace + last)
            if "*" in last or not pattern_matches(text, node):
                continue
        if node not in names:
            names.append(node)
    return names


def _node_keys(document: dict[Any, Any], depth: int = 0,
               path: tuple[str, ...] = ()) -> list[str]:
    """The node keys of a parameter file as rcl joins nested keys (``a/b``), one per
    mapping holding ``ros__parameters``; a top key with none below it is kept as it
    is."""
    keys: list[str] = []
    for key, value in document.items():
        if key == PARAMS_KEY:
            continue
        here = (*path, str(key))
        below: list[str] = []
        if isinstance(value, dict):
            if PARAMS_KEY in value:
                below.append("/".join(here))
            if depth < MAX_PARAM_DEPTH:
                below.extend(_node_keys(value, depth + 1, here))
        keys.extend(below if below or depth else [str(key)])
    return keys


def _yaml_file_lines(path: str, where: Location, workspace: Workspace,
                     config: Configuration) -> tuple[Any, Any] | None:
    """A YAML file a plugin element names, read with the safe loader: its document and
    where each of its keys is written (``safe_yaml.load_with_lines``); None if not read."""
    if not path or UNKNOWN_MARK in path or not os.path.isabs(path):
        return None
    path = path if os.path.isfile(path) else share_source(workspace, path)
    if not os.path.isfile(path) or not workspace.readable(path):
        config.diagnostics.append(diag.make("ROBOT_DESCRIPTION_FILE", where,
                                            path=workspace.relpath(path),
                                            detail="no such file in the workspace"))
        return None
    text, found = read_text(path, workspace.location(path, 1))
    config.diagnostics.extend(found)
    try:
        return safe_yaml.load_with_lines(text, ParamFileLoader) if text is not None \
            else None
    except yaml.YAMLError:
        config.diagnostics.append(diag.make("ROBOT_DESCRIPTION_FILE", where,
                                            path=workspace.relpath(path),
                                            detail="not YAML"))
        return None


def _where(element: etree._Element, workspace: Workspace) -> Location:
    here: etree._Element | None = element
    while here is not None and here.get(FILE) is None:
        here = here.getparent()
    path = here.get(FILE) if here is not None else None
    if path is None:
        return NOWHERE
    return workspace.location(path, xacro.line_of(element))


def _conditions(element: etree._Element, where: Location) -> tuple[Condition, ...]:
    found: list[Condition] = []
    here: etree._Element | None = element
    while here is not None:
        text = here.get(xacro.CONDITION)
        if text:
            found.extend(Condition(part.strip(), "source", "xacro:if", where)
                         for part in text.split("; "))
        here = here.getparent()
    return tuple(reversed(found))


def _child(element: etree._Element, path: str) -> str | None:
    """The text of the child element ``path`` (``robotNamespace``, ``ros/namespace``)."""
    found = element.find(path)
    if found is None:
        return None
    return (found.text or "").strip()


def _value(element: etree._Element, row: Plugin, key: str, depth: int = 0) -> str | None:
    """A child element's value, or the row's default (which may refer to others)."""
    given = _child(element, key)
    if given is not None:
        return given
    default = dict(row.defaults).get(key)
    if default is None:
        return None
    return _template(element, row, default, depth + 1)


def _template(element: etree._Element, row: Plugin, text: str, depth: int = 0) -> str | None:
    """``{element}`` filled from the plugin's children (``{@sensor}``: its sensor's name);
    None when an element it needs is absent with no default."""
    out = []
    rest = text
    while "{" in rest and depth < 8:
        head, _, tail = rest.partition("{")
        key, _, rest = tail.partition("}")
        out.append(head)
        if key == "@sensor":
            sensor = next((a for a in element.iterancestors("sensor")), None)
            value = sensor.get("name") if sensor is not None else None
        else:
            value = _value(element, row, key, depth)
        if value is None:
            return None
        if value == "" and rest.startswith("/") and not "".join(out):
            rest = rest[1:]  # an empty first part: the name is relative (camera_name "")
        out.append(value)
    out.append(rest)
    return "".join(out)


def _truth(element: etree._Element, entity: Entity) -> bool | None:
    if entity.when is None:
        return True
    if entity.when == "@depth":
        sensor = next(element.iterancestors("sensor"), None)
        return sensor is not None and sensor.get("type") == "depth"
    if entity.when.startswith("@camera:"):
        return _camera_side(element, entity.when.partition(":")[2])
    values = []
    for key in entity.when.split("|"):
        text = _child(element, key)
        if text is None:
            values.append(entity.when_default)
        elif text.lower() in ("true", "1"):
            values.append(True)
        elif text.lower() in ("false", "0"):
            values.append(False)
        else:
            return None
    return any(values)


def _camera_side(element: etree._Element, side: str) -> bool | None:
    """Whether a <camera> of the plugin's <sensor> takes ``side``: the first of
    ``MULTICAMERA_SIDES`` its name holds (None when a name with unknown parts could)."""
    sensor = next(element.iterancestors("sensor"), None)
    if sensor is None:
        return False
    unsure = False
    for camera in sensor.iterfind("camera"):
        name = camera.get("name") or ""
        taken = next((s for s in MULTICAMERA_SIDES if s in name), None)
        if taken == side:
            return True
        if taken is None and UNKNOWN_MARK in name:
            unsure = True
    return None if unsure else False


def _calls(element: etree._Element, row: Plugin, where: Location,
           conditions: tuple[Condition, ...], namespace: str | None,
           home: str = "/") -> Iterator[PrimitiveCall]:
    """The plugin's calls. ROS 1 (``namespace``: its node handle's): a relative name is
    joined to that namespace and written relative to the gazebo node's (``home``) when it
    lies in it, as the node resolves it; a name the description writes global stays so."""
    for entity in row.entities:
        truth = _truth(element, entity)
        if truth is False:
            continue
        extra: tuple[Condition, ...] = ()
        if truth is None:
            text = f"<{entity.when}> is true"
            if entity.when and entity.when.startswith("@camera:"):
                text = f"a <camera> of the sensor is named with {entity.when[8:]}"
            extra = (Condition(text, "source", "if", where),)
        name = _template(element, row, entity.name)
        if name is None or (entity.kind != "read" and name.strip("/") == ""):
            continue
        kind = _template(element, row, entity.type) or UNKNOWN_MARK
        if row.ros_version == 2 and kind.count("/") == 1:
            package, _, message = kind.partition("/")
            kind = f"{package}/msg/{message}"
        own = name
        if namespace is not None and not name.startswith("/"):
            name = clean(namespace + name)
            if name.startswith(home) and len(name) > len(home):
                name = name[len(home):]
        # a searched read starts from its handle's namespace: the name's part before
        # the key (``PrimitiveCall.handle_namespace``)
        handle = name[:-len(own) - 1] if entity.searched and name.endswith("/" + own) \
            else None
        if handle is None and entity.handle is not None and namespace is not None:
            handle = _handle_namespace(element, row, entity.handle, namespace, name, own,
                                       home)
        yield PrimitiveCall(cast(CallKind, entity.kind), name,
                            kind if entity.kind != "read" else None,
                            conditions=(*conditions, *extra), location=where,
                            origin="description", searched=entity.searched,
                            handle_namespace=handle or None,
                            transport="*" if entity.transport else None)


def _handle_namespace(element: etree._Element, row: Plugin, template: str, namespace: str,
                      name: str, own: str, home: str) -> str | None:
    """The namespace of the node handle an entity's call is made on (``Entity.handle``),
    written as the call's ``name`` is: ``camera/left`` of ``camera/left/image_raw``, so
    the graph remaps it before it resolves the rest (``graph.build._handle_name``). None
    when it is the plugin's own handle (an empty ``<cameraName>``), when the name the
    description gives does not lie under it (a global topic name), or when not known."""
    below = _template(element, row, template)
    if below is None or UNKNOWN_MARK in below or not below.strip("/") or \
            below.startswith("/") or not own.startswith(below.rstrip("/") + "/"):
        return None
    handle = clean(namespace + below.rstrip("/"))
    if handle.startswith(home) and len(handle) > len(home):
        handle = handle[len(home):]
    return handle if name.startswith(handle + "/") else None


def _ros1_namespace(element: etree._Element, row: Plugin, spawn: Spawn,
                    host: NodeInstance) -> str:
    """The full namespace of the plugin's node handle (``/`` + ``robotNamespace``)."""
    own = _child(element, "robotNamespace")
    if own is None:  # the spawner adds its -robot_namespace (its namespace by default)
        own = spawn.robot_namespace if spawn.robot_namespace is not None else \
            spawn.decl.namespace
        own = own or None
    model = spawn.model or UNKNOWN_MARK
    if (row.namespace == "model" and not own) or (row.namespace == "sensor" and own == ""):
        own = model
    elif row.namespace == "sensor_model" and own is None:
        own = "/" + model
    return as_namespace(resolve(own or "", host.namespace)) if own else \
        as_namespace(host.namespace)


def _ros2_instance(element: etree._Element, name: str, spawn: Spawn, host: NodeInstance,
                   where: Location, conditions: tuple[Condition, ...],
                   workspace: Workspace, config: Configuration) -> tuple[NodeInstance, list[str]]:
    """The plugin's node instance and why it is partial (its ``<argument>`` words)."""
    namespace = _child(element, "ros/namespace")
    if spawn.robot_namespace:
        namespace = spawn.robot_namespace
    namespace = as_namespace(namespace or "/")
    ros = element.find("ros")
    said = _PluginArguments(name, workspace, config)
    for argument in ros.iterfind("argument") if ros is not None else ():
        said.word(argument)
    said.end()
    remaps = []
    for rule in ros.iterfind("remapping") if ros is not None else ():
        text = (rule.text or "").strip()
        source, sep, target = text.partition(":=")
        if not sep:
            source, sep, target = text.partition("=")
        if sep and source and target:
            remaps.append((source.strip(), target.strip()))
    # rcl takes the first rule that matches a name (a ROS 2 instance's remap_rules): the
    # arguments come first
    remaps = said.remaps_for(name) + remaps
    if said.namespace is not None:
        namespace = as_namespace(said.namespace)
    full = clean(namespace + (said.name or name or UNKNOWN_MARK))
    instance = NodeInstance(full, None, namespace=namespace, remaps=remaps,
                            conditions=(*host.conditions, *conditions), location=where,
                            origin="description", ros_version=2)
    instance.id = f"node:{full}"
    return instance, said.partial


# rcl's flags after --ros-args that take the next word as their value, and those alone
_ROS_VALUE_FLAGS = {"-r", "--remap", "-p", "--param", "--params-file", "-e", "--enclave",
                    "--log-level", "--log-config-file", "--log-file-name"}
_ROS_FLAGS = {f"--{way}-{what}-logs" for way in ("enable", "disable")
              for what in ("stdout", "rosout", "external-lib")}
_RULE_NAME = re.compile(r"~?/?[A-Za-z_][\w/]*|~|/|__ns|__node|__name", re.ASCII)


class _PluginArguments:
    """A plugin's ``<ros><argument>`` words read as rcl reads a node's arguments.

    gazebo_ros's ``Node::Get`` (gazebo_ros_pkgs eloquent to ros2/humble) puts each
    ``<argument>`` text, whole, in the node's arguments, before the ``--ros-args -r rule``
    words of its ``<remapping>`` elements. rcl (eloquent to rolling) reads words from the
    start: outside ``--ros-args`` a word that parses as a remap rule (``from:=to``,
    ``__ns:=/ns``, ``__node:=name``, ``node:from:=to``) is a remap (deprecated form,
    warned about); any other word is not a ROS argument and is left alone. After
    ``--ros-args``, ``-r``/``--remap`` take a rule and the other flags their value; a
    word that is none of these makes rclcpp throw (the node is not made), as does a flag
    whose value does not parse."""

    def __init__(self, plugin: str, workspace: Workspace, config: Configuration) -> None:
        self.plugin, self.workspace, self.config = plugin, workspace, config
        self.rules: list[tuple[str | None, str, str]] = []
        self.namespace: str | None = None
        self.name: str | None = None
        self.partial: list[str] = []
        self.inside = False
        self.flag: tuple[str, etree._Element] | None = None  # waiting for its value

    def _say(self, code: str, element: etree._Element, text: str, detail: str) -> None:
        where = _where(element, self.workspace)
        self.config.diagnostics.append(diag.make(code, where, argument=repr(text),
                                                 name=self.plugin, detail=detail))
        if code == "GAZEBO_PLUGIN_ARGUMENT_UNKNOWN":
            self.partial.append(f"<argument> {text!r} of plugin {self.plugin} not known "
                                f"({where.file}:{where.line})")

    def _unmodelled(self, element: etree._Element, text: str) -> None:
        self._say("GAZEBO_PLUGIN_ARGUMENT_UNKNOWN", element, text,
                  "a remap of topics or services alone is not modelled")

    def word(self, element: etree._Element) -> None:
        text = (element.text or "").strip()
        remap_value = self.flag is not None and self.flag[0] in ("-r", "--remap")
        if UNKNOWN_MARK in text and (remap_value or self.flag is None):
            self._say("GAZEBO_PLUGIN_ARGUMENT_UNKNOWN", element, text,
                      "its text has parts that are not known")
            self.flag = None
            return
        if self.flag is not None:
            flag, _ = self.flag
            self.flag = None
            if remap_value:
                found = self._rule(text)
                if found == "scheme":
                    self._unmodelled(element, text)
                elif found == "no":
                    self._say("GAZEBO_PLUGIN_ARGUMENT", element, text,
                              f"rcl cannot read it as the rule of {flag}: the plugin's node "
                              "is not made")
            return  # the value of another flag: no name changes
        if text == "--ros-args":
            self.inside = True
            return
        if self.inside:
            if text == "--":
                self.inside = False
            elif text in _ROS_VALUE_FLAGS:
                self.flag = (text, element)
            elif text not in _ROS_FLAGS:
                self._say("GAZEBO_PLUGIN_ARGUMENT", element, text,
                          "after --ros-args rcl does not know it: the plugin's node is not "
                          "made" + (" (a rule there needs -r before it)" if ":=" in text
                                    else ""))
            return
        found = self._rule(text)
        if found == "scheme":
            self._unmodelled(element, text)
        if found != "no":
            return
        if any(c.isspace() for c in text) and ("--ros-args" in text or ":=" in text):
            self._say("GAZEBO_PLUGIN_ARGUMENT", element, text,
                      "it is one word to rcl, not a remap rule, so it is ignored (give "
                      "each word an <argument> of its own)")
        elif ":=" in text:
            self._say("GAZEBO_PLUGIN_ARGUMENT", element, text,
                      "rcl cannot read it as a remap rule, so it is ignored")

    def end(self) -> None:
        if self.flag is not None:
            flag, element = self.flag
            if flag in ("-r", "--remap"):
                self._say("GAZEBO_PLUGIN_ARGUMENT", element, flag,
                          "no rule follows it among the <argument> words")

    def _rule(self, text: str) -> str:
        """``"rule"`` (kept) if ``text`` is a remap rule rcl reads, ``"scheme"`` if it is
        one for topics or services alone (``rostopic://``: not modelled), else ``"no"``."""
        rule = split_rule(text)
        if rule is None:
            return "no"
        if re.match(r"(?:(\w+):)?(rostopic|rosservice)://", text):
            return "scheme"
        node, left, right = rule
        # rcl has no wildcards nor back references in rules yet: not rules
        if not _RULE_NAME.fullmatch(left) or not _RULE_NAME.fullmatch(right) or \
                right.startswith("__") or (left.startswith("__") and left not in (
                    "__ns", "__node", "__name")):
            return "no"  # ROS 1 / dashing's __log_level:=, __params:= are not rules
        if node is not None and not is_ros2_node_name(node):
            return "no"
        if left == "__ns" and not right.startswith("/"):
            return "no"  # rcl wants a fully qualified namespace
        if left in ("__node", "__name") and not is_ros2_node_name(right):
            return "no"
        self.rules.append((node, left, right))
        return "rule"

    def remaps_for(self, name: str) -> list[tuple[str, str]]:
        """The name remaps for the node called ``name``; sets its namespace and name.
        rcl matches the ``__ns``/``__node`` rules against the plugin's name and the
        others against the node's name after those (the first rule that matches wins)."""
        for node, left, right in self.rules:
            if node is None or node == name:
                if left == "__ns" and self.namespace is None:
                    self.namespace = right
                elif left in ("__node", "__name") and self.name is None:
                    self.name = right
        final = self.name or name
        return [(left, right) for node, left, right in self.rules
                if left not in ("__ns", "__node", "__name") and node in (None, final)]


