"""Source extraction: the ROS primitive calls in each node's sources.

Entry points: ``extract_nodes(nodes, workspace)`` fills ``calls``, ``rosname`` and
``rosnames`` (ROS 2: several nodes in one executable's process) of
every node and returns the diagnostics, parsing each C++ translation unit of all the
nodes once, in parallel, through the persistent cache; ``extract_node`` does one node.
C++ goes through libclang, Python through ``ast``.
"""

from __future__ import annotations

import json
import os
import re
import time
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from .. import diagnostics as diag
from ..ctext import code_only
from ..diagnostics import Diagnostic
from ..files import AUTO_CACHE, read_text
from ..manifest import version_environment
from ..model.source import Node, class_load_base, is_class_load
from ..model.values import UNKNOWN_MARK
from ..plugins.classes import base_name, exported_classes
from ..plugins.hosts import host_of
from ..plugins.inherit import without_other_classes, without_overridden
from ..workspace import Workspace
from .overrides import clear_where_declared

if TYPE_CHECKING:
    from .cpp import CppBatch, CppResult

_RUNS: list[dict[Any, Any]] = []  # the blocks of ``one_run``, innermost last


@contextmanager
def one_run() -> Iterator[None]:
    """Within the block (one run of the pipeline: its files do not change meanwhile), a
    C++ batch of the same sources and options as an earlier batch of the block takes
    that batch's prepared headers instead of preparing them again (``cpp._batch``): a
    run after one changed source compares what its units give (``pipeline._again``)
    and, when that differs, extracts the same units again (navigation2's bringup: 0.3 s
    of 3.1). The include setups are closed when the block ends."""
    kept: dict[Any, Any] = {}
    _RUNS.append(kept)
    try:
        yield
    finally:
        _RUNS.pop()
        for prepared in kept.values():
            prepared[0].close()


def this_run() -> dict[Any, Any] | None:
    """The prepared batches of the innermost ``one_run`` block (None outside any)."""
    return _RUNS[-1] if _RUNS else None


