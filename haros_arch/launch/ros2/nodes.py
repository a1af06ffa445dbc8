"""A ``Node`` / ``ComposableNode`` performed statically: its name, remaps and parameters.

Parameters are applied in launch_ros's order (``SetParameter`` globals, then the node's
``parameters`` list in order, then ``-p`` / ``--params-file`` from its ros arguments);
a later value for the same name replaces an earlier one, as in the running node. A
parameter whose value cannot be known is still declared, with value ``None``.
"""

from __future__ import annotations

import os
import shlex
from dataclasses import replace
from typing import TYPE_CHECKING, Any

import yaml

from ... import safe_yaml
from ...files import read_text
from ...model.location import Location
from ...model.values import UNKNOWN_MARK, Value
from ...share import configured, file_setting, generated_at, share_source
from ..model import ForeignSections
from ..paths import missing_argument_paths
from . import entities as e
from . import naming
from .runner import make_param, node_decl
from .substitutions import Evaluator

if TYPE_CHECKING:
    from .runner import Runner, Scope

COMPONENT_CONTAINER = ("rclcpp_components", "component_container")


def _text(ev: Evaluator, t: e.Text | None, default: str = "?") -> str:
    return default if t is None else ev.value(t).text


def _quoted(word: str) -> str:
    """One argument of a Python ``arguments=[...]`` list in the command line: quoted
    when it holds a space (``"-r ~/cmd_vel:=/cmd_vel"`` stays one argument)."""
    return shlex.quote(word) if not word or any(c.isspace() for c in word) else word


def _rewritten(runner: Runner, ev: Evaluator, arguments: list[e.Text], scope: Scope,
               where: Location) -> dict[str, str]:
    """The text of each file an argument names as a file with text replaced
    (``ReplaceString``: nav2's rviz_launch.py gives rviz2 ``-d`` its configuration with
    ``<robot_namespace>`` replaced), by the path the argument holds; a file whose
    replacements are not known is left out (read as written, its names kept)."""
    found: dict[str, str] = {}
    for argument in arguments:
        value = ev.value(argument)
        entry = value.file
        path = value.literal
        if not isinstance(entry, e.ParamFile) or not entry.replacements or not path:
            continue
        source = share_source(runner.workspace, path)
        if not os.path.isfile(source):
            continue
        text, problems = read_text(source, runner.workspace.location(source))
        runner.model.diagnostics.extend(problems)
        done = runner.replace(text, entry, scope, where) if text is not None else None
        if done is not None:
            found[path] = done
    return found


def installed_source(runner: Runner, path: str) -> str | None:
    """The source file a path of a node's command line stands for, a share folder's
    file read from what the package's build installs there (``share_source``); None
    for one the build makes (a file ``configure_file`` writes or an install rule takes
    from the build folder), which no checkout holds, and for one in a folder that is
    not there, which the launch file may make."""
    if generated_at(runner.workspace, path) is not None:
        return None
    source = share_source(runner.workspace, path)
    if os.path.lexists(source):
        return source
    if not os.path.isdir(os.path.dirname(source)):
        # a folder the package does not hold: the launch file may make it and write the
        # file there before the node starts (bitbots_main's mujoco_simulation.launch.py
        # writes config/domain_bridges/robot11_bridge.yaml, then hands it to the bridge)
        return None
    return None if configured(runner.workspace, source) is not None else source


def written_by_launch(runner: Runner) -> set[str]:
    """The files the launch file writes as it runs (``LaunchModel.environment_values``:
    the paths ``open(path, 'w')`` and the other writers are handed), which no check of a
    missing file on a command line judges."""
    return {os.path.normpath(v) for v in runner.model.environment_values
            if v.startswith(os.sep)}


