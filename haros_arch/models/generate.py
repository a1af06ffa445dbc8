"""``haros-arch models build LIST``: interface models from pinned public sources.

The list (YAML) pins where each model comes from::

    - repository: github:ros-planning/navigation
      branch: noetic-devel            # for people; the commit is what counts
      commit: 9d7f5a1...              # 40 hex digits
      distro: noetic
      packages: [amcl, move_base, map_server]
      with:                           # scanned too (message and library packages the
        - repository: github:ros-planning/navigation_msgs   # code includes), not modelled
          commit: 793d06f...

Each entry's source tree is expected at ``SOURCES/<owner>+<name>@<commit[:12]>``
(``scripts/models-fetch`` puts it there from a local git mirror). Each package is one
unit of work, run by the same code as a workspace analysis (workspace scan, build
files, C++ and Python extraction): on a local process pool by default, or on a Dask
distributed cluster (``--scheduler ADDRESS``; the optional ``dask`` extra). A node is
``partial`` where extraction says so (``extract.cpp.recall``: a line of its C++ that
calls a ROS API function with no call extracted there, an error in a function that
calls the API). An
override file ``OVERRIDES/<distro>/<package>.yaml`` (hint format, reviewed like code)
may complete a model; what it adds has origin ``override``.
"""

from __future__ import annotations

import json
import os
import re
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any

import yaml

from .. import __version__
from .. import diagnostics as diag
from ..diagnostics import Diagnostic
from ..extract import AUTO_CACHE, extract_nodes
from ..files import read_text
from ..graph.hints import apply_node_hints
from ..model.conditions import Condition
from ..model.location import Location
from ..model.source import NUMBERED, Node, PrimitiveCall, declared_defaults
from ..model.values import UNKNOWN_MARK
from ..pipeline import distro_variables, read_build_files, without_deferred
from ..plugins.behavior_trees import package_model_data
from ..processes import worker_pool
from ..workspace import scan
from .attach import ros_of
from .format import InterfaceModel, dumps
from .launch_files import package_launch_data

OVERRIDES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "overrides")
COMMIT = re.compile(r"^[0-9a-f]{40}$")
REPOSITORY = re.compile(r"^github:[A-Za-z0-9_.-]+/[A-Za-z0-9_.-]+$")
# an override node block may also say why the node is now complete, put calls the
# extractor took as unconditional under the condition that guards them, name calls by
# the elements of a list parameter or a numbered family of parameters, and drop the
# calls of source files the node links but never runs (a library's other classes)
OVERRIDE_KEYS = ("complete", "partial", "conditions", "names", "drop", "handles", "aliases",
                 "defaults")


class ListError(ValueError):
    """The list file cannot be used; ``str()`` says where and why."""


@dataclass(frozen=True)
class Entry:
    """One pinned repository of the list."""

    repository: str
    commit: str
    distro: str
    packages: tuple[str, ...]
    branch: str = ""
    # (repository, commit) of trees scanned with it: the message packages and libraries
    # its code includes, so their types are known; they are not modelled
    context: tuple[tuple[str, str], ...] = ()

    @property
    def folder(self) -> str:
        """Where its tree is expected under the sources folder."""
        return folder_of(self.repository, self.commit)

    @property
    def context_folders(self) -> list[str]:
        return [folder_of(repository, commit) for repository, commit in self.context]


def folder_of(repository: str, commit: str) -> str:
    """``<owner>+<name>@<commit[:12]>``: a pinned tree's folder under the sources folder."""
    return f"{repository.removeprefix('github:').replace('/', '+')}@{commit[:12]}"


@dataclass(frozen=True)
class Task:
    """One package to model: picklable, so it can go to another process or machine."""

    entry: Entry
    package: str
    tree: str
    overrides: str
    cache_dir: str | None = AUTO_CACHE
    context: tuple[str, ...] = ()  # the folders of the entry's context trees