def extract_nodes(nodes: Sequence[Node], workspace: Workspace, *,
                  cache_dir: str | None = AUTO_CACHE, jobs: int | None = None,
                  compile_commands: Sequence[str] | None = None,
                  timings: dict[str, float] | None = None,
                  cpp_batch: CppBatch | None = None,
                  kept: Mapping[str, Any] | None = None,
                  keep: dict[str, Any] | None = None,
                  distro: str | None = None) -> list[Diagnostic]:
    """Extract every node; C++ nodes in one batch (``cpp.extract_cpp_nodes``): a source
    shared by several nodes is parsed once. ``cache_dir`` None: no cache; ``jobs``: worker
    processes (default: the number of cores); ``compile_commands``: the
    compile_commands.json files to take flags from (None: those in the workspace);
    ``timings``, when given, gets the seconds of the C++ batch ("C++") and of the
    other nodes ("Python", read during the batch: within its seconds), added;
    ``cpp_batch``, when given, the C++ batch's own diagnostics and the digest of what
    each translation unit gave (``CppBatch.units``; not the node results, which are the
    nodes'); ``kept``: what an earlier run's nodes of other languages gave, by
    ``other_key`` (``keep`` of that run), taken instead of reading them again where the
    caller knows their files unchanged (``pipeline``: only C++ files changed since);
    ``keep``, when given, gets what this run's give; ``distro``: the ROS distribution
    whose rclcpp version C++ is parsed with (``cpp.versions``; None: not known)."""
    found: list[Diagnostic] = []
    start = time.perf_counter()
    others: list[Diagnostic] = []  # the other nodes' diagnostics, after the C++ batch's
    spent = [0.0]  # seconds of the other nodes

    def other_nodes() -> None:
        began = time.perf_counter()
        for node in nodes:
            if node.language != "cpp":
                key = other_key(node)
                said = _kept_result(node, kept.get(key)) if kept is not None else None
                if said is None:
                    said = extract_node(node, workspace)
                if keep is not None:
                    keep[key] = _result_data(node, said)
                others.extend(said)
            elif not node.sources:
                completeness(node, [])
        spent[0] += time.perf_counter() - began

    every = _cpp_nodes(nodes)
    # plugin classes only code's ClassLoaders load (``Node.deferred``): read after the
    # others, those of a base some node read so far loads by a parameter's value
    cpp = [node for node in every if not node.deferred]
    deferred = [node for node in every if node.deferred]
    if not cpp:
        other_nodes()
    meanwhile: Callable[[], None] | None = other_nodes
    read_cpp = bool(cpp)
    while cpp:
        from .cpp import extract_cpp_nodes  # libclang loads only when there is C++ to parse

        # the other nodes are read while the workers parse C++ (they need none of it)
        batch = extract_cpp_nodes([_paths(node, workspace) for node in cpp], workspace,
                                  cache_dir=cache_dir, jobs=jobs,
                                  compile_commands=compile_commands, meanwhile=meanwhile,
                                  distro=distro, entries=_entries(cpp))
        meanwhile = None
        for node, result in zip(cpp, batch.results, strict=True):
            node.calls = without_other_classes(
                node, without_overridden(node, result.calls, workspace), workspace)
            node.rosname = _rosname(node, result.rosname)
            _process_nodes(node, result.rosnames)
            node.handles_given = dict(result.handles_given)
            node.local_rules = _local_rules(node, result.local_rules)
            clear_where_declared(node, workspace)
        if cpp_batch is not None:
            cpp_batch.extend(batch)
        found.extend(_read_elsewhere(batch.all_diagnostics(), cpp, batch.results, workspace))
        macros = _build_macros(cpp, workspace, compile_commands)
        found.extend(d for said in macros for d in said)
        for node, result, said in zip(cpp, batch.results, macros, strict=True):
            found.extend(completeness(node, [*batch.diagnostics, *result.diagnostics,
                                             *said], workspace))
        bases = {base_name(base) for node in cpp for call in node.calls
                 if (base := class_load_base(call.loads)) is not None}
        # and the classes a node creates by a name written in its code, or by a
        # parameter whose default names them where the loader's base is not known (a
        # load in a template, on the class its use gives: ros_canopen's
        # ClassAllocator<T>::allocateInstance)
        named = {name.lstrip(":") for node in cpp for name in node.nodelets}
        named |= {call.default.lstrip(":") for node in cpp for call in node.calls
                  if is_class_load(call.loads) and class_load_base(call.loads) is None
                  and isinstance(call.default, str) and call.default}
        cpp = [node for node in deferred if base_name(node.plugin_base or "") in bases
               or node.executable in named or (node.plugin_class or "").lstrip(":") in named]
        deferred = [node for node in deferred if node not in cpp]
        for node in cpp:
            node.deferred = False
    found.extend(others)
    if timings is not None:  # with workers, the other nodes' seconds are within C++'s
        batch_seconds = time.perf_counter() - start if read_cpp else 0.0
        timings["C++"] = timings.get("C++", 0.0) + batch_seconds
        timings["Python"] = timings.get("Python", 0.0) + spent[0]
    return found


def other_key(node: Node) -> str:
    """What names a node of another language than C++ from run to run: its package,
    executable, kind, language, sources and entry."""
    return json.dumps([node.package, node.executable, node.kind, node.language,
                       node.sources, node.entry])


# the node fields extraction sets (``extract_node``, ``completeness``)
_RESULT_FIELDS = ("calls", "rosname", "rosnames", "completeness", "completeness_reasons",
                  "plugin_loads", "nodelets", "handles_given", "local_rules")


def _result_data(node: Node, said: list[Diagnostic]) -> dict[str, Any]:
    from ..model.serialise import to_data

    data = to_data(node)
    return {"node": {k: data[k] for k in ("package", *_RESULT_FIELDS) if k in data},
            "diagnostics": to_data(said)}


def _kept_result(node: Node, data: Any) -> list[Diagnostic] | None:
    """Set ``node``'s extraction fields from an earlier run's ``_result_data``; its
    diagnostics. None (``node`` untouched) when ``data`` is not such data."""
    from ..model.load import diagnostic_from_data, node_from_data

    try:
        kept = node_from_data(data["node"], node.package)
        said = [diagnostic_from_data(d) for d in data["diagnostics"]]
    except (KeyError, TypeError, ValueError, AttributeError):
        return None
    for name in _RESULT_FIELDS:
        setattr(node, name, getattr(kept, name))
    return said


def _build_macros(nodes: Sequence[Node], workspace: Workspace,
                  compile_commands: Sequence[str] | None) -> list[list[Diagnostic]]:
    """Per C++ node, the ROS calls its sources choose with a macro its package's CMake
    defines (``cpp.build_macros``); none where a compile_commands.json gives the build's
    macros."""
    from .. import compile_commands as commands
    from .cpp import build_macros

    given = compile_commands if compile_commands is not None else commands.find(workspace)
    if any(os.path.isfile(path) or os.path.isdir(path) for path in given):
        return [[] for _ in nodes]
    found: list[list[Diagnostic]] = []
    macros: dict[str, dict[str, tuple[str, int]]] = {}  # per package root: read once
    for node in nodes:
        paths = _paths(node, workspace)
        package = workspace.package_of(paths[0]) if paths else None
        root = package.root if package is not None else ""
        if root and root not in macros:
            macros[root] = build_macros.cmake_macros(root, workspace)
        found.append(build_macros.build_macro_calls(paths, macros.get(root, {}), workspace))
    return found