def perform_node(runner: Runner, action: e.NodeAction, scope: Scope) -> None:
    where = action.location
    ev = runner.evaluator(scope, where)
    given = ev.value(action.name) if action.name is not None else None
    arguments = [ev.value(a).text for a in action.arguments]
    ros_given = [ev.value(a).text for a in action.ros_arguments]
    if action.split:
        arguments = [w for a in arguments for w in a.split()]
        ros_given = [w for a in ros_given for w in a.split()]
    plain, ros_in_args = naming.split_arguments(arguments)
    # launch_ros's command line: ``arguments``, ``--ros-args`` + ``ros_arguments``, then
    # its own ``-r __node:=`` / ``__ns:=``, parameters, the scope's SetRemap rules and the
    # node's ``remappings``; rcl takes the first rule that matches (remap.c), so a rule
    # of the arguments comes before all the others, the node's name and namespace too
    ros = ros_in_args + ros_given
    parsed = naming.parse_ros_args(ros, given.literal if given is not None else None)
    name = parsed.node_name or (given.text if given is not None else "?")
    ns_given = ev.value(action.namespace).text if action.namespace is not None else None
    namespace = naming.clean_namespace(parsed.namespace) if parsed.namespace else \
        naming.node_namespace(scope.namespace, ns_given)
    full = naming.full_name(namespace, name)
    remaps = [*parsed.remaps, *naming.rules_for([
        *scope.remaps, *((ev.value(a).text, ev.value(b).text) for a, b in action.remaps)],
        name)]
    runner.model.nodes.append(node_decl(
        name=full, package=_text(ev, action.package), executable=_text(ev, action.executable),
        namespace=naming.with_slash(namespace),
        args=" ".join(plain if action.split else map(_quoted, plain)), remaps=remaps,
        conditions=scope.conditions, location=where,
        package_location=action.package_written,
        name_given=given is not None or parsed.node_name is not None,
        namespace_given=bool(parsed.namespace) or ns_given is not None
        or scope.namespace is not None))
    runner.model.nodes[-1].rewritten_files = _rewritten(runner, ev, action.arguments,
                                                        scope, where)
    made = written_by_launch(runner)
    for path in missing_argument_paths(
            plain, runner.workspace,
            lambda p: None if p in made else installed_source(runner, p)):
        runner.report("LAUNCH_NODE_ARG_PATH_MISSING", where,
                      path=runner.workspace.relpath(path), name=full)
    if not action.split:  # one word per argument: a Command's output is one of them
        runner.model.nodes[-1].arg_commands = {
            index: line for index, argument in enumerate(action.arguments[:len(plain)])
            if (line := command_line(argument, ev)) is not None}
    entries: list[e.ParamEntry] = list(action.parameters)
    entries += [e.ParamFile((path,), location=where) for path in parsed.params_files]
    entries += [((key,), (value,)) for key, value in parsed.params]
    node_params(runner, ev, full, entries, scope, where)
    for component in action.composable:
        perform_composable(runner, component, scope, full)


def perform_composable(runner: Runner, component: e.ComposableNode, scope: Scope,
                       container: str) -> None:
    where = component.location
    inner = runner.condition(component.condition, scope, where)
    if inner is None:
        return
    ev = runner.evaluator(inner, where)
    name = _text(ev, component.name)
    ns_given = ev.value(component.namespace).text if component.namespace is not None else None
    namespace = naming.node_namespace(inner.namespace, ns_given)
    full = naming.full_name(namespace, name)
    remaps = naming.rules_for([
        *inner.remaps, *((ev.value(a).text, ev.value(b).text) for a, b in component.remaps)],
        name)
    runner.model.nodes.append(node_decl(
        name=full, package=_text(ev, component.package), executable=_text(ev, component.plugin),
        namespace=naming.with_slash(namespace), remaps=remaps, conditions=inner.conditions,
        location=where, composable=True, container=container,
        package_location=component.package_written,
        name_given=component.name is not None,
        namespace_given=ns_given is not None or inner.namespace is not None))
    node_params(runner, ev, full, list(component.parameters), inner, where)


MAX_PARAM_ENTRIES = 100_000  # SetParameter-in-scope and own entries, over all nodes