@dataclass
class Outcome:
    """What one package gave: its model document (None when it could not be made) and
    a report line of what was extracted and what stayed partial."""

    package: str
    distro: str
    text: str | None = None
    nodes: list[str] = field(default_factory=list)
    calls: int = 0
    unresolved: int = 0
    partial: dict[str, list[str]] = field(default_factory=dict)
    problem: str | None = None
    override_problems: list[str] = field(default_factory=list)
    files: tuple[int, int] | None = None  # ROS 1: launch files and parameter files kept


def read_list(path: str) -> list[Entry]:
    """The entries of a list file; raises ``ListError`` naming the entry at fault."""
    text, problems = read_text(path, Location(file=path))
    if text is None:
        raise ListError(problems[0].message if problems else f"{path}: cannot read")
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as error:
        raise ListError(f"{path}: invalid YAML: {error}") from None
    if not isinstance(data, list):
        raise ListError(f"{path}: the list is a YAML sequence of repositories")
    entries = []
    for index, item in enumerate(data, 1):
        where = f"{path}: entry {index}"
        if not isinstance(item, dict):
            raise ListError(f"{where}: must be a mapping")
        repository, commit = _pinned(item, where)
        context = item.get("with") or []
        if not isinstance(context, list):
            raise ListError(f"{where}: 'with' must be a list of repository and commit")
        pins = tuple(_pinned(other, f"{where}, with {number}")
                     for number, other in enumerate(context, 1))
        packages = item.get("packages")
        if not isinstance(packages, list) or not packages or not all(
                isinstance(p, str) and re.match(r"^[A-Za-z0-9_]+$", p) for p in packages):
            raise ListError(f"{where}: packages must be a list of package names")
        distro = str(item.get("distro", ""))
        if not re.match(r"^[a-z]+$", distro):
            raise ListError(f"{where}: distro must be a distribution name (noetic, jazzy)")
        entries.append(Entry(repository, commit, distro, tuple(packages),
                             str(item.get("branch", "")), pins))
    return entries


def _pinned(item: Any, where: str) -> tuple[str, str]:
    if not isinstance(item, dict):
        raise ListError(f"{where}: must be a mapping")
    repository, commit = str(item.get("repository", "")), str(item.get("commit", ""))
    if not REPOSITORY.match(repository):
        raise ListError(f"{where}: repository must be github:owner/name")
    if not COMMIT.match(commit):
        raise ListError(f"{where}: commit must be 40 hexadecimal digits")
    return repository, commit


def tasks(entries: Iterable[Entry], sources: str, overrides: str = OVERRIDES,
          only: Sequence[str] = (), cache_dir: str | None = AUTO_CACHE) -> list[Task]:
    return [Task(entry, package, os.path.join(sources, entry.folder), overrides, cache_dir,
                 tuple(os.path.join(sources, f) for f in entry.context_folders))
            for entry in entries for package in entry.packages
            if not only or package in only]


def build_package(task: Task) -> Outcome:
    """Model one package with the workspace pipeline. A bug of ours met on one package
    is reported as that package's problem; the other packages go on."""
    outcome = Outcome(task.package, task.entry.distro)
    try:
        return _build(task, outcome)
    except Exception as error:  # a bug of ours: this package is not modelled
        if os.environ.get("HAROS_ARCH_DEBUG"):
            raise
        outcome.text = None
        outcome.problem = f"internal error: {type(error).__name__}: {error}"
        return outcome