def _build_environment(node: Node, workspace: Workspace) -> dict[str, str] | None:
    """The environment a node's Python code is read in: the run's, but for a node of a
    package built per ROS version in a run that names none (``Package.node_versions``),
    where it is that version's (ros_compatibility's ``ROS_VERSION`` tests)."""
    package = workspace.packages.get(node.package)
    version = package.node_versions.get(node.executable) if package is not None else None
    return None if version is None else version_environment(workspace.environment, version)


def _entries(nodes: Sequence[Node]) -> list[str | None]:
    """The class each node is, where a container, nodelet manager or host constructs it
    (``cpp.extract_cpp``'s ``entry``): a component's, a nodelet's or a plugin's, and
    that of the executable a component's registration makes
    (``rclcpp_components_register_node(... EXECUTABLE x)``: the component's node at the
    same place, with the same sources; ``cmake.nodes.components``)."""
    made = {(node.package, node.location, tuple(node.sources)): node.executable
            for node in nodes if node.kind == "component"}
    return [node.executable if node.kind == "component" else node.plugin_class
            if node.kind in ("nodelet", "plugin") else made.get(
                (node.package, node.location, tuple(node.sources)))
            for node in nodes]


def _cpp_nodes(nodes: Sequence[Node]) -> list[Node]:
    return [node for node in nodes if node.language == "cpp" and node.sources]


def cpp_sources(nodes: Sequence[Node], workspace: Workspace) -> list[str]:
    """The C++ translation units ``extract_nodes`` may read for ``nodes`` (it reads
    those of deferred plugins only when a node loads their base: ``CppBatch.parts``
    are those it read)."""
    return [path for node in _cpp_nodes(nodes) for path in _paths(node, workspace)]


# What leaves a node's calls partly unknown, per language: the code of the diagnostic of
# each cause (a C++ error that can hide a call, ``cpp.recall``; a file that could not be
# read or parsed)
_PARTIAL_CAUSES = {
    "cpp": ("CPP_CALL_MISSED", "CPP_ERROR_NEAR_CALL", "CPP_PARSE_FAILED", "CPP_TIME_LIMIT",
            "FILE_UNREADABLE",
            "CPP_NODE_PASSED", "CPP_NODE_TO_UNKNOWN", "CPP_NODE_UNREAD", "CPP_CLASS_UNSEEN",
            "CPP_BUILD_MACRO",
            "CPP_VERSION_UNKNOWN", "CPP_TARGET_UNKNOWN", "CPP_LIBRARY_LOADED"),
    "python": ("PY_PARSE_ERROR", "PY_TOO_COMPLEX", "FILE_UNREADABLE", "PY_CLASS_UNSEEN",
               "PY_FUNCTION_UNSEEN", "PY_NODE_UNSEEN", "PY_MODULE_UNSEEN",
               "PY_LAUNCHES", "PY_DYNAMIC_IMPORT", "PY_RUNS_ROS_TOOL", "PY_CALL_DEPTH",
               "PY_DYNAMIC_CLASSES"),
}
_PARTIAL_CODE = {"cpp": "CPP_NODE_PARTIAL", "python": "PY_NODE_PARTIAL"}
# causes whose own warning (one per place) says all there is to say: a version branch
# that no known distribution decides is in a header nearly every node of a workspace
# includes (navigation2's node_utils.hpp), which made a node warning of each of 116 nodes
_SAID_AT_THE_PLACE = frozenset({"CPP_VERSION_UNKNOWN", "CPP_TARGET_UNKNOWN"})


# nodelet::Loader's load(name, type, ...): a nodelet made by name in this process (the
# wrapper executables of image_view, stereo_image_proc, ...), with arguments
NODELET_LOAD = re.compile(r"(?:\.|->)\s*(load)\s*\(\s*[^)\s]")
# the class of a ``CPP_NODELET_IN_PROCESS`` (its message)
IN_PROCESS = re.compile(r"runs the nodelet (\S+) in its own process"
                        r"|creates the plugin class (\S+) by its name written")