def node_params(runner: Runner, ev: Evaluator, node: str, entries: list[e.ParamEntry],
                scope: Scope, where: Location) -> None:
    # name -> (value, where it is set, the setting for several nodes that gave it, if
    # one did: ``ParamDecl.setting``)
    found: dict[str, tuple[Any, Location, str | None]] = {}
    # entries for particular nodes of files given to a node whose name is not known
    # yet, in file order: (pattern, name, value, location); a later value set for all
    # replaces them, as it would whatever name the node has
    pending: list[tuple[str, str, Any, Location]] = []

    def put(name: str, leaf: Any, location: Location, setting: str | None = None) -> None:
        found[name] = (leaf, location, setting)
        pending[:] = [p for p in pending if p[1] != name]

    # where the node may get parameters we cannot see (a file not read, an entry not
    # known statically): it then has a parameter "<node>/?" set by the launch, so that
    # a read of any of its parameters is not called unset (unknown is not empty)
    unseen: list[Location] = []
    # what a dictionary of the node's own list gives it, as written, until a file later
    # in the list sets the name again for this node (``_overridden``)
    own: dict[str, Any] = {}
    # what a ``SetParameter`` in scope gives it, as written, with where: launch_ros hands
    # the node those before its own list (``_overridden``)
    scoped: dict[str, tuple[Any, Location]] = {}
    # those the node's own file sets again, said once the list is read unless a
    # dictionary of the list sets the name too (an override written beside the node)
    overridden: dict[str, tuple[Any, Any, Any, Location, Location]] = {}

    def read_file(entry: e.ParamFile, location: Location, mine: bool = True) -> None:
        placed: list[tuple[str, Any]] = []
        composable = runner.model.nodes[-1].composable
        document = runner.param_file(entry, scope, location, placed=placed,
                                     component=composable)
        if document is None:
            unseen.append(location)
            return
        if composable:
            document = naming.as_component_file(document)
        keys = _key_places(runner, placed, composable, node)
        runner.model.nodes[-1].param_files.append(
            (document, location, _key_places(runner, placed, composable, UNKNOWN_MARK)))
        outside = naming.values_outside(document)
        path = runner.value(entry.path, scope, location) if not (
            len(entry.path) == 1 and isinstance(entry.path[0], e.FileRef)) else None
        shared = path.literal if path is not None else None
        said = shared or f"{location.file}:{location.line}:{location.column}"
        # the setting its ``/**`` entries are: the file read (``file_setting``), so that
        # its nodes in several launch files are the nodes of one setting
        setting = file_setting(runner.workspace, shared) if shared else None

        def file_said(code: str, keys: list[str], listed: int) -> None:
            """What is wrong with the file, said once per file, its first keys named."""
            if not keys or (code, said) in runner.files_said:
                return
            runner.files_said.add((code, said))
            file = runner.workspace.relpath(share_source(runner.workspace, shared)) if (
                shared) else "a rewritten parameter file"
            runner.report(code, location, file=file, keys=", ".join(keys[:listed]) + (
                f" and {len(keys) - listed} more" if len(keys) > listed else ""))

        file_said("LAUNCH_PARAMS_OUTSIDE", outside, 5)
        file_said("LAUNCH_PARAMS_MIXED_SEQUENCE", [
            f"{key} ({kinds})" for key, kinds in naming.mixed_sequences(document)]
            if not composable else [], 3)
        # what the file's ``/**`` entries give every node it is given to (an entry for
        # this node's name is this node's own): a setting for each of them (``shared``)
        if shared:
            runner.file_uses.setdefault(shared, []).append(
                (document, node, location, scope.conditions))
        if UNKNOWN_MARK not in node:
            every = naming.for_every_node(document, node) if shared else set()
            for name, leaf in naming.params_for_node(document, node):
                at = keys.get(("", name), location)
                if name in own:
                    _overridden(runner, node, name, own.pop(name), found[name][0], leaf,
                                at, where)
                elif name in scoped and mine and _plain(entry):
                    written, place = scoped[name]
                    overridden[name] = (written, found[name][0], leaf, at, place)
                scoped.pop(name, None)
                put(name, leaf, at, setting if name in every else None)
            return
        if naming.names_a_node(document):
            kept = _as_given(runner, entry, scope, location)
            decl = runner.model.nodes[-1]
            decl.unnamed_param_files.append(location)
            if kept is not None and not decl.composable:  # launch_ros passes it on
                decl.params_files_given.append(kept)
        for pattern, params in naming.node_patterns(document):
            for name, leaf in naming.flatten(params):
                at = keys.get((pattern, name), location)
                if pattern == "/**":
                    put(name, leaf, at, setting)
                else:
                    pending.append((pattern, name, leaf, at))

    before = runner.param_entries
    runner.param_entries += len(scope.params) + len(entries)
    if runner.param_entries > MAX_PARAM_ENTRIES:  # each node takes every one in scope
        if before <= MAX_PARAM_ENTRIES:  # said once, where it happened
            runner.report("LAUNCH_PY_BUDGET", where, detail=f"more than {MAX_PARAM_ENTRIES} "
                          "parameter entries applied to nodes: the parameters of the "
                          "nodes from this one on are not read")
        _unseen(runner, node, scope, where)
        return
    for key, value, location in scope.params:  # SetParameter(s), SetParametersFromFile
        if key is None:
            read_file(value, location, mine=False)
            continue
        raw = dict(flat(key, value)) if isinstance(value, dict) else {}
        for name, leaf in flat(key, convert(value, ev)):
            put(name, leaf, location, f"{location.file}:{location.line}:{location.column}")
            scoped[name] = (raw.get(name, value), location)
    commands: dict[str, str] = {}
    given: dict[str, Any] = {}  # the node's dictionaries' parameters
    for entry in entries:
        if isinstance(entry, e.ParamFile):
            read_file(entry, entry.location if entry.location.file else where)
        elif isinstance(entry, e.UnknownParams):
            unseen.append(entry.location if entry.location.file else where)
        else:
            written, value = entry
            empty = null_text(value, ev)
            if empty is not None:
                # launch_ros reads substitutions' text as YAML, and YAML's null is no
                # parameter value: evaluate_parameter_dict raises TypeError
                runner.report("LAUNCH_BAD_VALUE", where, detail=(
                    f"parameter {ev.value(written).text} of {node} is given {empty!r} by "
                    "substitutions, which launch_ros reads as YAML: null, no parameter "
                    "value (TypeError 'Allowed value types are ...'), so ros2 launch stops "
                    "here; ParameterValue(..., value_type=str) would give the text"))
                continue
            text = ev.value(written).text
            raw = dict(flat(text, value)) if isinstance(value, dict) else {}
            for name, leaf in flat(text, convert(value, ev)):
                put(name, leaf, where)
                given[name] = leaf
                own[name] = raw.get(name, value)
                scoped.pop(name, None)  # the node's own value, written beside it
                overridden.pop(name, None)
            command = command_line(value, ev)
            if command is not None:
                commands[ev.value(written).text] = command
    for name, (written, mine, theirs, at, place) in overridden.items():
        _overridden(runner, node, name, written, mine, theirs, at, place, scope_given=True)
    if given:
        # launch_ros writes a node's dictionaries to a file of its own under ``/**``: a
        # parameter file of the process, which reaches a node the process makes that
        # takes every override (``plugins.attach``: ros2_control's controllers)
        runner.model.nodes[-1].param_files.append(
            ({"/**": {naming.PARAMS_KEY: given}}, where, {}))
    owner = len(runner.model.nodes) - 1  # the declaration just appended
    for name, (leaf, location, setting) in found.items():
        param = make_param(node, name, leaf, scope.conditions, location)
        param.owner, param.setting = owner, setting
        param.command = commands.get(name)
        runner.model.params.append(param)
    for pattern, name, leaf, location in pending:  # after those they may replace
        param = make_param(node, name, leaf, scope.conditions, location)
        param.owner, param.pattern = owner, pattern
        runner.model.params.append(param)
    if unseen:
        _unseen(runner, node, scope, unseen[0])