def _build(task: Task, outcome: Outcome) -> Outcome:
    missing = [t for t in (task.tree, *task.context) if not os.path.isdir(t)]
    if missing:
        outcome.problem = f"no source tree at {missing[0]} (run scripts/models-fetch)"
        return outcome
    # the environment the release's build runs in, as its distribution's setup script
    # sets it: a package for both ROS versions chooses its build on it (foxglove_bridge's
    # ``if("$ENV{ROS_VERSION}" STREQUAL "2")``, package.xml's ``condition=``), and with
    # none the jazzy model had its ROS 1 nodelet only, not the ROS 2 node
    environment = {"ROS_DISTRO": task.entry.distro, **distro_variables(task.entry.distro)}
    workspace = scan([task.tree, *task.context], environment)
    # what the release's build finds of its client library (``find_package(rclcpp)``'s
    # version: mavros defines USE_OLD_DECLARE_PARAMETER below 9.0.0, Foxy's)
    workspace.source_distro = task.entry.distro
    package = workspace.packages.get(task.package)
    if package is None:
        outcome.problem = f"no package {task.package} in {task.entry.repository}"
        return outcome
    found = read_build_files(package, workspace)
    # its plugin classes that only a ClassLoader of code loads (``Node.deferred``): a
    # host elsewhere does (dwb_plugins' trajectory generators, which dwb_core's
    # DWBLocalPlanner loads by a parameter's value), so the model has them all
    for node in package.nodes:
        node.deferred = False
    found += extract_nodes(package.nodes, workspace, cache_dir=task.cache_dir, jobs=1,
                           distro=task.entry.distro)  # the code of that release's rclcpp
    without_deferred([package])
    override = _apply_override(task, package.nodes, found)
    outcome.override_problems = [f"{d.location.file}: {d.message}" for d in found
                                 if d.code == "HINT_INVALID"]
    model = InterfaceModel(
        task.package, task.entry.distro, package.nodes, package.version,
        {"repository": task.entry.repository, "branch": task.entry.branch,
         "commit": task.entry.commit, "path": package.path,
         **({"with": ", ".join(f"{r}@{c}" for r, c in task.entry.context)}
            if task.entry.context else {})},
        {"name": "haros-arch", "version": __version__}, override)
    # the BT libraries it builds and, for a tree host, its default trees: a tree host
    # of another package without source runs them (nav2's bt_navigator and
    # nav2_behavior_tree's nodes)
    model.bt_libraries, model.bt_trees = package_model_data(task.package, workspace)
    # a ROS 1 package's launch files and the parameter files they load from it: an
    # include of one from a workspace reads them (``launch_files``)
    if ros_of(task.entry.distro) == 1:
        model.launch_files, model.param_files = package_launch_data(task.package,
                                                                    package.root)
        outcome.files = (len(model.launch_files), len(model.param_files))
    outcome.text = _tree_relative(dumps(model), (task.tree, *task.context))
    outcome.nodes = [n.executable for n in package.nodes]
    outcome.calls = sum(len(n.calls) for n in package.nodes)
    outcome.unresolved = sum(1 for n in package.nodes for c in n.calls
                             if UNKNOWN_MARK in c.name and c.name_param is None)
    outcome.partial = {n.executable: list(n.completeness_reasons) for n in package.nodes
                       if n.completeness in ("partial", "unknown")}
    return outcome


def _tree_relative(text: str, folders: Iterable[str]) -> str:
    """The model's text with each path into a source tree of the build (the package's, or
    one scanned alongside: a controller's test executable runs controller_manager's
    code, in ros_control's tree) relative to that tree, as the package's own paths are:
    no path of the machine that built it."""
    for folder in folders:
        prefix = json.dumps(os.path.abspath(folder).rstrip(os.sep) + os.sep)[1:-1]
        text = text.replace(f'"{prefix}', '"').replace(f" {prefix}", " ")
    return text


