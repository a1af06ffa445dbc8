"""Perform a ROS 2 launch description statically, as ``LaunchService`` would.

Actions run in order against a ``Scope`` (launch configurations, pushed namespace,
global remaps and parameters, conditions). A condition whose value is known keeps or
drops its action; an unknown one makes what the action creates conditional. Nothing is
started: a ``Node`` becomes a ``NodeDecl`` and its parameters ``ParamDecl``s.
"""

from __future__ import annotations

import ast
import functools
import os
import pickle
import re
import shlex
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field, fields, is_dataclass, replace
from typing import Any

import yaml

from ... import diagnostics as diag
from ... import safe_yaml
from ...evaluate.syntax import parse
from ...files import read_text
from ...model.conditions import Condition
from ...model.launch_tree import (
    ArgOrigin,
    ArgUse,
    LaunchArg,
    LaunchCondition,
    LaunchItem,
    PackageUse,
    installed_check,
)
from ...model.location import Location
from ...model.values import UNKNOWN_MARK, Unknown, Value
from ...share import generated_at, share_source
from ...workspace import Workspace
from ..model import (
    LaunchModel,
    NodeDecl,
    ParamDecl,
    RecordedEnvironment,
    found_nowhere,
    unset_variables,
)
from ..partial_yaml import MARK, marked_text, unknown_parts
from ..paths import missing_argument_paths, written_absolute
from ..tree import node_items
from . import entities as e
from . import naming, recording
from .substitutions import Evaluator

MAX_INCLUDE_DEPTH = 24
MAX_ACTIONS = 20_000
MAX_PARAM_FILE = 1024 * 1024
MAX_WALKED = 50_000  # files and folders of a package looked through for ros2 launch's file
MAX_ITERATIONS = 1_000  # of one ForEach / ForLoop

# diagnostics that say part of a launch file was not read as launch would run it: what
# that part would have declared or read of the launch configurations is not seen
MAX_SKIPPED_DEPTH = 8  # groups a left-out include may be in
MAX_SKIPPED_VISITS = 20_000  # values of a skipped action looked through for names
MAX_SKIPPED_DEPTH = 24
HIDING_CODES = frozenset({
    "LAUNCH_UNSUPPORTED", "LAUNCH_PY_UNSUPPORTED", "LAUNCH_PY_BUDGET", "LAUNCH_PY_SYNTAX",
    "LAUNCH_XML_SYNTAX", "LAUNCH_YAML_SYNTAX", "LAUNCH_UNKNOWN_TAG", "LAUNCH_FILE_MISSING",
})

# path -> actions (or None when the file could not be read); set by ros2.__init__
Parser = Callable[[str, "Runner", Location], "list[e.Action] | None"]


# ros2 launch's options that print the launch description and start nothing, and
# those that take a value
_LAUNCH_PRINTS = frozenset({"-p", "--print", "--print-description", "-s", "--show-args",
                            "--show-arguments"})
_LAUNCH_OPTIONS_WITH_VALUE = frozenset({"--launch-prefix", "--launch-prefix-filter"})
# the agents that put the topics of a micro-ROS or XRCE-DDS client (PX4's
# uxrce_dds_client, a microcontroller's micro-ROS) on the ROS 2 graph, run as programs
# (the Python nodes' reader counts them too: extract.python.visitor._ROS_TOOLS)
_XRCE_AGENTS = frozenset({"MicroXRCEAgent", "micro-ros-agent", "micro_ros_agent"})


@dataclass
class Scope:
    configs: dict[str, Value | None]
    namespace: str | None = None
    remaps: list[tuple[str, str]] = field(default_factory=list)
    # SetParameter (name, value, where), and SetParametersFromFile as (None, file, where)
    params: list[tuple[str | None, Any, Location]] = field(default_factory=list)
    conditions: tuple[Condition, ...] = ()
    environment: dict[str, str] = field(default_factory=dict)
    file: str = ""
    # the launch tree's file or group being performed (shared by copies of the scope)
    item: LaunchItem = field(default_factory=lambda: LaunchItem("file", ""))
    # where actions the reader could not see were performed in this scope (a value not
    # known statically among the entities, an action not interpreted, an include not
    # read), each with what it was: any of them may have declared or set a launch
    # configuration, so one not seen here is not known to be unset
    unseen: tuple[tuple[Location, str], ...] = ()

    def copy(self) -> Scope:
        return replace(self, configs=dict(self.configs), remaps=list(self.remaps),
                       params=list(self.params), environment=dict(self.environment))