def _overridden(runner: Runner, node: str, name: str, written: Any, mine: Any,
                theirs: Any, at: Location, where: Location,
                scope_given: bool = False) -> None:
    """``LAUNCH_PARAM_OVERRIDDEN``: a value given to ``node`` for ``name`` that a parameter
    file later in what launch_ros hands the node sets again for it, so the value is never
    used. launch_ros hands a ``Node``'s ``parameters`` to rcl in order (each dictionary
    written to a file of its own) and rcl keeps the last value: roverrobotics'
    ``parameters=[{'use_sim_time': use_sim_time}, ekf_yaml]``, whose file says
    ``use_sim_time: false``, so ``use_sim_time:=true`` changed nothing. A component's
    list is the same: launch_ros' ``to_parameters_list`` makes one list of its entries in
    order (a file's section for the node where a file is) and rclcpp_components gives it
    to the node's options as overrides, of which rclcpp keeps the last of a name. Said
    when the value comes from substitutions (a launch argument meant to choose it) or is
    written out and differs from the file's; not where either value is not known and
    written out.

    ``scope_given``: the value is a ``SetParameter``'s in scope (``where``), which
    launch_ros hands a node, or puts in a component's load request, before the node's own
    list, so that the node's own values win: said only when its value comes from
    substitutions and the file's is written out in it (the launch argument reaches every
    node but this one); a literal there is a default the node's file may mean to change."""
    if scope_given and (_written_out(written) or theirs is None):
        return
    if _written_out(written) and (mine is None or theirs is None or mine == theirs):
        return
    file = at.file or "a parameter file"
    given = "a substitution (a launch argument's value)" if not _written_out(written) else (
        f"{mine!r}")
    runner.report("LAUNCH_PARAM_OVERRIDDEN", where, name=name, node=node,
                  file=f"{file}:{at.line}" if at.file and at.line else file,
                  given=f"by SetParameter here as {given}, before its own parameters,"
                  if scope_given else f"here as {given}",
                  kept=f"{theirs!r}" if theirs is not None else "a value not known here")