def _apply_override(task: Task, nodes: list[Node], found: list[Diagnostic]) -> str | None:
    """The reviewed override of the package, if any: hint-format calls per node (a node
    the build files do not show is made from them), ``complete: <why>`` to say the
    node's interface is now whole, ``partial: <why>`` to say what it still lacks,
    ``aliases: [name]`` for the other names releases install the executable under."""
    relative = os.path.join(task.entry.distro, task.package + ".yaml")
    path = os.path.join(task.overrides, relative)
    if not os.path.isfile(path):
        return None
    text, problems = read_text(path, Location(file=path))
    found.extend(problems)
    data = yaml.safe_load(text) if text else None
    blocks = data.get("nodes") if isinstance(data, dict) else None
    if not isinstance(blocks, dict):
        return None
    by_name = {node.name: node for node in nodes}
    where = Location(file=relative)
    plain = {name: {k: v for k, v in block.items() if k not in OVERRIDE_KEYS}
             for name, block in blocks.items() if isinstance(block, dict)}
    # names first, where their calls are extracted: a hint completes what is left (a
    # getter of a name with ``?`` would otherwise take a call a names entry renames);
    # then the entries of calls the hints add
    later: dict[str, list[Any]] = {}
    for name, node in by_name.items():
        block = blocks.get(name)
        if isinstance(block, dict):
            later[name] = []
            _override_names(node, block.get("names"), relative, found, later[name])
    apply_node_hints(by_name, plain, where)
    for name, node in by_name.items():
        for call in node.calls:
            if call.origin == "hint":
                call.origin = "override"
        # an override writes what the extraction missed: a call it places nowhere in the
        # code (its own file's location) or at a line, that the extraction has found since
        # (the same kind and name; anywhere, at that line) is kept once, as extracted
        anywhere = {(c.kind, c.name) for c in node.calls if c.origin != "override"}
        placed = {(c.kind, c.name, c.location.file, c.location.line) for c in node.calls
                  if c.origin != "override"}
        node.calls = [c for c in node.calls if c.origin != "override" or not (
            (c.kind, c.name) in anywhere if c.location.file == relative
            else (c.kind, c.name, c.location.file, c.location.line) in placed)]
        block = blocks.get(name)
        if isinstance(block, dict) and isinstance(block.get("rosname"), str):
            node.rosnames = []  # the one ROS node the override names
        if isinstance(block, dict):
            _override_handles(node, block.get("handles"), relative, found)
            _override_drop(node, block.get("drop"), relative, found)
            _override_conditions(node, block.get("conditions"), relative, found)
            _override_defaults(node, block.get("defaults"), relative, found)
            _override_names(node, later.get(name, block.get("names")), relative, found)
            node.calls = declared_defaults(node.calls)
        if isinstance(block, dict) and isinstance(block.get("aliases"), list):
            node.aliases = [str(a) for a in block["aliases"] if isinstance(a, str)]
        if isinstance(block, dict) and isinstance(block.get("partial"), str):
            node.mark_partial(f"override {relative}: {block['partial']}")
        if isinstance(block, dict) and isinstance(block.get("complete"), str):
            node.completeness = "complete"
            node.completeness_reasons = [f"completed by override {relative}: "
                                         f"{block['complete']}"]
        if node not in nodes:  # a node the build files do not show
            nodes.append(node)
    return relative


def _override_conditions(node: Node, entries: Any, relative: str,
                         found: list[Diagnostic]) -> None:
    """``conditions: [{calls: file:line, text: ..., at: file:line}]``: the calls made at
    ``calls`` exist only under ``text``, written at ``at`` (a caller's ``if`` the
    extractor does not carry into the function it calls); ``program_args: true`` when
    ``at`` is in ``main(argc, argv)`` (its ``argc`` / ``argv`` are the program's)."""
    for entry in entries if isinstance(entries, list) else []:
        at, text = _place(entry.get("at")), entry.get("text")
        for call in _calls_at(node, entry, relative, found,
                              isinstance(text, str) and at is not None):
            where = Location(node.package, at[0], at[1]) if at else Location()
            call.conditions = (*call.conditions, Condition(
                str(text), "source", "if", where, entry.get("program_args") is True))