def _links_plugin_classes(node: Node, workspace: Workspace | None) -> bool:
    """Whether a source of ``node`` exports a plugin class: a standalone nodelet
    executable that links its nodelet's library (pointcloud_to_laserscan_node) runs
    that code, read with it (``cmake.nodes``), so its ``nodelet::Loader`` load hides
    nothing; one that links none (image_view's) makes calls we do not see."""
    if workspace is None:
        return False
    return any(exported_classes(os.path.join(workspace.root, source), workspace)
               for source in node.sources)


def _hosted(node: Node) -> bool:
    """Whether ``node`` is a plugin host of the table (``plugins.hosts``), in either
    ROS."""
    return any(host_of(node.package, node.executable, version) is not None
               for version in (1, 2))


def completeness(node: Node, found: Sequence[Diagnostic],
                 workspace: Workspace | None = None) -> list[Diagnostic]:
    """Mark ``node`` partial when the diagnostics of its sources say calls may be
    missing (``Node.mark_partial``, each reason with its file:line), unknown when it has
    no source; the warning that says so, if any. A class of another package built with
    the node (``CPP_NODE_PASSED``) hides nothing when a source of the node defines its
    constructor: a library of that package the node links (its calls are the node's)."""
    if not node.sources:
        node.completeness = "unknown"
        node.completeness_reasons = ["no source file of the node was found"]
        return []
    loads = [d for d in found if d.code == "CPP_PLUGINS_LOADED" and d.location.file]
    # a load of the class a parameter's value names (``model.source.PLUGINLIB_CLASS``):
    # the graph loads it (``plugins.attach.chains``), the site hides nothing
    named = {(c.location.file, c.location.line) for c in node.calls
             if is_class_load(c.loads)}
    loads = [d for d in loads if (d.location.file, d.location.line) not in named]
    # the nodelets run under the node's own name: the graph gives each instance their
    # calls (``CPP_NODELET_IN_PROCESS``, said instead of the load)
    # (a plugin host of the table attaches what it loads itself, move_base's default
    # recovery behaviours created by their names in its code: a load as before)
    hosted = _hosted(node)
    own = [match.group(1) or match.group(2) for d in found
           if d.code in ("CPP_NODELET_IN_PROCESS", "CPP_PLUGIN_IN_PROCESS")
           and (match := IN_PROCESS.match(d.message)) is not None
           and (d.code == "CPP_NODELET_IN_PROCESS" or not hosted)]
    if hosted:
        loads += [diag.make("CPP_PLUGINS_LOADED", d.location, text=d.message,
                            loader="pluginlib")
                  for d in found if d.code == "CPP_PLUGIN_IN_PROCESS"]
    if (own or any(NODELET_LOAD.search(d.message) for d in loads)) and (
            _links_plugin_classes(node, workspace)):
        loads = [d for d in loads if not NODELET_LOAD.search(d.message)]
        own = []
    node.nodelets = list(dict.fromkeys(own))
    node.plugin_loads = list(dict.fromkeys(f"{d.location.file}:{d.location.line}"
                                           for d in loads))
    # a unit's errors are in its files and the headers they include; an unreadable
    # file counts when it is one of the node's
    causes = [d for d in found if d.code in _PARTIAL_CAUSES.get(node.language, ())
              and (d.code != "FILE_UNREADABLE" or d.location.file in node.sources)
              and (d.code not in _DEFINED_ELSEWHERE or workspace is None
                   or not _constructed_here(d, node, workspace))]
    if not causes:
        return []
    for cause in causes:
        where = f"{cause.location.file}:{cause.location.line}" if cause.location.file else ""
        node.mark_partial(f"{where}: {cause.message}" if where else cause.message)
    if all(c.code in _SAID_AT_THE_PLACE for c in causes):
        return []  # partial: each place says why once, not once more for every node
    first = node.completeness_reasons[0]
    return [diag.make(_PARTIAL_CODE[node.language], node.location, node=node.name,
                      count=len(causes), first=first)]


# the causes that name a class whose code another source of the node may hold: the
# first word of the message is the class; a source that defines its constructor (of a
# class built with the node) or any member of it (of a ROS 1 class built without)
# is a library of its package the node links, whose calls are the node's
_DEFINED_ELSEWHERE = {"CPP_NODE_PASSED": " of package ", "CPP_CLASS_UNSEEN": " of ROS package "}