def _plain(entry: e.ParamFile) -> bool:
    """Whether a parameter file's values are those written in it: no ``RewrittenYaml``
    rewrites (nav2's bringup rewrites ``use_sim_time`` with the launch argument a
    ``SetParameter`` beside it gives too), no substitutions in its text, no
    ``ReplaceString``, not a rewritten file passed on by path."""
    return not (entry.rewrites or entry.value_rewrites or entry.allow_substs
                or entry.replacements or any(isinstance(part, e.FileRef)
                                             for part in entry.path))


def _written_out(value: Any) -> bool:
    """Whether a parameter value of a launch file's dictionary is written out in it (no
    substitution: a launch argument cannot change it)."""
    if isinstance(value, e.ParamValue):
        return _written_out(value.value)
    if isinstance(value, tuple):
        return all(isinstance(part, str) for part in value)
    if isinstance(value, list):
        return all(_written_out(item) for item in value)
    if isinstance(value, dict):
        return all(_written_out(item) for item in value.values())
    return isinstance(value, (str, bool, int, float))


def _key_places(runner: Runner, placed: list[tuple[str, Any]], composable: bool,
                node: str) -> dict[tuple[str, str], Location]:
    """Where each parameter of a file read for ``node`` is written, at its key's line
    (``Runner.param_file``'s ``placed``): for a node whose name is known, by ("", name)
    for what the file gives the node itself (its last section that matches, as
    ``naming.params_for_node`` takes the values); else by (section pattern, name)."""
    if not placed or not isinstance(placed[-1][1], dict):
        return {}
    file, lines = placed[-1]
    if composable:
        lines = naming.as_component_file(lines)
    at = runner.workspace.location(file, 1, 0)
    if UNKNOWN_MARK not in node:  # ``read_file`` asks only for the node's own
        return {("", name): replace(at, line=line)
                for name, line in naming.params_for_node(lines, node)
                if isinstance(line, int)}
    return {(pattern, name): replace(at, line=line)
            for pattern, params in naming.node_patterns(lines)
            for name, line in naming.flatten(params) if isinstance(line, int)}


def sections_for_no_node(runner: Runner) -> None:
    """Each parameter file given to nodes by a path known statically whose every section
    for particular nodes is for a name none of those nodes has (clearpath_control's
    imu_filter.yaml, ``imu_filter:``, given to the node ``imu_filter_node``): rcl sets
    none of those parameters (``LaunchModel.foreign_sections``, judged by the graph).
    Not when a node it is given to has a name not known statically (it may be the
    section's) or the file has no section for particular nodes (only ``/**``). Where
    some sections are for nodes it is given to, each node of a known name that no
    section is for, with the sections none of its nodes has (``lonely``: the graph keeps
    those named after that node's executable or code name)."""
    for path, uses in runner.file_uses.items():
        nodes = list(dict.fromkeys(node for _, node, _, _ in uses))
        patterns = list(dict.fromkeys(
            pattern for document, _, _, _ in uses
            for pattern, _ in naming.node_patterns(document)))
        if not patterns or "/**" in patterns:
            continue
        file = runner.workspace.relpath(share_source(runner.workspace, path))
        foreign = [p for p in patterns if not any(naming.pattern_matches(p, n) for n in nodes)]
        if len(foreign) == len(patterns) and not any(UNKNOWN_MARK in n for n in nodes):
            runner.model.foreign_sections.append(
                ForeignSections(file, nodes, patterns, uses[0][2]))
            continue
        # the nodes no section is for, beside nodes that take theirs (or whose name the
        # graph finds: it keeps only the sections no node of the configuration has): the
        # graph says the file for one of them where such a section is named after it
        for node in (n for n in nodes if UNKNOWN_MARK not in n):
            if foreign and not any(naming.pattern_matches(p, node) for p in patterns):
                where = next(location for _, name, location, _ in uses if name == node)
                runner.model.foreign_sections.append(
                    ForeignSections(file, [node], foreign, where, lonely=True))