def _override_handles(node: Node, entries: Any, relative: str,
                      found: list[Diagnostic]) -> None:
    """``handles: [{file: F, kinds: [read], namespace: "~"}]``: the calls of those kinds
    made in F (at ``line`` only, when given) whose handle the extractor could not tell
    (names ``?/x``, a NodeHandle a constructor takes; ``~?/x`` and ``/?/x``, a handle in
    an unknown namespace) are made on a handle of that namespace (``~x``; ``ns/x``)."""
    for entry in entries if isinstance(entries, list) else []:
        fields = entry if isinstance(entry, dict) else {}
        file, kinds, namespace = fields.get("file"), fields.get("kinds"), fields.get(
            "namespace")
        line = fields.get("line")
        hit = [c for c in node.calls if c.location.file == file and c.kind in kinds
               and c.name.startswith(tuple(lead + UNKNOWN_MARK + "/" for lead in (
                   "", "~", "/"))) and line in (None, c.location.line)
               ] if isinstance(kinds, list) else []
        if not hit or not isinstance(namespace, str):
            found.append(diag.make("HINT_INVALID", Location(file=relative), detail=(
                f"{node.name}: handles entry {entry!r} names no call of the node")))
            continue
        for call in hit:
            rest = call.name.split(UNKNOWN_MARK + "/", 1)[1]
            call.name = namespace + rest if namespace.endswith(("~", "/")) else (
                f"{namespace}/{rest}" if namespace else rest)
            call.handle_namespace, call.origin = None, "override"


def _override_drop(node: Node, files: Any, relative: str, found: list[Diagnostic]) -> None:
    """``drop: [file, ...]``: the node's calls made in these files are not its own (a
    library the executable links, whose other classes its ``main`` never makes);
    ``file:line``: those made at that line (a member the extraction also took for
    default-constructed, which every constructor initialises otherwise)."""
    if files is None:
        return
    if not isinstance(files, list) or not all(isinstance(f, str) for f in files):
        found.append(diag.make("HINT_INVALID", Location(file=relative), detail=(
            f"{node.name}: 'drop' must be a list of source files")))
        return

    def dropped(call: PrimitiveCall, entry: str) -> bool:
        place = _place(entry)
        if place is not None:
            return (call.location.file, call.location.line) == place
        return call.location.file == entry

    unknown = [f for f in files if not any(dropped(c, f) for c in node.calls)]
    if unknown:
        found.append(diag.make("HINT_INVALID", Location(file=relative), detail=(
            f"{node.name}: 'drop' names files with no call of the node: "
            f"{', '.join(unknown)}")))
    node.calls = [c for c in node.calls if not any(dropped(c, f) for f in files)]


def _override_defaults(node: Node, places: Any, relative: str,
                       found: list[Diagnostic]) -> None:
    """``defaults: [file:line, ...]``: the reads made at these places have a default in
    code that the extraction did not see (one a helper takes as an argument: MoveIt's
    ``KinematicsBase::lookupParam(name, value, default)``)."""
    for place in places if isinstance(places, list) else []:
        for call in _calls_at(node, {"calls": place}, relative, found, True):
            if call.kind == "read":
                call.has_default = True