def _read_elsewhere(found: list[Diagnostic], nodes: Sequence[Node],
                    results: Sequence[CppResult], workspace: Workspace) -> list[Diagnostic]:
    """``found`` without the ``CPP_CLASS_UNSEEN`` that no node it is said for keeps: a
    class whose code every such node reads from a library it links (``move_base``'s
    ``Costmap2DROS``) is no unseen code there."""
    kept: set[Diagnostic] = set()
    dropped: set[Diagnostic] = set()
    for node, result in zip(nodes, results, strict=True):
        for said in result.diagnostics:
            if said.code == "CPP_CLASS_UNSEEN":
                (dropped if _constructed_here(said, node, workspace) else kept).add(said)
    return [d for d in found if d not in dropped or d in kept]


def _constructed_here(said: Diagnostic, node: Node, workspace: Workspace) -> bool:
    """Whether a source of ``node`` has the code of the class that ``said`` (a
    ``CPP_NODE_PASSED``, ``CPP_CLASS_UNSEEN``) names (``_DEFINED_ELSEWHERE``)."""
    cls = said.message.split(_DEFINED_ELSEWHERE[said.code], 1)[0].rsplit("::", 1)[-1].strip()
    if not cls.isidentifier():
        return False
    member = cls if said.code == "CPP_NODE_PASSED" else r"~?\w+"
    # a definition, its body or its initialisers after the parameters, not a call of a
    # static member (ROBOTIS-OP3's ``RobotisController::getInstance();`` in main)
    defines = re.compile(rf"\b{cls}\s*::\s*{member}\s*\([^;{{}}]*\)\s*"
                         r"(?:(?:const|noexcept|override|final)\b\s*)*"
                         r"(?:[{:]|=\s*(?:default|delete)\b)")
    for source in _paths(node, workspace):
        text, _ = read_text(source, workspace.location(source))
        if text and defines.search(code_only(text)):  # (not a comment's words)
            return True
    return False


def _process_nodes(node: Node, rosnames: list[str]) -> None:
    """The C++ nodes of an executable's process; a component library's classes are
    loaded one by one (each its own plugin), never together: one node, no node names."""
    if node.kind == "executable":
        node.rosnames = rosnames
    elif rosnames:
        node.calls = [replace(c, node_name=None) if c.node_name else c for c in node.calls]


def _local_rules(node: Node, found: list[tuple[str, str]]) -> dict[str, list[str]]:
    """``Node.local_rules`` of the nodes the executable makes (``rosname``,
    ``rosnames``): a component's class is one node, its own."""
    names = {node.rosname, *node.rosnames}
    rules: dict[str, list[str]] = {}
    for name, rule in found:
        if name in names and rule not in rules.get(name, []):
            rules.setdefault(name, []).append(rule)
    return rules


def _paths(node: Node, workspace: Workspace) -> list[str]:
    return [s if os.path.isabs(s) else os.path.join(workspace.root, s) for s in node.sources]


def _rosname(node: Node, found: str | None) -> str | None:
    """The node name the code gives: a plugin's, found by the build stage (mavros'
    ``Plugin(uas_, "imu")``), stays unless extraction finds one wholly known."""
    if node.kind == "plugin" and node.rosname and (not found or UNKNOWN_MARK in found):
        return node.rosname
    return found


def extract_node(node: Node, workspace: Workspace) -> list[Diagnostic]:
    sources = _paths(node, workspace)
    if node.language == "cpp" and sources:
        from .cpp import extract_cpp  # libclang loads only when there is C++ to parse

        result = extract_cpp(sources, workspace, entry=_entries([node])[0])
        node.calls = without_other_classes(
                node, without_overridden(node, result.calls, workspace), workspace)
        node.rosname = _rosname(node, result.rosname)
        _process_nodes(node, result.rosnames)
        node.handles_given = dict(result.handles_given)
        node.local_rules = _local_rules(node, result.local_rules)
        clear_where_declared(node, workspace)
        said = _read_elsewhere(result.diagnostics, [node], [result], workspace)
        return [*said, *completeness(node, result.diagnostics, workspace)]
    if node.language == "python" and sources:
        from .python import extract_python

        found = extract_python(sources, workspace, package=node.package,
                               environment=_build_environment(node, workspace),
                               entry=node.entry)
        node.calls = found.calls
        clear_where_declared(node, workspace)
        node.rosname = found.rosname
        if found.rosname and found.namespace and found.namespace.strip("/"):
            # as the C++ side writes it: the namespace the code gives, then the name
            node.rosname = f"/{found.namespace.strip('/')}/{found.rosname}"
        node.rosnames = found.nodes
        return [*found.diagnostics, *completeness(node, found.diagnostics)]
    return completeness(node, [])