def _unseen(runner: Runner, node: str, scope: Scope, location: Location) -> None:
    """The launch parameter ``<node>/?`` of the declaration just appended: the node may
    get parameters here that are not known statically."""
    param = make_param(node, UNKNOWN_MARK, None, scope.conditions, location)
    param.owner = len(runner.model.nodes) - 1
    runner.model.params.append(param)


def command_line(value: Any, ev: Evaluator) -> str | None:
    """The command line of a value that is one ``Command`` (``ParameterValue`` of one
    too), as text with ``?`` for unknown parts; None for any other value."""
    if isinstance(value, e.ParamValue):
        value = value.value
    if not isinstance(value, tuple):
        return None
    commands = [part for part in value if isinstance(part, e.Command)]
    rest = [part for part in value if not isinstance(part, e.Command)]
    if len(commands) == 1 and all(isinstance(p, str) and not p.strip() for p in rest):
        return ev.value(commands[0].command).text
    if commands or not any(isinstance(part, e.Var) for part in value):
        return None
    # a launch configuration that holds a Command's output (``$(var description)``)
    parts = [p for p in ev.value(value).parts if not (isinstance(p, str) and not p.strip())]
    if len(parts) != 1 or isinstance(parts[0], str):
        return None
    return next((line for output, line in ev.runner.command_outputs
                 if output is parts[0]), None)


def _as_given(runner: Runner, entry: e.ParamFile, scope: Scope,
              location: Location) -> str | None:
    """The path launch_ros gives a ``Node`` as ``--params-file``: a file used as it is
    (not rewritten, no substitutions in it); None otherwise."""
    if entry.rewrites or entry.key_rewrites or entry.value_rewrites or entry.replacements \
            or entry.root_key is not None or entry.allow_substs or (
            len(entry.path) == 1 and isinstance(entry.path[0], e.FileRef)):
        return None
    path = runner.value(entry.path, scope, location)
    return None if path is None or path.literal is None else path.literal


def flat(key: str, value: Any) -> list[tuple[str, Any]]:
    if isinstance(value, dict):
        return list(naming.flatten(value, key))
    return [(key, value)]


def null_text(value: Any, ev: Evaluator) -> str | None:
    """The text of a parameter value made of substitutions (not only text: a
    ``LaunchConfiguration``, ``$(var x)``) that launch_ros reads as YAML's null (``~``,
    ``null``, blanks): its ``evaluate_parameter_dict`` refuses it with a TypeError. Not
    the empty text, which it reads as the empty string (launch_ros#300, 2022, in every
    release from Foxy's last on; Dashing and Eloquent refused it too). None for any
    other value, and for one not known."""
    if not isinstance(value, tuple) or all(isinstance(part, str) for part in value):
        return None
    text = ev.value(value).literal
    if not text or len(text) > 16:
        return None
    try:
        return text if safe_yaml.load(text) is None else None
    except yaml.YAMLError:
        return None


def convert(value: Any, ev: Evaluator, depth: int = 0) -> Any:
    """A parameter value as launch_ros gives it to the node (None when unknown)."""
    if depth > naming.MAX_PARAM_DEPTH:
        return None
    if isinstance(value, e.ParamValue):
        inner = convert(value.value, ev, depth + 1) if not value.as_text else None
        if value.as_text:
            if isinstance(value.value, tuple):
                return ev.value(value.value).literal
            return value.value if isinstance(value.value, str) else None
        return inner
    if isinstance(value, tuple):  # Text: substitutions, evaluated then read as YAML
        known: Value = ev.value(value)
        return None if known.literal is None else naming.yaml_value(known.literal)
    if isinstance(value, str):
        return naming.yaml_value(value)
    if isinstance(value, list):
        items = [convert(item, ev, depth + 1) for item in value]
        return None if any(item is None for item in items) else items
    if isinstance(value, dict):
        return {str(k): convert(v, ev, depth + 1) for k, v in value.items()}
    if isinstance(value, (bool, int, float)):
        return value
    return None