def _override_names(node: Node, entries: Any, relative: str,
                    found: list[Diagnostic], missed: list[Any] | None = None) -> None:
    """``names: [{calls: file:line, param: ~topics, each: topic}]``: the calls made at
    ``calls`` are named by the field ``each`` of every element of the list parameter
    ``param`` (a name the code reads through a helper the extractor cannot follow);
    without ``each``, by the value of ``param`` (``default:`` the code's default);
    ``numbered: true`` instead of ``each``: by each parameter ``param0``, ``param1``, ...
    (robot_localization's ``imu0``); ``name``: the name as the code writes it, where the
    extractor could not tell (``?`` for the parameter's value alone). ``missed``: where
    the entries that name no call go, instead of a diagnostic (tried again later)."""
    for entry in entries if isinstance(entries, list) else []:
        if not isinstance(entry, dict):
            entry = {}
        param, each, name = entry.get("param"), entry.get("each"), entry.get("name")
        default, numbered = entry.get("default"), entry.get("numbered") is True
        if param is not None:  # named by the parameter's value, elements or family
            usable = isinstance(param, str) and (
                each is None or (isinstance(each, str) and not numbered))
        else:  # only the name as the code writes it
            usable = each is None and not numbered and isinstance(name, str)
        usable = usable and all(v is None or isinstance(v, str) for v in (name, default))
        if missed is not None and usable and not _calls_at(node, entry, relative, [],
                                                            usable, mark=False):
            missed.append(entry)
            continue
        for call in _calls_at(node, entry, relative, found, usable):
            if isinstance(name, str):
                call.name, call.handle_namespace = name, None
            if isinstance(param, str):
                call.name_param, call.name_default = param, default
                call.name_each = NUMBERED if numbered else each


def _calls_at(node: Node, entry: Any, relative: str, found: list[Diagnostic],
              usable: bool, mark: bool = True) -> list[PrimitiveCall]:
    """The node's calls at an override entry's ``calls: file:line`` (marked as changed by
    the override); none, and a diagnostic, when the entry is malformed or names none."""
    place = _place(entry.get("calls")) if isinstance(entry, dict) else None
    hit = [c for c in node.calls if place and (c.location.file, c.location.line) == place]
    if not hit or not usable:
        found.append(diag.make("HINT_INVALID", Location(file=relative), detail=(
            f"{node.name}: override entry {entry!r} names no call of the node")))
        return []
    for call in hit if mark else ():
        call.origin = "override"
    return hit


def _place(text: Any) -> tuple[str, int] | None:
    if not isinstance(text, str) or ":" not in text:
        return None
    file, _, line = text.rpartition(":")
    return (file, int(line)) if line.isdigit() else None


def run(work: Sequence[Task], jobs: int | None = None, scheduler: str | None = None
        ) -> list[Outcome]:
    """Every task, on a local process pool (``jobs`` workers) or a Dask cluster."""
    if scheduler:
        return _on_dask(work, scheduler)
    if jobs == 1 or len(work) <= 1:
        return [build_package(task) for task in work]
    with worker_pool(jobs) as pool:
        return list(pool.map(build_package, work))


def _on_dask(work: Sequence[Task], scheduler: str) -> list[Outcome]:
    from distributed import Client  # the optional 'dask' extra

    with Client(scheduler) as client:
        futures = client.map(build_package, list(work), pure=False)
        return list(client.gather(futures))


def write(outcomes: Iterable[Outcome], output: str) -> list[str]:
    """Write each model to ``OUTPUT/<distro>/<package>.json``; the paths written."""
    written = []
    for outcome in outcomes:
        if outcome.text is None:
            continue
        folder = os.path.join(output, outcome.distro)
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, outcome.package + ".json")
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(outcome.text)
        written.append(path)
    return written


def report(outcomes: Iterable[Outcome], say: Callable[[str], Any]) -> None:
    """One line per package, then each partial node's reasons."""
    for outcome in outcomes:
        name = f"{outcome.distro}/{outcome.package}"
        if outcome.problem:
            say(f"{name}: not modelled: {outcome.problem}")
            continue
        state = f"{len(outcome.partial)} partial" if outcome.partial else "complete"
        files = (f", {outcome.files[0]} launch files, {outcome.files[1]} parameter files"
                 if outcome.files is not None else "")
        say(f"{name}: {len(outcome.nodes)} nodes, {outcome.calls} calls, "
            f"{outcome.unresolved} names unknown statically, {state}{files}")
        for problem in outcome.override_problems:
            say(f"    override not used: {problem}")
        for node, reasons in outcome.partial.items():
            for reason in reasons:
                say(f"    {node}: {reason}")