def near_name(name: str, other: str) -> bool:
    """Whether ``other`` is most likely ``name`` misspelt: at most one edit per four
    letters and never more than two (``query.absence.distance``, the similar-name
    rule's measure, as ``Workspace.misspelt`` takes it)."""
    from ...query.absence import MAX_DISTANCE, distance
    limit = min(MAX_DISTANCE, len(name) // 4)
    return name != other and limit >= 1 and abs(len(name) - len(other)) <= limit and (
        distance(name, other) <= limit)


@dataclass
class IncludeFrame:
    """An include being performed: what its file and the files it includes in turn
    declare and read of the launch configurations, and the first part of them that was
    not seen (``IncludeFrame.hidden``), to tell which of the arguments the include
    passes are used (``LaunchArg.use``)."""

    declared: set[str] = field(default_factory=set)
    read: set[str] = field(default_factory=set)
    hidden: str = ""
    # what the include's file itself (not the files it includes) declares or sets of
    # the launch configurations (``config_own``): a configuration it reads and does
    # not hold is the choice of the files around it
    own: set[str] = field(default_factory=set)

    def use(self, name: str) -> tuple[ArgUse, str]:
        """How the include's file uses an argument it is passed, and what was not seen
        when that is not known."""
        if name in self.declared:
            return "declared", ""
        if name in self.read:
            return "read", ""
        if self.hidden:
            return "unknown", self.hidden
        return "unused", ""


class _Written(Mapping[str, str]):
    """The launch process's environment: what its Python launch files wrote in
    ``os.environ`` as they were loaded (``written``) over the configuration's."""

    def __init__(self, base: Mapping[str, str]) -> None:
        self.base = base
        self.written: dict[str, str] = {}

    def __getitem__(self, key: str) -> str:
        return self.written[key] if key in self.written else self.base[key]

    def __contains__(self, key: object) -> bool:
        return key in self.written or key in self.base

    def __iter__(self) -> Iterator[str]:
        yield from self.written
        yield from (key for key in self.base if key not in self.written)

    def __len__(self) -> int:
        return len(self.written) + sum(1 for key in self.base if key not in self.written)


class _Scoped(Mapping[str, str]):
    """The environment where a file is loaded: the variables ``SetEnvironmentVariable``
    / ``UnsetEnvironmentVariable`` actions in scope set or unset (``Scope.environment``,
    an unset one marked ``NAME\0unset``) over the process's."""

    def __init__(self, base: Mapping[str, str], scoped: Mapping[str, str]) -> None:
        self.base = base
        self.scoped = scoped

    def __getitem__(self, key: str) -> str:
        if key in self.scoped:
            return self.scoped[key]
        if key + "\0unset" in self.scoped:
            raise KeyError(key)
        return self.base[key]

    def __contains__(self, key: object) -> bool:
        return isinstance(key, str) and (key in self.scoped or (
            key + "\0unset" not in self.scoped and key in self.base))

    def __iter__(self) -> Iterator[str]:
        yield from (key for key in self.scoped if "\0" not in key)
        yield from (key for key in self.base
                    if key not in self.scoped and key + "\0unset" not in self.scoped)

    def __len__(self) -> int:
        return sum(1 for _ in self)


# programs whose arguments name the files or folders they make: a path of them that is
# not there is no file missing (``_missing_paths``)
_FILE_MAKERS = frozenset({"cp", "mv", "mkdir", "touch", "ln", "tee", "install", "rsync",
                          "dd", "tar", "unzip", "wget", "curl"})
# a shell redirection, alone (its file the next word) or with its file (``>out``)
_REDIRECT = re.compile(r"\d?>>?|&>|\d?>>?\S+|&>\S+")


class Runner:
    def __init__(self, workspace: Workspace, environment: Mapping[str, str],
                 parse: Parser) -> None:
        self.workspace = workspace
        self.parse = parse
        self.model = LaunchModel()
        # what the launch reads of the machine's environment is noted: a path under it
        # follows the machine, not a folder the launch file hard-codes; what a Python
        # launch file writes in ``os.environ`` as it is loaded is the process's from then
        # on, for the files it includes (loaded after it) and the substitutions
        # performed after (``wrote``)
        self._process = _Written(RecordedEnvironment(environment, self.model.environment_values))
        self.environment: Mapping[str, str] = self._process
        # the variables a launch file wrote under a test not known statically: not known
        self.environment_unsure: set[str] = set()
        # the environment of the scope whose file is being loaded (``run_file``)
        self.scope_environment: Mapping[str, str] = {}
        self.stack: list[str] = []
        self.performed = 0
        # the arguments of the command line that starts the first file (``name:=value``),
        # which a Python launch file may read from ``sys.argv`` (``load``)
        self.command_line: Mapping[str, str] = {}
        # ``sys.argv`` of the ``ros2 launch`` process (``command_argv``), for every file
        # it loads; None when the first file is in no package of the workspace
        self.argv: list[Any] | None = None
        # the action lists being run, innermost last (``run``)
        self.running: list[list[e.Action]] = []
        self.param_entries = 0  # parameter entries applied to nodes (nodes.node_params)
        # each parameter file given to nodes by a path known statically: the document
        # read for each use, the node's full name, where and under which conditions
        # (``nodes.sections_for_no_node``)
        self.file_uses: dict[str, list[tuple[Any, str, Location,
                                             tuple[Condition, ...]]]] = {}
        # (code, parameter file) of what was said of a file (LAUNCH_PARAMS_OUTSIDE, ...)
        self.files_said: set[tuple[str, str]] = set()
        self.anon: dict[str, Unknown] = {}
        self.guard: LaunchCondition | None = None  # the condition of the action at hand
        # the unknown output of each Command evaluated, with its command line: a value
        # that is one of them, through launch configurations (``<let name="d"
        # value="$(command 'xacro ...')"/>`` then ``value="$(var d)"``), is that command's
        # output, which robot descriptions read (``nodes.command_line``)
        self.command_outputs: list[tuple[Unknown, str]] = []
        self.includes: list[IncludeFrame] = []  # the includes being performed, innermost last
        # the whole run's (``unused_arguments``): each argument declared, where; the
        # launch configurations read by name; the first part not seen, if any
        self.declared_args: list[tuple[str, Location]] = []
        self.all_read: set[str] = set()
        # the launch configurations read where nothing had set them (their default, or
        # none, taken), where no action the reader did not see could have
        self.read_unset: set[str] = set()
        # the launch files performed, by the name a location gives them -> their path
        self.performed_files: dict[str, str] = {}
        self.all_hidden = ""
        # the values of the ForEach / ForLoop iterations being performed, innermost last
        # (launch's context locals, which ``$(for-var)`` / ``$(index)`` read); None for
        # an iteration whose values are not known statically
        self.loop_values: list[dict[str, str] | None] = []

    # -- diagnostics and values --------------------------------------------------
    def report(self, code: str, location: Location, **params: object) -> None:
        self.take_said([diag.make(code, location, **params)])

    def take_said(self, found: list[diag.Diagnostic]) -> None:
        """Diagnostics said here (``report``) or by a Python function launch called
        when it ran (an OpaqueFunction's, a ForEach iteration's), once each, those that
        hide part of the launch noted as such."""
        for said in found:
            if said.code in HIDING_CODES:
                self.hidden(said)
            if said not in self.model.diagnostics:
                self.model.diagnostics.append(said)

    # -- what the includes being performed declare and read -------------------------
    def config_read(self, name: str) -> None:
        """A launch configuration read by name (``LaunchConfiguration``, ``$(var)``,
        ``context.launch_configurations``): the includes being performed use it."""
        self.all_read.add(name)
        for frame in self.includes:
            frame.read.add(name)

    def read_skipped(self, action: Any) -> None:
        """The launch configurations an action its condition skips names by name (its
        LaunchConfiguration / ``$(var)`` substitutions): read there when the condition
        holds, so an include's argument of that name is used, not ignored
        (webots_ros2_epuck's robot_tools_launch.py reads ``fill_map`` in its mapper's
        parameters, the mapper under ``IfCondition(use_mapper)``, false by default)."""
        for name in _names_read(action):
            self.config_read(name)

    def config_declared(self, name: str) -> None:
        for frame in self.includes:
            frame.declared.add(name)
        self.config_own(name)

    def config_own(self, name: str) -> None:
        """The file being performed declares or sets the launch configuration ``name``
        (``DeclareLaunchArgument``, ``<let>``, a group's configurations)."""
        if self.includes:
            self.includes[-1].own.add(name)

    def chosen_by(self, text: e.Text) -> str:
        """The launch configurations ``text`` reads (by names known statically) that the
        included file being performed neither declares nor sets, comma-separated: their
        values come from the files that include it (autoware_global_parameter_loader's
        ``FindPackageShare([LaunchConfiguration('vehicle_model'), '_description'])``,
        ``vehicle_model`` given by the launch file that includes it). Empty in the file
        the configuration starts (its configurations are the command line's)."""
        if not self.includes:
            return ""
        own = self.includes[-1].own
        return ", ".join(sorted({name for name in _names_read(text) if name not in own}))

    def hidden(self, what: diag.Diagnostic | str, where: Location | None = None) -> None:
        """Part of the includes being performed is not seen (``what``: the diagnostic that
        says so, or what it was and ``where``): any launch configuration may be read
        there."""
        if isinstance(what, str):
            text = f"{what} ({where.file}:{where.line})" if where is not None else what
        else:
            text = f"{what.code} at {what.location.file}:{what.location.line}"
        self.all_hidden = self.all_hidden or text
        for frame in self.includes:
            if not frame.hidden:
                frame.hidden = text

    def uses(self, package: str, location: Location,
             conditions: tuple[Condition, ...] = (), chosen_by: str = "",
             tried: bool = False) -> None:
        """A substitution asked for the folder of ``package`` (``?`` for parts not known),
        under ``conditions`` (a Python test of whether a package is installed, maybe);
        ``chosen_by``: the launch configurations of its name the file does not hold;
        ``tried``: asked for where the file goes on without it (``FindPackage.tried``)."""
        self.model.package_uses.append(PackageUse(package, location, guard=installed_check(
            c.text for c in conditions if c.kind == "launch" and c.statement == "if") or (
            package if tried else None), chosen_by=chosen_by))

    def evaluator(self, scope: Scope, location: Location) -> Evaluator:
        return Evaluator(self, scope, location)

    def loaded_environment(self) -> Mapping[str, str]:
        """The environment a launch file being loaded sees (``os.environ`` of a Python
        one): the process's under the actions in scope that set or unset variables."""
        return _Scoped(self.environment, self.scope_environment)

    def wrote(self, written: Mapping[str, str], unsure: set[str]) -> None:
        """A Python launch file, loading, wrote ``written`` in ``os.environ`` and some
        of ``unsure`` under a test not known statically: the process's environment from
        here on (``ros2 launch`` loads an included file when the include runs, after
        its includer was loaded)."""
        for key, value in written.items():
            self._process.written[key] = value
            self.environment_unsure.discard(key)
        self.environment_unsure |= unsure - written.keys()

    def value(self, t: e.Text | None, scope: Scope, location: Location) -> Value | None:
        if t is None:
            return None
        return self.evaluator(scope, location).value(t)

    def condition(self, cond: e.Cond | None, scope: Scope,
                  location: Location) -> Scope | None:
        """None if ``cond`` is known false, else the scope for what it guards."""
        if cond is None:
            return scope
        truth = self.evaluator(scope, location).truth(cond)
        self.guard = recording.condition(cond, scope.configs, truth,
                                         {**self.environment, **scope.environment})
        if truth is None:
            statement = "unless" if cond.negate else "if"
            made = Condition(cond.source or "?", "launch", statement, location,
                             compares=self.compared(cond, scope, location), runs=cond.runs)
            return replace(scope, conditions=(*scope.conditions, made))
        return scope if truth else None

    def compared(self, cond: e.Cond, scope: Scope,
                 location: Location) -> tuple[str, tuple[str, ...], bool] | None:
        """``(argument, strings, holds when it is one of them)`` for a condition not
        decided that compares one launch argument with known strings:
        ``LaunchConfigurationEquals`` / ``NotEquals``, ``$(equals $(var x) s)`` /
        ``$(not-equals ..)`` (their Python classes too), or a ``PythonExpression`` /
        ``$(eval)`` that compares the quoted argument alone (``'"', x, '" == "s"'``,
        ``... in ('a', 'b')``); else None. Conditions of one argument and strings that
        cannot both match then exclude each other (``model.conditions.contradict``)."""
        evaluator = self.evaluator(scope, location)
        expression = cond.expression
        if cond.equals is None and len(expression) == 1 and isinstance(
                expression[0], e.Eval):
            found = _compared_in(expression[0].expression, evaluator)
            if found is None:
                return None
            return found[0], found[1], found[2] != cond.negate
        equal = True
        if cond.equals is not None:
            sides: tuple[e.Text, ...] = (expression, cond.equals)
        elif len(expression) == 1 and isinstance(expression[0], e.Logic) and (
                expression[0].op in ("equals", "notequals")) and len(
                expression[0].operands) == 2:
            sides = expression[0].operands
            equal = expression[0].op == "equals"
        else:
            return None
        for variable, other in (sides, sides[::-1]):
            if len(variable) != 1 or not isinstance(variable[0], e.Var):
                continue
            name = evaluator.value(variable[0].name).literal
            string = evaluator.value(other).literal
            if name is not None and string is not None:
                return name, (string,), equal != cond.negate
        return None

    # -- files ---------------------------------------------------------------------
    def run_file(self, path: str, scope: Scope, where: Location) -> None:
        if self.stack and not os.path.isabs(path):
            # an include by a relative path: launch opens it from the folder ``ros2
            # launch`` runs in, which no file says (not the folder this tool runs in);
            # what it would start stays unknown, not missing
            scope.item.kind = "include"
            self.not_seen(scope, where, f"the include of {path}")
            self.report("LAUNCH_UNKNOWN_VALUE", where, detail=(
                f"launch file {path!r} is a relative path, opened from the folder ros2 "
                "launch runs in; it is not read"))
            return
        reached = os.path.abspath(path)  # $(dirname) is where the file was found
        path = share_source(self.workspace, reached)  # the source file installed there
        if path in self.stack or len(self.stack) >= MAX_INCLUDE_DEPTH:
            self.report("LAUNCH_BAD_VALUE", where,
                        detail=f"include cycle or depth: {self.workspace.relpath(path)}")
            return
        if self.stack and not self.workspace.readable(path, self.environment):
            scope.item.kind = "include"  # the include that reached it, not read
            self.not_seen(scope, where, f"the include of {self.workspace.relpath(path)}")
            # as parameter files: an included launch file is read only from the workspace
            # and the installed packages (Clearpath's robot_spawn.launch.py includes
            # $HOME/clearpath/platform/launch/*.launch.py, written on the robot by the
            # generator it starts first): what it would start stays unknown, not missing
            self.report("LAUNCH_UNKNOWN_VALUE", where, detail=(
                f"launch file {path} is outside the workspace and installed packages; "
                "it is not read"))
            if written_absolute(path, self.stack[-1]):
                self.report("LAUNCH_INCLUDE_ABSOLUTE", where, path=path)
            return
        if not os.path.isfile(path):
            made = generated_at(self.workspace, path)
            if made is not None:
                # installed from the build folder (ros_gz_sim's gz_sim.launch.py, made by
                # configure_file from gz_sim.launch.py.in): there, but not readable here
                scope.item.kind = "include"
                self.not_seen(scope, where,
                              f"the include of {self.workspace.relpath(path)}")
                self.report("LAUNCH_UNKNOWN_VALUE", where, detail=(
                    f"launch file {self.workspace.relpath(path)} is made by the build "
                    f"(installed from the build folder at {self.workspace.relpath(made[0])}"
                    f":{made[1]}); it is not read"))
                return
            if (note := self.workspace.submodule_note(path)) is not None:
                scope.item.kind = "include"
                self.not_seen(scope, where, f"the include of {self.workspace.relpath(path)}")
                self.report("LAUNCH_UNKNOWN_VALUE", where, detail=note)
                return
            self.report("LAUNCH_FILE_MISSING", where, path=self.workspace.relpath(path))
            return
        before = len(self.model.diagnostics)
        self.scope_environment = scope.environment
        actions = self.parse(path, self, where)
        for said in self.model.diagnostics[before:]:
            if said.code in HIDING_CODES:
                self.hidden(said)
        if actions is None:
            return
        self.model.files.append(self.workspace.relpath(path))
        self.performed_files.setdefault(self.workspace.relpath(path), path)
        self.stack.append(path)
        outer = scope.file
        scope.file = reached
        try:
            self.run(actions, scope)
        finally:
            scope.file = outer
            self.stack.pop()

    # -- actions -------------------------------------------------------------------
    def run(self, actions: list[e.Action], scope: Scope) -> None:
        # a copy, which an OpaqueFunction may lengthen (``do_Callback``)
        pending = list(actions)
        self.running.append(pending)
        try:
            self._run(pending, scope)
        finally:
            self.running.pop()

    def _run(self, actions: list[e.Action], scope: Scope) -> None:
        for action in actions:
            self.performed += 1
            if self.performed > MAX_ACTIONS:
                self.report("LAUNCH_PY_BUDGET", action.location,
                            detail=f"more than {MAX_ACTIONS} launch actions")
                return
            self.guard = None
            inner = self.condition(action.condition, scope, action.location)
            if inner is None:
                self.read_skipped(action)
                left_out = recording.skipped(action, self.guard) if self.guard else None
                if left_out is not None:
                    if left_out.kind == "include" and os.path.isabs(left_out.name):
                        left_out.name = self.workspace.relpath(left_out.name)
                    scope.item.add(left_out)
                self.skipped_includes(action, scope)
                continue
            handler = getattr(self, "do_" + type(action).__name__, None)
            if handler is None:
                self.report("LAUNCH_UNSUPPORTED", action.location,
                            detail=f"{type(action).__name__} is not interpreted")
                continue
            if inner is scope:
                handler(action, scope)
                continue
            # a conditional action: its own effects carry the condition, but the
            # launch configurations and namespaces it sets still reach the scope
            saved = scope.conditions
            scope.conditions = inner.conditions
            try:
                handler(action, scope)
            finally:
                scope.conditions = saved

    def take_guard(self) -> LaunchCondition | None:
        guard, self.guard = self.guard, None
        return guard

    def do_DeclareArg(self, action: e.DeclareArg, scope: Scope) -> None:
        self.config_declared(action.name)
        self.declared_args.append((action.name, action.location))
        self.record_arg(action, scope)
        if action.name in scope.configs:
            return
        if action.default is None:
            scope.configs[action.name] = None
            self.report("LAUNCH_ARG_UNSET", action.location, name=action.name)
        else:
            scope.configs[action.name] = self.value(action.default, scope, action.location)
        if len(self.stack) == 1:
            value = scope.configs[action.name]
            self.model.args[action.name] = value.text if value is not None else None

    def unused_arguments(self) -> None:
        """Each launch argument declared that nothing of the whole launch reads by name,
        said once where it is declared: LAUNCH_ARG_MISSPELT (a warning) when a
        configuration of a near name is read where nothing had set it, or never
        declared (raspimouse_slam_navigation_ros2's pc_navigation.launch.py declared
        ``use_sim_tim`` and read ``LaunchConfiguration('use_sim_time',
        default='False')``, which it hands to navigation2's bringup, whose own
        declaration of ``use_sim_time`` comes too late for that read), else
        LAUNCH_ARG_UNUSED (an info: a leftover, harmless).
        Nothing is said when a part of the launch was not seen (an include not read, a
        function not interpreted, a configuration of a name not known), nor when the
        name is written in the launch files performed anywhere but where it is declared:
        an action the reader performs only in part (ros_gz_bridge's XML tag, whose
        ``container_name="$(var container_name)"`` it does not read) or not at all
        (slam_toolbox's ``EmitEvent(..., condition=IfCondition(autostart))``) may read
        it. An argument a library's launch helper declares (moveit_configs_utils'
        ``monitor_dynamics``), whose name the file calling it does not write, is not
        the user's to remove."""
        if self.all_hidden:
            return
        texts: dict[str, str] = {}  # read once a name is unread (mostly none is)
        declared = {n for n, _ in self.declared_args}
        said: set[str] = set()
        for name, where in self.declared_args:
            if name in self.all_read or name in said:
                continue
            said.add(name)
            if not texts:
                for name_of, path in self.performed_files.items():
                    text, _ = read_text(path, Location(file=name_of))
                    texts[name_of] = text or ""
            written = re.compile(rf"(?<!\w){re.escape(name)}(?!\w)")
            sites = {(w.file, w.line) for n, w in self.declared_args if n == name}
            if not all(written.search(texts.get(file or "", "")) for file, _ in sites):
                continue  # declared by code the user does not write
            if sum(len(written.findall(text)) for text in texts.values()) > len(sites):
                continue  # written elsewhere: perhaps read by what is not interpreted
            near = sorted(n for n in self.all_read
                          if (n not in declared or n in self.read_unset)
                          and near_name(name, n))
            if near:
                self.report("LAUNCH_ARG_MISSPELT", where, name=name, near=", ".join(near))
            else:
                self.report("LAUNCH_ARG_UNUSED", where, name=name)

    def record_arg(self, action: e.DeclareArg, scope: Scope) -> None:
        """The argument on the tree, unless the including file gave it already."""
        if scope.item.arg(action.name) is not None:
            return
        if action.name in scope.configs:
            given = scope.configs[action.name]
            origin: ArgOrigin = "command line" if len(self.stack) == 1 else "include"
            scope.item.args.append(LaunchArg(
                action.name, given.text if given is not None else None, origin,
                action.location))
            return
        value = None if action.default is None else self.value(
            action.default, scope, action.location)
        scope.item.args.append(LaunchArg(
            action.name, value.text if value is not None else None,
            "unset" if action.default is None else "default", action.location))

    def do_SetConfig(self, action: e.SetConfig, scope: Scope) -> None:
        name = self.value(action.name, scope, action.location)
        if name is None or name.literal is None:
            return
        self.config_own(name.literal)
        scope.configs[name.literal] = self.value(action.value, scope, action.location)

    def do_Group(self, action: e.Group, scope: Scope) -> None:
        inner = scope.copy() if action.scoped else scope
        inner.item = scope.item.add(LaunchItem(
            "group", "", action.location, namespace=scope.namespace or "/",
            condition=self.take_guard()))
        if action.scoped and not action.forwarding:
            inner.configs = {}
            inner.unseen = ()
        for key, val in action.configs:
            name = self.value(key, scope, action.location)
            if name is not None and name.literal is not None:
                self.config_own(name.literal)
                inner.configs[name.literal] = self.value(val, scope, action.location)
        self.run(action.actions, inner)

    def do_ResetConfigs(self, action: e.ResetConfigs, scope: Scope) -> None:
        """``ResetLaunchConfigurations``: every launch configuration goes, the pushed
        namespace, SetRemap and SetParameter(s) with them (launch_ros keeps those as
        launch configurations), except the ones given, performed before the reset."""
        kept: dict[str, Value | None] = {}
        for key, val in action.keeps or []:
            name = self.value(key, scope, action.location)
            if name is not None and name.literal is not None:
                kept[name.literal] = self.value(val, scope, action.location)
        scope.configs.clear()
        scope.configs.update(kept)
        scope.unseen = ()
        scope.namespace = None
        scope.remaps.clear()
        scope.params.clear()

    def do_PushNamespace(self, action: e.PushNamespace, scope: Scope) -> None:
        value = self.value(action.namespace, scope, action.location)
        if value is not None:
            scope.namespace = naming.push_namespace(scope.namespace, value.text)
            scope.item.pushed.append(value.text)
            scope.item.namespace = scope.namespace or "/"

    def do_SetRemap(self, action: e.SetRemap, scope: Scope) -> None:
        src = self.value(action.source, scope, action.location) or Value()
        dst = self.value(action.target, scope, action.location) or Value()
        scope.remaps.append((src.text, dst.text))
        scope.item.remaps.append((src.text, dst.text))

    def do_SetParam(self, action: e.SetParam, scope: Scope) -> None:
        name = self.value(action.name, scope, action.location)
        if name is not None:
            scope.params.append((name.text, action.value, action.location))
            scope.item.params.append(name.text)

    def do_SetParamFile(self, action: e.SetParamFile, scope: Scope) -> None:
        """``SetParametersFromFile``: the file's path is performed now; each node in
        scope reads the file and takes what its patterns give it."""
        path = self.value(action.path, scope, action.location) or Value.unknown()
        if path.literal is None:
            self.report("LAUNCH_PARAM_FILE", action.location,
                        detail=f"parameter file {path} is not known statically")
            return
        entry = e.ParamFile((path.literal,), location=action.location)
        scope.params.append((None, entry, action.location))
        scope.item.params.append(path.literal)

    def do_SetEnv(self, action: e.SetEnv, scope: Scope) -> None:
        name = self.value(action.name, scope, action.location)
        if name is None or name.literal is None:
            return
        value = self.value(action.value, scope, action.location)
        if value is None:
            scope.environment.pop(name.literal, None)
            scope.environment[name.literal + "\0unset"] = ""
        elif value.literal is not None:
            scope.environment[name.literal] = value.literal

    def skipped_includes(self, action: e.Action, scope: Scope, depth: int = 0) -> None:
        """An include a decided condition leaves out (itself, or in a group it leaves
        out) reaches its file with another value of the condition's arguments
        (``include_patterns``, as the ROS 1 loader keeps them): its path, when known,
        evaluated with nothing said or used (the include is not performed)."""
        if isinstance(action, e.Group) and depth < MAX_SKIPPED_DEPTH:
            for inner in action.actions:
                self.skipped_includes(inner, scope, depth + 1)
        if not isinstance(action, e.Include):
            return
        said, used = len(self.model.diagnostics), len(self.model.package_uses)
        hidden = [frame.hidden for frame in self.includes]
        all_hidden = self.all_hidden
        path = self.value(action.path, scope, action.location)
        del self.model.diagnostics[said:]
        del self.model.package_uses[used:]
        for frame, was in zip(self.includes, hidden, strict=True):
            frame.hidden = was
        self.all_hidden = all_hidden
        if path is not None and path.literal is not None and path.literal.strip():
            self.model.include_patterns.append(re.escape(os.path.abspath(path.literal)))

    def do_Include(self, action: e.Include, scope: Scope) -> None:
        path = self.value(action.path, scope, action.location)
        if path is None or path.literal is None:
            unset = unset_variables(path) if path is not None else []
            if path is not None and unset and found_nowhere(path, environment=True):
                # unknown only through environment variables the configuration does not
                # set (``$(env ARM_TYPE)``, no default; launch raises SubstitutionFailure
                # without them): said once, naming them, as the ROS 1 loader says it
                unsure = [name for name in unset if name in self.environment_unsure]
                self.report("LAUNCH_UNKNOWN_VALUE", action.location, detail=(
                    f"included file {path} is not known statically: environment "
                    f"variable{'s' if len(unset) > 1 else ''} {', '.join(unset)} "
                    f"{'are' if len(unset) > 1 else 'is'} not set in the configuration"
                    + (f" (a launch file sets {', '.join(unsure)} under a test not known "
                       "statically)" if unsure else "")))
            elif path is None or not found_nowhere(path):
                self.report("LAUNCH_UNSUPPORTED", action.location,
                            detail=f"included file {path} is not known statically")
            self.unread(str(path) if path is not None else "?", scope, action.location)
            self.not_seen(scope, action.location, f"the include of {path}")
            return
        item = LaunchItem("file", self.workspace.relpath(share_source(
            self.workspace, os.path.abspath(path.literal))), action.location,
            namespace=scope.namespace or "/", condition=self.take_guard())
        passed: list[LaunchArg] = []
        for key, val in action.args:
            name = self.value(key, scope, action.location)
            if name is not None and name.literal is not None:
                value = self.value(val, scope, action.location)
                scope.configs[name.literal] = value
                passed.append(LaunchArg(name.literal, value.text if value is not None
                                        else None, "include", action.location))
        item.args.extend(passed)
        outer = scope.item
        scope.item = outer.add(item)
        frame = IncludeFrame()
        self.includes.append(frame)
        try:
            self.run_file(path.literal, scope, action.location)
        finally:
            scope.item = outer
            self.includes.pop()
        for arg in passed:  # the frames around it saw its reads and declarations too
            arg.use, arg.unseen = frame.use(arg.name)

    def do_Delayed(self, action: e.Delayed, scope: Scope) -> None:
        inner = scope.copy()
        inner.conditions = (*scope.conditions,
                            Condition(action.why, "launch", action.statement,
                                      action.location))
        self.run(action.actions, inner)

    def do_ForEach(self, action: e.ForEach, scope: Scope) -> None:
        """``ForEach`` / ``ForLoop``: the iterations its values give, each in the scope
        (launch runs the entities an iteration makes where the loop is: what they set of
        the launch configurations stays), its values in ``loop_values`` while they run.
        Values not known statically: the loop may run any number of times; its entities
        once, under that loop (names made of its values keep '?'), not never."""
        value = self.value(action.values, scope, action.location) or Value.unknown()
        items = self._iterations(action, value.literal, action.location) \
            if value.literal is not None else None
        if items is None and value.literal is not None:
            return  # launch fails there (said): nothing of the loop runs
        if items is None:
            what = "ForLoop of a length" if action.length else "ForEach over values"
            cond = Condition(f"{what} not known statically: {value.text}", "launch",
                             "for", action.location)
            saved = scope.conditions
            scope.conditions = (*saved, cond)
            try:
                self._iteration(action, None, scope)
            finally:
                scope.conditions = saved
            return
        for item in items:
            self._iteration(action, item, scope)

    def _iteration(self, action: e.ForEach, item: dict[str, Any] | None,
                   scope: Scope) -> None:
        self.loop_values.append(None if item is None else {
            str(key): str(value) for key, value in item.items()})
        try:
            if action.make is None:
                self.run(action.children, scope)
                return
            made, found = action.make(item)
            self.take_said(found)
            self.run(made, scope)
        finally:
            self.loop_values.pop()

    def _iterations(self, action: e.ForEach, text: str, where: Location
                    ) -> list[dict[str, Any]] | None:
        """The values of each iteration, as launch makes them of the performed text:
        ``ForLoop``, ``int(text)`` iterations ``{index: i}``; ``ForEach``, each non-empty
        part between ``;`` read as YAML (an empty document no iteration), which must be
        a mapping (launch calls the function with it as keyword arguments). None, said,
        where launch raises."""
        if action.length:
            try:
                count = int(text.strip())
            except ValueError:
                self.report("LAUNCH_BAD_VALUE", where, detail=f"ForLoop length {text!r} is "
                            "not an integer: launch raises ValueError")
                return None
            if count > MAX_ITERATIONS:
                self.report("LAUNCH_PY_BUDGET", where,
                            detail=f"a ForLoop of more than {MAX_ITERATIONS} iterations")
                count = MAX_ITERATIONS
            return [{str(action.index): index} for index in range(count)]
        out: list[dict[str, Any]] = []
        for part in filter(None, text.strip().split(";")):
            try:
                loaded = safe_yaml.load(part.strip())
            except yaml.YAMLError as err:
                mark = getattr(err, "problem", None) or type(err).__name__
                self.report("LAUNCH_BAD_VALUE", where, detail=f"ForEach values {part.strip()!r}"
                            f" are not valid YAML ({mark}): launch raises")
                return None
            if loaded is None:
                continue
            if not isinstance(loaded, dict):
                self.report("LAUNCH_BAD_VALUE", where, detail=f"ForEach values "
                            f"{part.strip()!r} are not a YAML mapping: launch raises "
                            "TypeError calling the iteration's function")
                return None
            if len(out) == MAX_ITERATIONS:
                self.report("LAUNCH_PY_BUDGET", where,
                            detail=f"a ForEach of more than {MAX_ITERATIONS} iterations")
                break
            out.append(loaded)
        return out

    def do_Callback(self, action: e.Callback, scope: Scope) -> None:
        ev = self.evaluator(scope, action.location)
        made, found = action.run(ev.value, functools.partial(self.configuration, scope, ev))
        self.take_said(found)
        # what it added to the launch description that holds it runs after the rest of
        # that description, as launch visits the list that grew
        if action.later and action.condition is not None:
            # under the condition of the OpaqueFunction that added them
            self.running[-1].append(e.Group(action.later, scoped=False,
                                            condition=action.condition,
                                            location=action.location))
        else:
            self.running[-1].extend(action.later)
        self.run(made, scope)

    def configuration(self, scope: Scope, ev: Evaluator, name: str) -> tuple[str, Any]:
        """How ``scope`` holds the launch configuration ``name`` for an OpaqueFunction's
        ``context.launch_configurations`` (``python_values.Context.configuration``).
        ``global_params`` is the list launch_ros' ``SetParameter`` and
        ``SetParametersFromFile`` extend: a ``(name, value)`` pair per parameter, the
        value as launch_ros evaluates it (substitutions performed, then read as YAML),
        and a file's path as a text (Autoware's launch files read the vehicle's
        dimensions back from it: ``dict(context.launch_configurations.get(
        "global_params", {}))``); a value not known here is ``Unknown``, and actions not
        seen add a pair not known, so a name looked up that the pairs lack is not known
        either (``python_values.open_keys``)."""
        if name == "global_params" and scope.params:
            from .nodes import convert

            pairs: list[Any] = []
            for key, value, _ in scope.params:
                if key is None:
                    path = value.path[0] if isinstance(value, e.ParamFile) and len(
                        value.path) == 1 and isinstance(value.path[0], str) else None
                    pairs.append(path if path is not None else Unknown("parameter file"))
                    continue
                known = convert(value, ev)
                pairs.append((key if UNKNOWN_MARK not in key else Unknown(f"parameter {key}"),
                              Unknown(f"parameter {key}") if known is None
                              else tuple(known) if isinstance(known, list) else known))
            if scope.unseen:
                pairs.append((Unknown("a parameter an action not seen set"),
                              Unknown("a parameter an action not seen set")))
            return "value", pairs
        if name in scope.configs:
            return "set", None
        return ("unknown", None) if scope.unseen else ("unset", None)

    def do_Process(self, action: e.Process, scope: Scope) -> None:
        """A process whose command line, as the shell splits it, is ``ros2 run PKG EXE
        ...`` (that node) or ``ros2 topic pub ...`` (a publisher, see
        ``python_api.execute_process``); any other, or one not known here, no node."""
        if action.words is not None:  # known to be no node when it was made
            head = e.command_head(action.words)
            self.report("LAUNCH_PROCESS", action.location, command=head)
            # and what a terminal or a shell it opens runs (``xterm -e ros2 bag play``)
            for inner in e.shell_commands(action.words):
                line = ["".join(p for p in word if isinstance(p, str))
                        if all(isinstance(p, str) for p in word) else None
                        for word in inner]
                self._ros_command(e.command_head(inner), scope, action.location, line)
            ev = self.evaluator(scope, action.location)
            self._missing_paths(head, [ev.value(word).text for word in action.words],
                                action.location)
            return
        value = self.value(action.cmd, scope, action.location)
        words: list[str] = []
        if value is not None and value.literal is not None:
            try:
                words = shlex.split(str(value.literal))
            except ValueError:
                words = []
        made = e.process_actions([(w,) for w in words], action.location)
        if not made:  # said: a ROS node it may start is not in the graph
            self.report("LAUNCH_PROCESS", action.location,
                        command=e.command_head([(w,) for w in words]))
            text = str(value.literal if value is not None and value.literal is not None
                       else value.text if value is not None else "")
            if not words:
                self._ros_command(" ".join(text.split()[:3]), scope, action.location, [])
            for inner in e.shell_commands([(w,) for w in words]) if words else []:
                ran: list[str | None] = [str(w[0]) for w in inner]
                self._ros_command(" ".join(str(w) for w in ran[:3]), scope,
                                  action.location, ran)
            self._missing_paths(e.command_head([(w,) for w in words]), words,
                                action.location)
            return
        self.run(made, scope)  # its nodes, launch files, a shell line's commands

    def _missing_paths(self, head: str, words: list[str], where: Location) -> None:
        """The paths into the workspace among the arguments of a process that is no node
        (``rviz2 -d <share>/rviz/x.rviz``, ``python3 <share>/scripts/x.py``) that are not
        there, judged as a node's arguments are (``paths.missing_argument_paths``): the
        program is started with a file it cannot open. The program's own word is not
        (a colcon install's ``lib/<pkg>/<exe>`` is no file of a checkout)."""
        from .nodes import installed_source, written_by_launch

        program = os.path.basename(words[0]) if words else ""
        if program in _FILE_MAKERS:
            return  # its arguments name the files it makes (cp's target, mkdir's folder)
        # a shell's redirection names a file the process writes (``> /ws/log.txt``)
        judged = [UNKNOWN_MARK if (at and _REDIRECT.fullmatch(words[at - 1]))
                  or _REDIRECT.match(word) else word for at, word in enumerate(words)]
        made = written_by_launch(self)
        for path in missing_argument_paths(
                judged[1:], self.workspace,
                lambda p: None if p in made else installed_source(self, p)):
            self.report("LAUNCH_PROCESS_ARG_PATH_MISSING", where,
                        command=program or head, path=self.workspace.relpath(path))

    def _ros_command(self, head: str, scope: Scope, where: Location,
                     line: list[str | None] | None = None) -> None:
        """A ROS 2 command a process runs that is not interpreted here (``ros2 bag play``,
        which publishes the recorded topics: ouster's replay launch) starts a node whose
        topics and parameters are not seen: it may be the missing side of anything, as
        an include not read is. So does Gazebo classic run with a system plugin of
        gazebo_ros (``gazebo -s libgazebo_ros_factory.so``, ``line`` the command's words,
        None where not known): those plugins are ROS nodes (``/spawn_entity``,
        ``/clock``), and the models spawned into it load their own ROS plugins
        (tello_ros' simulation: its TelloPlugin serves ``tello_action``). And so does a
        micro XRCE-DDS agent (``MicroXRCEAgent udp4 -p 8888``), whose clients' topics
        (PX4's) it puts on the graph."""
        gazebo = gazebo_ros_command(line or [])
        if gazebo is not None:
            self.unread(gazebo, scope, where, detail="process")
            return
        words = head.split()
        if words and words[0].rsplit("/", 1)[-1] in _XRCE_AGENTS:
            # a micro XRCE-DDS agent publishes and subscribes for its clients (PX4's
            # ``/fmu/out/...``): what is not seen, as a bag's topics are
            self.unread(head, scope, where, detail="process")
            return
        if words[:1] == ["ros2"]:
            verb = ROS2CLI_VERBS.get(words[1]) if len(words) > 1 else None
            if verb is not None:  # ``ros2 bag``: the package that gives ros2 the verb
                self.uses(verb, where)
            self.unread(head, scope, where, detail="process")

    def do_LaunchCommand(self, action: e.LaunchCommand, scope: Scope) -> None:
        """``ros2 launch PKG FILE [NAME:=VALUE ...]`` (or ``ros2 launch PATH ...``) as a
        process: the launch file ros2launch finds, the one file of that name in the
        package's folder, run as a launch of its own. Only the arguments given on the
        command line reach it, not this launch's configurations, namespace, remaps or
        parameters; the process's conditions (an event handler's) are its nodes'."""
        where = action.location
        positional: list[str] = []
        arguments: list[tuple[str, Value | None]] = []
        words = list(action.words)
        index = 0
        while index < len(words):
            value = self.value(words[index], scope, where)
            text = value.literal if value is not None else None
            index += 1
            if text is not None and text.startswith("-"):
                if text in _LAUNCH_PRINTS:  # prints the launch description, starts nothing
                    return
                if text in _LAUNCH_OPTIONS_WITH_VALUE:
                    index += 1
                continue
            if value is not None and ":=" in value.text:
                head = value.text.split(":=", 1)[0]
                if "?" not in head:  # NAME:=VALUE, the value maybe not known statically
                    rest = text.split(":=", 1)[1] if text is not None else None
                    arguments.append((head, Value.of(rest) if rest is not None
                                      else Value.unknown(f"argument {head} of ros2 launch")))
                    continue
            if text is None:
                self.report("LAUNCH_PROCESS", where, command=e.command_head(
                    [("ros2",), ("launch",), *action.words]))
                return
            positional.append(text)
        path = self._launched_file(positional, where)
        if path is None:
            if len(positional) == 2 and self.workspace.find(positional[0]) is None:
                self.unread(" ".join(positional), scope, where, process=True)
            return
        inner = Scope({name: value for name, value in arguments},
                      conditions=scope.conditions, environment=dict(scope.environment))
        item = LaunchItem("file", self.workspace.relpath(share_source(self.workspace, path)),
                          where, namespace="/", condition=self.take_guard())
        item.args = [LaunchArg(name, value.text if value is not None else None,
                               "command line", where) for name, value in arguments]
        inner.item = scope.item.add(item)
        self.run_file(path, inner, where)

    def unread(self, name: str, scope: Scope, where: Location, detail: str = "",
               process: bool = False) -> None:
        """A launch file included (or run by ``ros2 launch``) that cannot be read: its
        path not known statically, its package not here; or an action not interpreted
        (``detail`` "action"). What it starts or sets is not seen, so it may be the
        missing side of anything (``query.absence``); ROS 1's ``<include>`` of a file
        not known is kept so too. An included file or an action (a ``Node`` of a class
        not known) takes the scope's ``SetRemap`` rules, as launch_ros gives them to
        every node launched after them (``Configuration.remaps``: a remap such an item
        takes may be used there); a process (``process``, or ``detail`` "process") does
        not: ``ros2 launch`` runs another launch with its own rules."""
        scope.item.add(LaunchItem("include", name, where, namespace=scope.namespace or "/",
                                  detail=detail, condition=self.take_guard(),
                                  remaps=[] if process or detail == "process"
                                  else list(scope.remaps)))

    def not_seen(self, scope: Scope, where: Location, what: str) -> None:
        """Actions performed in ``scope`` at ``where`` that the reader cannot see: they
        may declare or set launch configurations (an included file shares its
        includer's, as launch runs it), and read any."""
        self.hidden(what, where)
        if all(place != where for place, _ in scope.unseen):
            scope.unseen = (*scope.unseen, (where, what))

    def _launched_file(self, positional: list[str], where: Location) -> str | None:
        """The file ``ros2 launch`` runs: ``PKG FILE``, the one file named FILE in the
        package's folder (ros2launch walks its share folder so); ``PATH``, that file."""
        if len(positional) == 1 and os.path.isabs(positional[0]):
            return positional[0]  # run_file says when it is not there
        if len(positional) != 2:
            self.report("LAUNCH_PROCESS", where, command=" ".join(
                ["ros2", "launch", *positional]))
            return None
        package, name = positional
        self.uses(package, where)
        folder = self.workspace.find(package)
        if folder is None:  # installed on the robot, perhaps: what it starts is unknown
            self.report("LAUNCH_UNKNOWN_VALUE", where, detail=(
                f"package {package} {self.workspace.absence(package)}; what "
                f"ros2 launch {package} {name} starts is unknown"))
            return None
        found: list[str] = []
        seen = 0
        for top, folders, files in os.walk(folder):
            folders[:] = sorted(f for f in folders if not f.startswith("."))
            found.extend(os.path.join(top, f) for f in sorted(files) if f == name)
            seen += len(files) + len(folders)
            if len(found) > 1 or seen > MAX_WALKED:
                break
        if seen > MAX_WALKED and len(found) < 2:
            self.report("LAUNCH_UNSUPPORTED", where, detail=(
                f"package {package} has more than {MAX_WALKED} files; {name} is not "
                "looked for in it"))
            return None
        if not found:
            self.report("LAUNCH_FILE_MISSING", where, path=f"{package}/.../{name}")
            return None
        if len(found) > 1:
            self.report("LAUNCH_UNSUPPORTED", where, detail=(
                f"package {package} has several files named {name}; which one ros2 "
                "launch runs depends on what the build installs"))
            return None
        return found[0]

    def do_Unsupported(self, action: e.Unsupported, scope: Scope) -> None:
        self.report("LAUNCH_UNSUPPORTED", action.location, detail=action.what)
        self.unread(action.what, scope, action.location, "action")
        self.not_seen(scope, action.location, action.what)

    def do_UnknownAction(self, action: e.UnknownAction, scope: Scope) -> None:
        self.unread(action.what, scope, action.location, "action")
        self.not_seen(scope, action.location, action.what)

    def do_NodeAction(self, action: e.NodeAction, scope: Scope) -> None:
        from .nodes import perform_node

        guard = self.take_guard()
        nodes_before, params_before = len(self.model.nodes), len(self.model.params)
        perform_node(self, action, scope)
        for item in node_items(self.model, nodes_before, params_before, guard):
            scope.item.add(item)

    def do_LoadComposable(self, action: e.LoadComposable, scope: Scope) -> None:
        from .nodes import perform_composable

        target = self.value(action.target, scope, action.location) or Value.unknown()
        container = target.text if target.text.startswith("/") else "/" + target.text
        guard = self.take_guard()
        nodes_before, params_before = len(self.model.nodes), len(self.model.params)
        for node in action.nodes:
            perform_composable(self, node, scope, container)
        for item in node_items(self.model, nodes_before, params_before, guard):
            scope.item.add(item)

    # -- parameter files -------------------------------------------------------------
    def param_file(self, entry: e.ParamFile, scope: Scope, where: Location,
                   depth: int = 0, placed: list[tuple[str, Any]] | None = None,
                   component: bool = False) -> Any:
        """The parsed document of a parameter file, rewritten as asked; None if unknown.
        ``placed``, if given, gets the file read and where each key of the document is
        written (``safe_yaml.load_with_lines``, its keys renamed and put under a root
        key as the document's are). ``component``: the file is given to a composable
        node, whose parameter files launch_ros opens itself."""
        if len(entry.path) == 1 and isinstance(entry.path[0], e.FileRef) and depth < 8:
            document = self.param_file(entry.path[0].file, scope, where, depth + 1, placed,
                                       component)
            if document is None:
                return None
            if placed:
                placed[-1] = (placed[-1][0], self.rewrite(placed[-1][1], entry, scope,
                                                          where, keys_only=True))
            return self.substituted(self.rewrite(document, entry, scope, where), entry,
                                    scope, where)
        path = self.value(entry.path, scope, where)
        if path is not None and isinstance(path.file, e.ParamFile) and depth < 8 and (
            path.file is not entry
        ):
            # a rewritten file passed on in a launch argument (orca4's bringup gives
            # nav2's navigation_launch.py its RewrittenYaml as params_file, which that
            # rewrites again): its own rewrites first, then this one's
            inner = e.ParamFile((e.FileRef(path.file),), entry.root_key, entry.rewrites,
                                entry.location, entry.replacements, entry.condition,
                                entry.allow_substs, entry.key_rewrites, entry.value_rewrites)
            return self.param_file(inner, scope, where, depth + 1, placed, component)
        if path is None or path.literal is None:
            self.report("LAUNCH_PARAM_FILE", where,
                        detail=f"parameter file {path} is not known statically")
            return None
        if not os.path.isabs(path.literal):
            # launch_ros opens it from the folder ``ros2 launch`` runs in, which no file
            # says (nanosaur_control's teleop.launch.py: ``parameters=[config_filepath]``,
            # its default 'ps3'); not from the folder this tool runs in
            self.report("LAUNCH_UNKNOWN_VALUE", where, detail=(
                f"parameter file {path.literal!r} is a relative path, opened from the "
                "folder ros2 launch runs in; it is not read"))
            return None
        file = share_source(self.workspace, path.literal)
        if not self.workspace.readable(file, self.environment):
            # as a ROS 1 <rosparam file> and $(file-content): only the workspace's and the
            # installed packages' files are read (Clearpath's /etc/clearpath/... files
            # are made on the robot); what it would set stays unknown
            self.report("LAUNCH_UNKNOWN_VALUE", where, detail=(
                f"parameter file {file} is outside the workspace and installed packages; "
                "it is not read"))
            return None
        if not os.path.lexists(file) and (
                note := self.workspace.submodule_note(file)) is not None:
            self.report("LAUNCH_UNKNOWN_VALUE", where, detail=note)
            return None
        if not os.path.lexists(file) and (component or entry.allow_substs):
            # launch_ros opens the file itself: ParameterFile.evaluate with allow_substs
            # reads it to substitute in it, and a composable node's load request reads
            # each of its files (to_parameters_list's open()); a file that is not there
            # raises FileNotFoundError and ros2 launch stops (autoware_core 6207f301d:
            # the preprocessor's crop_box_filter.param.yaml, a name the package has not)
            how = "to substitute in it (allow_substs)" if entry.allow_substs else \
                "to load the component"
            self.report("LAUNCH_BAD_VALUE", where, detail=(
                f"parameter file {self.workspace.relpath(file)} does not exist; launch_ros "
                f"opens it {how}, so ros2 launch fails (FileNotFoundError)"))
            return None
        if not os.path.lexists(file):
            # said where the launch file gives it (not at a file that is not there):
            # launch_ros warns "Parameter file path is not a file" and starts the node
            # without it; a build step may make it, so what it would set stays unknown
            self.report("LAUNCH_PARAM_FILE", where, detail=(
                f"parameter file {self.workspace.relpath(file)} does not exist; "
                "ros2 launch starts the node without it (with a warning)"))
            return None
        text, found = read_text(file, self.workspace.location(file), MAX_PARAM_FILE)
        self.model.diagnostics.extend(found)
        if text is None:
            if not found:
                self.report("LAUNCH_PARAM_FILE", where, detail=f"cannot read {file}")
            return None
        written = text
        text = self.replace(text, entry, scope, where)
        rewritten = bool(entry.rewrites or entry.key_rewrites or entry.value_rewrites) or (
            entry.root_key is not None)
        if text is not None and entry.allow_substs and not rewritten:
            text = self.substitute(text, scope, where)  # the file as written, comments too
        if text is None:
            return None
        # rcl reads a file launch_ros hands on as it is; launch_ros reads one itself
        # (one document) when it substitutes in it or loads a component, a rewrite too
        loader = naming.ParamFileLoader if (
            component or entry.allow_substs or rewritten) else naming.RclParamFileLoader
        try:
            if placed is None:
                document = _unknown_parts(naming.load_param_file(text, loader), text)
            else:
                loaded, lines = safe_yaml.load_with_lines(text, loader)
                document = _unknown_parts(loaded, text)
        except yaml.YAMLError as err:
            mark = getattr(err, "problem_mark", None)
            self.report("LAUNCH_YAML_SYNTAX", self.workspace.location(
                file, mark.line + 1 if mark else 0, mark.column + 1 if mark else 0),
                detail=str(getattr(err, "problem", err)))
            return None
        for keys, first, later in safe_yaml.keys_twice(written, naming.ParamFileLoader):
            self.report("LAUNCH_PARAM_FILE_KEY_TWICE", self.workspace.location(file, later),
                        key=param_key(keys), line=first, reader="rcl")
        rel = self.workspace.relpath(file)
        if rel not in self.model.files:
            self.model.files.append(rel)
        if placed is not None:
            placed.append((file, self.rewrite(lines, entry, scope, where, keys_only=True)
                           if rewritten else lines))
        if not rewritten:
            return document
        return self.substituted(self.rewrite(document, entry, scope, where), entry, scope,
                                where)

    def substituted(self, document: Any, entry: e.ParamFile, scope: Scope,
                    where: Location) -> Any:
        """``allow_substs`` on a rewritten file: launch_ros substitutes in the YAML that
        the rewrite dumped (without the source's comments), then reads it again."""
        if not entry.allow_substs or not _substitutes(document):
            return document  # (nothing to perform: the text read again is the same data)
        text = self.substitute(_dumped(document), scope, where)
        if text is None:
            return None
        try:
            return _unknown_parts(safe_yaml.load(text), text)
        except yaml.YAMLError:
            self.report("LAUNCH_PARAM_FILE", where, detail="a parameter file is not valid "
                        "YAML after its substitutions")
            return None

    def substitute(self, text: str, scope: Scope, where: Location) -> str | None:
        """``allow_substs``: the file's ``$(...)`` performed before it is read as YAML."""
        from .substitutions import SubstitutionSyntax, parse

        try:
            value = self.value(parse(text), scope, where)
        except SubstitutionSyntax as err:
            self.report("LAUNCH_PARAM_FILE", where,
                        detail=f"substitutions in a parameter file cannot be read: {err}")
            return None
        if value is None:
            return None
        if value.literal is None:  # read it all the same: what they make stays unknown
            self.report("LAUNCH_UNKNOWN_VALUE", where, detail="a parameter file uses "
                        "substitutions whose values are not known statically")
        return marked_text(value)

    def replace(self, text: str, entry: e.ParamFile, scope: Scope,
                where: Location) -> str | None:
        """nav2_common's ``ReplaceString``: plain text replacements, if its condition holds."""
        if not entry.replacements:
            return text
        truth = True if entry.condition is None else self.evaluator(scope, where).truth(
            entry.condition)
        if truth is False:
            return text
        if truth is None:
            self.report("LAUNCH_PARAM_FILE", where,
                        detail="text replacements in a parameter file under a condition "
                               "not known statically")
            return None
        for old, new in entry.replacements:
            before, after = self.value(old, scope, where), self.value(new, scope, where)
            if before is None or after is None or before.literal is None or (
                    after.literal is None):
                self.report("LAUNCH_PARAM_FILE", where,
                            detail="a text replacement in a parameter file is not known")
                return None
            text = text.replace(before.literal, after.literal)
        return text

    def known_pairs(self, pairs: list[tuple[e.Text, e.Text]], scope: Scope,
                    where: Location) -> dict[str, str | None]:
        """Rewrite pairs performed; a value not known statically becomes None."""
        out: dict[str, str | None] = {}
        for key, val in pairs:
            name, value = self.value(key, scope, where), self.value(val, scope, where)
            if name is not None and name.literal is not None:
                out[name.literal] = value.literal if value is not None else None
        return out

    def rewrite(self, document: Any, entry: e.ParamFile, scope: Scope,
                where: Location, keys_only: bool = False) -> Any:
        """nav2_common's ``RewrittenYaml``: replace keys' values, wrap in ``root_key``;
        ``keys_only``: rename keys and wrap alone (a document of key lines)."""
        if entry.rewrites and isinstance(document, dict) and not keys_only:
            rewrites: dict[str, Any] = {}
            for key, val in entry.rewrites:
                name = self.value(key, scope, where)
                if name is None or name.literal is None:
                    continue
                if isinstance(val, tuple):
                    known = self.value(val, scope, where)
                    rewrites[name.literal] = (naming.yaml_value(known.literal)
                                              if known is not None and known.literal
                                              is not None else None)
                else:
                    rewrites[name.literal] = val
            document = _rewrite(document, rewrites, ())
        keys = self.known_pairs(entry.key_rewrites, scope, where)
        if keys:
            document = _rename_keys(document, {old: new for old, new in keys.items()
                                               if new is not None}, 0)
        values = {} if keys_only else self.known_pairs(entry.value_rewrites, scope, where)
        if values:
            document = _rewrite_values(document, {
                old: None if new is None else naming.yaml_value(new)
                for old, new in values.items()}, 0)
        if entry.root_key is not None:
            root = self.value(entry.root_key, scope, where)
            if root is not None and root.text:
                document = {root.text: document}
        return document


def param_key(path: tuple[str, ...]) -> str:
    """A key of a ROS 2 parameter file as the parameter's name when it is one (the keys
    below ``ros__parameters`` joined with ``.``), else the keys down to it."""
    if "ros__parameters" in path[:-1]:
        return ".".join(path[path.index("ros__parameters") + 1:])
    return "/".join(path)


def _unknown_parts(document: Any, text: str) -> Any:
    """``unknown_parts`` of a document read from ``text``: the document itself when the
    text can hold no unknown part marked (each value and key would be what it is): no
    mark, and no backslash (a double-quoted scalar can write the mark with escapes, as
    ``yaml.safe_dump`` writes it)."""
    return unknown_parts(document) if MARK in text or "\\" in text else document


def _dumped(document: Any) -> str:
    """``yaml.safe_dump`` of a rewritten parameter document, as launch_ros writes it
    (block style); a document made again is dumped once, by its pickle (which tells
    every type and every value shared, as the dump's aliases do): nav2's bringup
    rewrites one file for twenty nodes, and YAML's pure writer took most of a launch's
    time."""
    try:
        pickled = pickle.dumps(document, protocol=pickle.HIGHEST_PROTOCOL)
    except Exception:  # what pickle cannot write, the dump says what is wrong with
        return yaml.safe_dump(document, default_flow_style=False)
    return _dump_of(pickled)


@functools.lru_cache(maxsize=64)
def _dump_of(pickled: bytes) -> str:
    """The dump of the document ``pickled`` holds (our own bytes, made just above)."""
    return yaml.safe_dump(pickle.loads(pickled), default_flow_style=False)


def _substitutes(node: Any, depth: int = 0) -> bool:
    """Whether a parameter document holds text that launch_ros would perform as a
    substitution (``$(``) once it dumps the document for ``allow_substs``; without one,
    dumping and reading again gives the same data. Deeper than the bound: said to."""
    if depth > naming.MAX_PARAM_DEPTH:
        return True
    if isinstance(node, str):
        return "$(" in node
    if isinstance(node, dict):
        return any(_substitutes(key, depth + 1) or _substitutes(value, depth + 1)
                   for key, value in node.items())
    if isinstance(node, list | tuple | set | frozenset):
        return any(_substitutes(value, depth + 1) for value in node)
    return False


def _rename_keys(node: Any, renames: dict[str, str], depth: int) -> Any:
    """RewrittenYaml's ``key_rewrites``: a key renamed wherever it appears."""
    if not isinstance(node, dict) or depth > naming.MAX_PARAM_DEPTH:
        return node
    return {renames.get(str(key), key): _rename_keys(value, renames, depth + 1)
            for key, value in node.items()}


def _rewrite_values(node: Any, values: dict[str, Any], depth: int) -> Any:
    """RewrittenYaml's ``value_rewrites``: a leaf whose text is a key is replaced."""
    if depth > naming.MAX_PARAM_DEPTH:
        return node
    if isinstance(node, dict):
        return {key: _rewrite_values(value, values, depth + 1) for key, value in node.items()}
    if isinstance(node, list):
        return [_rewrite_values(value, values, depth + 1) for value in node]
    return values.get(str(node), node)


def _rewrite(node: Any, rewrites: dict[str, Any], path: tuple[str, ...]) -> Any:
    if not isinstance(node, dict) or len(path) > naming.MAX_PARAM_DEPTH:
        return node
    out: dict[Any, Any] = {}
    for key, value in node.items():
        here = (*path, str(key))
        dotted = ".".join(here)
        if dotted in rewrites:
            out[key] = rewrites[dotted]
        elif str(key) in rewrites and not isinstance(value, dict):
            out[key] = rewrites[str(key)]
        else:
            out[key] = _rewrite(value, rewrites, here)
    return out


# the ros2cli verbs and the package that adds each to ``ros2`` (its setup.py's
# ``ros2cli.command`` entry point): a process running ``ros2 bag play ...`` needs ros2bag
# installed, as one running ``ros2 run`` needs the node's package
# Gazebo classic's programs and the option that loads a system plugin into the server
GAZEBO_PROGRAMS = ("gazebo", "gzserver")
_SERVER_PLUGIN = ("-s", "--server-plugin")


def gazebo_ros_command(words: list[str | None]) -> str | None:
    """``gazebo`` / ``gzserver`` given a system plugin of gazebo_ros (``-s
    libgazebo_ros_init.so``, ``--server-plugin=libgazebo_ros_factory.so``): the program
    and those plugins, as said of the process; else None (a Gazebo without them starts
    no ROS node of its own)."""
    if not words or words[0] is None or os.path.basename(words[0]) not in GAZEBO_PROGRAMS:
        return None
    plugins: list[str] = []
    for index, word in enumerate(words[1:], 1):
        if word is None:
            continue
        value = words[index + 1] if word in _SERVER_PLUGIN and index + 1 < len(words) \
            else word.split("=", 1)[1] if word.startswith("--server-plugin=") else None
        if value is not None and os.path.basename(value).startswith("libgazebo_ros"):
            plugins += ["-s", os.path.basename(value)]
    return " ".join([os.path.basename(words[0]), *plugins]) if plugins else None


ROS2CLI_VERBS = {
    "action": "ros2action", "bag": "ros2bag", "component": "ros2component",
    "control": "ros2controlcli", "doctor": "ros2doctor", "interface": "ros2interface",
    "launch": "ros2launch", "lifecycle": "ros2lifecycle", "node": "ros2node",
    "param": "ros2param", "pkg": "ros2pkg", "run": "ros2run", "service": "ros2service",
    "topic": "ros2topic",
}


def make_param(node: str, key: str, value: Any, conditions: tuple[Condition, ...],
               location: Location) -> ParamDecl:
    return ParamDecl(f"{node}/{key}", value, naming.param_type(value), conditions,
                     location, node=node, key=key)


def node_decl(**fields: Any) -> NodeDecl:
    return NodeDecl(ros_version=2, **fields)


# what stands for the argument in a Python expression read by ``_compared_in``, and the
# longest expression it reads (a comparison with a few strings)
_ARGUMENT = "@haros-arch launch argument@"
_COMPARED_TEXT = 2000


def _compared_in(text: e.Text, evaluator: Evaluator
                 ) -> tuple[str, tuple[str, ...], bool] | None:
    """``(argument, strings, holds when it is one of them)`` when the Python expression
    ``text`` compares the value of one launch argument, not known, written inside a
    string, with a string (``==``, ``!=``) or a tuple, list or set of strings (``in``,
    ``not in``): Interbotix's ``PythonExpression(['"', hardware_type, '"', " in
    ('actual', 'fake')"])``. Nothing is evaluated but the literals ``ast`` reads."""
    name: str | None = None
    parts: list[str] = []
    for part in text:
        value = part if isinstance(part, str) else evaluator.value((part,)).literal
        if value is not None:
            parts.append(value)
            continue
        if name is not None or not isinstance(part, e.Var):
            return None  # two parts not known, or one that is no argument
        name = evaluator.value(part.name).literal
        if name is None:
            return None
        parts.append(_ARGUMENT)
    source = "".join(parts).strip()
    if name is None or len(source) > _COMPARED_TEXT:
        return None
    try:
        tree = parse(source, mode="eval").body
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return None
    if not isinstance(tree, ast.Compare) or len(tree.ops) != 1:
        return None
    left, right, op = tree.left, tree.comparators[0], tree.ops[0]
    if isinstance(op, ast.Eq | ast.NotEq) and _literal(right) == _ARGUMENT:
        left, right = right, left
    if _literal(left) != _ARGUMENT:
        return None
    if isinstance(op, ast.Eq | ast.NotEq):
        strings: list[ast.expr] = [right]
    elif isinstance(op, ast.In | ast.NotIn) and isinstance(right, ast.Tuple | ast.List | ast.Set):
        strings = list(right.elts)
    else:
        return None
    values = [_literal(s) for s in strings]
    if not values or any(v is None or v == _ARGUMENT for v in values):
        return None
    return name, tuple(v for v in values if v is not None), isinstance(op, ast.Eq | ast.In)


def _literal(node: ast.expr) -> str | None:
    return node.value if isinstance(node, ast.Constant) and isinstance(node.value, str) else None


def _names_read(value: Any) -> Iterator[str]:
    """The launch configurations ``value`` (an action, a text) reads by names known
    statically, through its LaunchConfiguration / ``$(var)`` substitutions, looked for
    in its lists, tuples, dictionaries and dataclass fields (within
    ``MAX_SKIPPED_VISITS`` values, ``MAX_SKIPPED_DEPTH`` deep)."""
    stack: list[tuple[Any, int]] = [(value, 0)]
    seen = 0
    while stack and seen < MAX_SKIPPED_VISITS:
        value, depth = stack.pop()
        seen += 1
        if depth > MAX_SKIPPED_DEPTH:
            continue
        if isinstance(value, e.Var) and all(isinstance(p, str) for p in value.name):
            yield recording.written(value.name)
        if isinstance(value, (list, tuple)):
            stack.extend((item, depth + 1) for item in value)
        elif isinstance(value, dict):
            stack.extend((item, depth + 1) for item in value.values())
        elif is_dataclass(value) and not isinstance(value, type):
            stack.extend((getattr(value, f.name), depth + 1) for f in fields(value))
