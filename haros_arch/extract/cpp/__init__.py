"""The C++ extractor for ROS 1 (roscpp): the primitive calls in one node's sources.

``extract_cpp(sources, workspace)`` parses each translation unit once with libclang,
against built-in stand-in ROS headers and message headers synthesised from the
workspace's ``.msg`` / ``.srv`` files (``headers``), so no ROS installation is needed,
and walks the functions defined in the workspace for calls listed in ``api.ROSCPP``
(``visitor``). Problems become diagnostics; nothing here raises for bad input.
"""

from __future__ import annotations

import dataclasses
import functools
import hashlib
import json
import os
import re
import weakref
from collections.abc import Callable, Collection, Iterable, Iterator, Sequence
from dataclasses import dataclass, field
from typing import Any

from clang.cindex import (
    Cursor,
    CursorKind,
    SourceLocation,
    SourceRange,
    TranslationUnit,
    TranslationUnitLoadError,
    conf,
)
from clang.cindex import Diagnostic as ClangDiagnostic

from ... import compile_commands as commands
from ... import diagnostics as diag
from ... import safe_yaml
from ...collector import held_back
from ...ctext import closing, code_only
from ...diagnostics import Diagnostic
from ...files import MAX_FILE_BYTES, read_text
from ...manifest import parse_manifest, ros_version
from ...model.conditions import Condition
from ...model.location import Location
from ...model.source import Package, PrimitiveCall, declared_defaults
from ...processes import OverTime, cpu_limit, raise_if_stopped, worker_pool
from ...workspace import Workspace, manifest_of
from .. import IN_PROCESS, NODELET_LOAD, this_run
from . import (
    api,
    cache,
    call_conditions,
    links,
    recall,
    ros2_interfaces,
    synthesis,
    targets,
    toolchain,
    values,
    versions,
)
from .conditions import fewest
from .cursors import child_spellings, in_standin, namespace_blocks
from .headers import FALLBACK, QT, STANDIN, IncludeSetup, without_pch
from .interfaces import interface_package
from .interfaces import known as known_interface
from .owners import node_names, owner_of
from .values import PLACEHOLDER
from .visitor import (
    OTHER_WRITES,
    STATIC,
    WORDS,
    CallFinder,
    header_folder,
    known_name,
    named_header_folder,
)

__all__ = ["CppBatch", "CppResult", "extract_cpp", "extract_cpp_nodes"]

# CXTranslationUnit_DetailedPreprocessingRecord (for #define constants) | KeepGoing
PARSE_OPTIONS = 0x01 | 0x200
SKIP_FUNCTION_BODIES = 0x40  # CXTranslationUnit_SkipFunctionBodies
# given to each unit after the precompiled stand-ins: the unit's ROS for the stand-ins
# (HAROS_UNIT_ROS) and, in ROS 1, boost::bind's placeholders in the global namespace
UNIT_ROS = {1: os.path.join(STANDIN, "haros_ros1.h"), 2: os.path.join(STANDIN, "haros_ros2.h")}
MAX_ERRORS_PER_FILE = 50
# the processor time one unit's parses and walks may take (``processes.cpu_limit``): the
# largest units of real workspaces take a few seconds (Autoware's, navigation2's); past
# this the unit gives no calls and says so (CPP_TIME_LIMIT), and the run goes on
UNIT_CPU_SECONDS = 120.0
_HEADER = re.compile(r"no definition found for (\S+);")
_MEMBER = re.compile(r"^no member named '\w+' in '(?:struct |class )?(?:::)?(\w+)::")
_MEMBER_NAME = re.compile(r"^no member named '(\w+)'")
_ROS2_INTERFACE_TYPE = re.compile(r"::(?:msg|srv|action)::\w")


def _fieldless_packages(found: Sequence[Diagnostic]) -> set[str]:
    """Packages whose message headers were synthesised without fields."""
    packages = set()
    for item in found:
        match = _HEADER.search(item.message) if item.code == "CPP_MESSAGE_UNKNOWN" else None
        if match:
            packages.add(match.group(1).split("/")[0])
    return packages


class _HeaderFacts:
    """What the diagnostics of a run's headers (``IncludeSetup.diagnostics``) say: the
    packages whose messages are known only by name (``_fieldless_packages``) and the
    prefixes of the C libraries whose headers are missing (``synthesis.
    library_prefixes``). Both are unions over the diagnostics, which a run only adds
    to between two questions, so each question reads those added since the last one
    (every unit asked them again of the whole run's list)."""

    def __init__(self) -> None:
        self._read = 0
        self._fieldless: set[str] = set()
        self._libraries: set[str] = set()

    def _update(self, found: Sequence[Diagnostic]) -> None:
        if len(found) < self._read:  # not a list that grew: read anew
            self._read, self._fieldless, self._libraries = 0, set(), set()
        added = found[self._read:]
        self._read = len(found)
        self._fieldless |= _fieldless_packages(added)
        self._libraries |= synthesis.library_prefixes(
            d.message for d in added if d.code == "CPP_INCLUDE_MISSING")

    def fieldless(self, setup: IncludeSetup) -> set[str]:
        self._update(setup.diagnostics)
        return set(self._fieldless)

    def libraries(self, setup: IncludeSetup) -> set[str]:
        """Of the diagnostics said before the first parse and of the headers the unit
        being parsed includes that parses stood in for (``IncludeSetup.stood_in``):
        not of what the parses of the units its process read before said, which made
        a unit's permissive declarations depend on the worker it went to."""
        prepared = setup.diagnostics if setup.prepared is None else (
            setup.diagnostics[:setup.prepared_said])
        self._update(prepared)
        return set(self._libraries) | synthesis.library_prefixes(
            d.message for d in setup.unit_missing)


_HEADER_FACTS: weakref.WeakKeyDictionary[IncludeSetup, _HeaderFacts] = (
    weakref.WeakKeyDictionary())


def _header_facts(setup: IncludeSetup) -> _HeaderFacts:
    """The ``_HeaderFacts`` of ``setup``'s diagnostics, one per setup."""
    facts = _HEADER_FACTS.get(setup)
    if facts is None:
        facts = _HEADER_FACTS[setup] = _HeaderFacts()
    return facts


_NO_MATCHING = "no matching "  # function / member function / constructor for call
_NO_CONVERSION = "no known conversion from '"


@dataclass(frozen=True, slots=True)
class _Error:
    """A clang error of a parse, each of its facts asked of libclang once (a parse's
    errors are read by every step that judges it: the stand-in repair, the rounds of
    declaring names, the choice of the best parse, the diagnostics and ``_hidden``)."""

    spelling: str
    name: str | None  # the file, as clang names it
    path: str | None  # the same, absolute
    line: int
    column: int
    offset: int
    # what its notes say of a call no overload takes: each candidate's "no known
    # conversion from 'B *' to 'A *'" (``synthesis.Names`` learns bases from them)
    notes: tuple[str, ...] = ()


# clang's error for a function template used with a type of no linkage and not defined
_UNDEFINED_HERE = "is used but not defined in this translation unit, and cannot be defined"
# libclang 18 takes ``this->member_`` in a class template as dependent (clang 19 looks the
# current instantiation up), so ``this->node_->create_subscription<MsgT>(...)`` asks for
# ``template`` before the name, which a compiler does not: a member whose type depends on
# the template's parameters would need it there too (g++ refuses the call without it)
_TEMPLATE_KEYWORD = re.compile(
    r"use 'template' keyword to treat '\w+' as a dependent template name")
_THIS_MEMBER = ("this", "->")


def _errors(tu: TranslationUnit) -> list[_Error]:
    """The errors of a parse (severity error or fatal), read once per unit."""
    found: list[_Error] | None = getattr(tu, "_haros_errors", None)
    if found is None:
        found = []
        full: dict[str, str] = {}  # a parse's errors are in a few files
        for d in tu.diagnostics:
            if d.severity < ClangDiagnostic.Error:
                continue
            loc = d.location
            file = loc.file
            name = file.name if file is not None else None
            if name is not None and _UNDEFINED_HERE in d.spelling and os.path.abspath(
                    name).startswith(STANDIN + os.sep):
                # a stand-in's template declared without a body, instantiated with a
                # lambda (``std::transform(..., [](int i) {...})``): the real library
                # defines it. Said only by a parse with no other error, it made a parse
                # with the unknown names declared no better than one without (bwi's
                # logical translator kept ``boost::algorithm`` unknown)
                continue
            if name is not None and _TEMPLATE_KEYWORD.fullmatch(d.spelling) and (
                    _through_this_member(tu, loc)):
                continue
            if name is not None and name not in full:
                full[name] = os.path.abspath(name)
            spelling = d.spelling
            notes = tuple(n.spelling for n in d.children if _NO_CONVERSION in n.spelling) \
                if spelling.startswith(_NO_MATCHING) else ()
            found.append(_Error(spelling, name, full[name] if name is not None else None,
                                loc.line, loc.column, loc.offset, notes))
        tu._haros_errors = found
    return found


def _through_this_member(tu: TranslationUnit, at: SourceLocation) -> bool:
    """Whether the tokens of ``at``'s line before it end with ``this->name->`` or
    ``this->name.``: a template named through a member of the current instantiation
    (``_TEMPLATE_KEYWORD``)."""
    start = SourceLocation.from_position(tu, at.file, at.line, 1)
    tokens = [t.spelling for t in tu.get_tokens(extent=SourceRange.from_locations(start, at))
              if t.extent.end.offset <= at.offset]
    return len(tokens) >= 4 and tuple(tokens[-4:-2]) == _THIS_MEMBER and (
        tokens[-1] in ("->", ".")) and (tokens[-2][0].isalpha() or tokens[-2][0] == "_")


def _names_fieldless_type(spelling: str, packages: set[str]) -> bool:
    """A clang error about a field of a message we know only by name: our limit, not a
    mistake in the code."""
    match = _MEMBER.match(spelling)
    return match is not None and match.group(1) in packages


def _message_field(error: _Error, packages: set[str], source: SourceCache) -> bool:
    """``_names_fieldless_type``, but not a member the code calls there: a message has
    fields, no member functions, so ``psw.getParameter("language", v, "english")`` is
    of a class whose header, missing, was synthesised as a message's (a ``pkg/Name.h`` of
    a package not in the workspace: bender's ``uchile_util/ParameterServerWrapper.h``),
    whose code may make ROS calls: an error like any other. A ROS 2 interface
    (``pkg::msg::Name``) is not so judged: its ``set__<field>`` setters and the builder
    rosidl gives it (``build<T>().x(1.0)``, the message itself for one known by name)
    call its fields."""
    if not _names_fieldless_type(error.spelling, packages):
        return False
    lines = source.lines(error.path) if error.path is not None else None
    if lines is None or not 0 < error.line <= len(lines):
        return True
    member = _MEMBER_NAME.match(error.spelling)
    if member is None or _ROS2_INTERFACE_TYPE.search(error.spelling):
        return True  # a ROS 2 interface's setters and builder (``build<T>().x(1.0)``)
    rest = lines[error.line - 1][error.column - 1:]
    return re.match(
        re.escape(member.group(1)) + r"\s*(?:<[^;()]*>\s*)?\(", rest) is None


@dataclass
class CppResult:
    """What one node's C++ sources give: calls, the name passed to ``ros::init``."""

    calls: list[PrimitiveCall] = field(default_factory=list)
    rosname: str | None = None
    diagnostics: list[Diagnostic] = field(default_factory=list)
    # what a translation unit passes to the functions of the node's other files
    # (``links``); empty in a node's result, whose calls are filled with them
    facts: list[links.Fact] = field(default_factory=list)
    # ROS 2: the nodes the executable creates, when several (``Node.rosnames``); each
    # call's ``node_name`` is one of them or None (the first node's). In a translation
    # unit's result: every node construction as (owner, name), and each call's
    # ``node_name`` is its owner (``visitor.owner_of``)
    rosnames: list[str] = field(default_factory=list)
    node_names: list[tuple[str, str]] = field(default_factory=list)
    constructions: list[tuple[str, str]] = field(default_factory=list)  # visitor's
    uses: list[tuple[str, str]] = field(default_factory=list)  # visitor's
    defines: list[str] = field(default_factory=list)  # visitor's
    # in a translation unit's result: each construction of a class of the workspace, as
    # (class, the source conditions it is made under), one per place
    made_under: list[tuple[str, tuple[Condition, ...]]] = field(default_factory=list)
    # in a translation unit's result: the words of its code where an error left by the
    # parse can hide a statement (each function with one, a constructor with its class's
    # member types; ``*``: anything, the unit was not parsed), so a construction of a
    # class named there may be missed (``links.resolve``)
    unseen: list[str] = field(default_factory=list)
    # in a translation unit's result with ``*`` in ``unseen``: the owners whose code hands
    # the node to code the parse does not read ("": one not known); the ``*`` holds
    # where one of them runs (``_reached``)
    handed: list[str] = field(default_factory=list)
    # in a translation unit's result: (word, owner) for the words of ``unseen`` found
    # only in the code of functions, each with the owner of such a function: a word
    # counts where one of them runs (``_reached``)
    unseen_in: list[tuple[str, str]] = field(default_factory=list)
    # in a translation unit's result with ``*`` in ``unseen``: (owner, class) where the
    # owner builds a class of another package with the node (``CPP_NODE_PASSED``), whose
    # code another unit of the executable may hold (a library it links); the other
    # owners of ``handed`` give the node to code the parse does not know
    # (``CPP_NODE_TO_UNKNOWN``)
    passed: list[tuple[str, str]] = field(default_factory=list)
    # in a translation unit's result with ``*`` in ``unseen``: the words its errors leave
    # unseen (``unseen`` had the node not been handed on), what the ``*`` comes down to
    # where no code the node is handed to can be the executable's (``_reached``); ``*``
    # where something else makes it (a place not read, a library class's node)
    hidden: list[str] = field(default_factory=list)
    # in a translation unit's result: the classes it registers for a container, nodelet
    # manager or host to construct, each (class, class), then (class, base) for its bases
    # (``CallFinder.registered``): where a node is such a class, what runs starts there
    # (``_reached``)
    registered: list[tuple[str, str]] = field(default_factory=list)
    # in a translation unit's result: the owners whose code creates plugin classes or
    # nodelets by name (``CPP_PLUGINS_LOADED``; "": a load outside any function) or a
    # plugin class it names (``CPP_PLUGIN_IN_PROCESS``): such a load runs where its
    # owner runs (``_unbuilt``: a class a loader may build is not left out). Not a
    # nodelet it runs as itself (``CPP_NODELET_IN_PROCESS``: the graph gives the node
    # that class's calls)
    loads_in: list[str] = field(default_factory=list)
    # in a translation unit's result: (owner of the node, class of the workspace) for each
    # call of a method of the class that hands it a node (``visitor.node_handed``)
    node_handed: list[tuple[str, str]] = field(default_factory=list)
    # in a node's result: ``Node.handles_given`` (``links.handles_given``)
    handles_given: dict[str, list[str]] = field(default_factory=dict)
    # (node name, rule) for each ``__ns`` / ``__node`` rule of a node's own arguments
    # (``CallFinder.local_rules``); in a node's result with the names filled
    # (``Node.local_rules``)
    local_rules: list[tuple[str, str]] = field(default_factory=list)


@dataclass
class CppBatch:
    """What the C++ nodes of a workspace give: one result per node, in order, with the
    diagnostics of its translation units; ``diagnostics`` are those of the batch as a
    whole (headers missing or synthesised from a bad definition, unreadable sources)."""

    results: list[CppResult] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    # each translation unit's path and the digest of what it gave (``cache.digest``): two
    # batches of the same nodes whose units and diagnostics agree give the same results
    units: dict[str, str] = field(default_factory=dict)
    # the translation units of each batch that made these, in the order it read them
    # (``extract_nodes`` reads deferred plugins in a batch of their own: the headers
    # their sources share with the first batch's are prepared, and said missing, again)
    parts: list[list[str]] = field(default_factory=list)

    def extend(self, other: CppBatch) -> None:
        """Take in the units, own diagnostics and parts of another batch read after this
        one (the deferred plugins'), not its node results."""
        self.units.update(other.units)
        self.diagnostics.extend(other.diagnostics)
        self.parts.extend(other.parts)

    def all_diagnostics(self) -> list[Diagnostic]:
        """Every diagnostic once (a translation unit shared by nodes reports once)."""
        return list(dict.fromkeys(
            [*self.diagnostics, *(d for r in self.results for d in r.diagnostics)]))


def extract_cpp(sources: list[str], workspace: Workspace, *,
                include_dirs: Sequence[str] = (), system_headers: bool = False,
                cache_dir: str | None = cache.AUTO, jobs: int | None = None,
                compile_commands: Sequence[str] | None = None,
                distro: str | None = None, entry: str | None = None) -> CppResult:
    """The ROS calls in the translation units ``sources`` (absolute paths) of a node.

    With ``system_headers`` the installed ROS headers are used instead of the stand-ins.
    ``cache_dir`` is where results are kept between runs (``"auto"``: see
    ``cache.default_folder``; None: no cache). ``jobs`` translation units are parsed at a
    time in worker processes (default: the number of cores, at most the sources).
    ``compile_commands`` are the compile_commands.json files whose include folders,
    macros and standard each source is parsed with (None: those found in the workspace,
    see ``compile_commands.find``). ``distro`` is the ROS distribution whose rclcpp
    version the stand-ins announce (``versions``; None: not known). ``entry`` is the
    class the node is when a container, nodelet manager or host constructs it (a
    component's, nodelet's or plugin's; None: an executable): its code runs, not every
    class of the libraries it links (``_reached``).
    """
    batch = extract_cpp_nodes([sources], workspace, include_dirs=include_dirs,
                              system_headers=system_headers, cache_dir=cache_dir, jobs=jobs,
                              compile_commands=compile_commands, distro=distro,
                              entries=[entry])
    result = batch.results[0]
    result.diagnostics[:0] = batch.diagnostics
    return result


def extract_cpp_nodes(nodes: Sequence[Sequence[str]], workspace: Workspace, *,
                      include_dirs: Sequence[str] = (), system_headers: bool = False,
                      cache_dir: str | None = cache.AUTO, jobs: int | None = None,
                      compile_commands: Sequence[str] | None = None,
                      meanwhile: Callable[[], None] | None = None,
                      distro: str | None = None,
                      entries: Sequence[str | None] | None = None) -> CppBatch:
    """The ROS calls of several nodes, each given by its translation units' paths.

    Every translation unit is read and parsed once however many nodes build it, all of
    them in one pool of worker processes; options as for ``extract_cpp``, ``entries``
    each node's ``entry`` (None: none has one).
    ``meanwhile``, when given, is called once, while the workers parse (after the
    batch when there are none): work of the calling process that needs no result of
    the batch runs beside it rather than after it.
    """
    folder = _folder(cache_dir, workspace)
    store = None if folder is None else cache.Cache(folder, "")
    every = [list(dict.fromkeys(map(os.path.abspath, sources))) for sources in nodes]
    said: list[str | None] = list(entries) if entries is not None else [None] * len(nodes)
    kept: dict[int, CppResult] = {}

    def unkept(digests: dict[str, str]) -> set[str]:
        """The units of the nodes whose result the cache does not keep (``_kept_nodes``):
        only theirs are read back."""
        assert store is not None
        kept.update(_kept_nodes(store, every, digests, said, loadable))
        return {p for index, paths in enumerate(every) if index not in kept for p in paths}

    loadable = _loadable(workspace)
    batch, results = _batch(nodes, workspace, include_dirs, system_headers, cache_dir, jobs,
                            compile_commands, True if store is None else unkept, meanwhile,
                            distro)
    for index, paths in enumerate(every):
        found = kept.get(index)
        if found is None:
            complete = all(p in results for p in paths)
            found = _node_result([(p, results[p]) for p in paths if p in results], complete,
                                 said[index], loadable)
            if store is not None:
                _keep_node(store, cache.node_key(paths, batch.units, complete, said[index],
                                                 loadable), found)
        batch.results.append(found)
    return batch


def _loadable(workspace: Workspace) -> frozenset[str]:
    """The classes the workspace's packages declare for a loader (the plugin, nodelet
    and component classes of their build files and plugin descriptions), without
    template arguments: what a load by name may build."""
    return frozenset(
        node.plugin_class.lstrip(":").partition("<")[0]
        for package in workspace.packages.values() for node in package.nodes
        if node.plugin_class)


def _kept_nodes(store: cache.Cache, every: list[list[str]], digests: dict[str, str],
                entries: list[str | None], loadable: frozenset[str]) -> dict[int, CppResult]:
    """The results of the nodes (each given by its translation units' paths) that the
    cache keeps, by index: those whose units give what they gave when it was kept
    (``cache.node_key``). A run after one changed source made every node of
    navigation2's bringup again from units that had not changed: 0.6 s of 3.8, and read
    back every unit's result for them."""
    found: dict[int, CppResult] = {}
    for index, paths in enumerate(every):
        complete = all(p in digests for p in paths)
        data = store.load_node(cache.node_key(paths, digests, complete, entries[index],
                                              loadable))
        result = _result_from_data(data) if data is not None else None
        if result is not None:
            found[index] = result
    return found


def _keep_node(store: cache.Cache, key: str, result: CppResult) -> None:
    """Keep a node's result made from its units (``_node_result``), unless it would not
    read back whole."""
    text = json.dumps({"result": _result_data(result)})
    if _result_from_data(json.loads(text)["result"]) == result:
        store.store_node(key, text)


def _folder(cache_dir: str | None, workspace: Workspace) -> str | None:
    """The cache folder of a run's ``cache_dir`` option (None: no cache)."""
    return None if cache_dir is None else (
        cache.default_folder(workspace.root, cache_dir))


def unit_digests(paths: Sequence[str], workspace: Workspace, *,
                 cache_dir: str | None = cache.AUTO, jobs: int | None = None,
                 compile_commands: Sequence[str] | None = None,
                 distro: str | None = None) -> CppBatch:
    """What the translation units ``paths`` (the sources of a batch's nodes, in order)
    give, in short: the batch's own diagnostics and each unit's digest (``CppBatch.units``),
    no results (a unit's kept result is not even read back); options as for
    ``extract_cpp``. The same as a batch of the same nodes gave: the same results."""
    return _batch([paths], workspace, (), False, cache_dir, jobs, compile_commands, False,
                  distro=distro)[0]


# which kept translation units' results a batch reads back: all (True), none (False),
# or those a function of every unit's digest names (``_units``)
Wanted = bool | Callable[[dict[str, str]], Collection[str]]


def _batch(nodes: Sequence[Sequence[str]], workspace: Workspace, include_dirs: Sequence[str],
           system_headers: bool, cache_dir: str | None, jobs: int | None,
           compile_commands: Sequence[str] | None, wanted: Wanted,
           meanwhile: Callable[[], None] | None = None, distro: str | None = None
           ) -> tuple[CppBatch, dict[str, CppResult]]:
    """The batch's diagnostics and unit digests, and each unit's result (without
    ``wanted``: only those parsed; see ``_units``)."""
    batch = CppBatch()
    if compile_commands is None:
        compile_commands = commands.find(workspace)
    units, batch.diagnostics = commands.load(compile_commands, workspace)
    folder = _folder(cache_dir, workspace)
    paths = list(dict.fromkeys(os.path.abspath(p) for sources in nodes for p in sources))
    batch.parts.append(paths)
    key = (workspace.root, tuple(workspace.roots), tuple(include_dirs), system_headers,
           tuple(compile_commands), folder, distro, tuple(paths))
    run = this_run()
    prepared = run.get(key) if run is not None else None
    if prepared is not None and not prepared[0].hold():
        prepared = None  # another run took the kept folder meanwhile: prepared anew
    if prepared is None:
        prepared = _prepare(paths, workspace, IncludeSetup(
            workspace, include_dirs, system_headers, units,
            [p for sources in nodes for p in sources], distro, kept_in=folder))
        if run is not None:  # closed with the run (``extract.one_run``)
            stale = run.pop(key, None)
            if stale is not None:
                stale[0].close()
            run[key] = prepared
    setup, texts, ros2, read = prepared
    store = None if folder is None else cache.Cache(folder, setup.generated, setup.written,
                                                     setup.remade)
    try:
        results = _units(texts, ros2, setup, store, jobs, batch.units, wanted, meanwhile)
    finally:
        if run is None:
            setup.close()
        else:
            setup.release()
    batch.diagnostics += [*setup.diagnostics[:setup.prepared_said], *read]
    return batch, results


# a batch's include setup with its sources' texts, whether each is ROS 2 code and the
# diagnostics of reading them
Prepared = tuple[IncludeSetup, dict[str, str], dict[str, bool], list[Diagnostic]]


def _prepare(paths: list[str], workspace: Workspace, setup: IncludeSetup) -> Prepared:
    """Read the sources and prepare every header they include (closing ``setup`` if
    that fails)."""
    read: list[Diagnostic] = []
    texts: dict[str, str] = {}
    ros2: dict[str, bool] = {}
    try:
        for path in paths:
            text, found = read_text(path, workspace.location(path))
            read.extend(found)
            if text is not None:
                texts[path] = text
                ros2[path] = _is_ros2(path, setup.scan(path, text), workspace)
    except BaseException:
        setup.close()
        raise
    # the batch's own: what preparing the headers said; what a parse adds (a header
    # clang still missed) is its unit's (``_translation_unit``), said where it was
    # parsed, in this process or a worker, so not here: the same either way
    setup.prepared_now()
    return setup, texts, ros2, read


def _is_ros2(path: str, included: bool, workspace: Workspace) -> bool:
    """ROS 2 code: as its package's manifest says (``manifest.ros_version``), else when
    it or a workspace header it includes includes rclcpp or a ROS 2 interface
    (``included``). Never by headers alone where the package tells: ROS 2 code that
    includes only tf2_ros headers is ROS 2."""
    package = workspace.package_of(path)
    version = ros_version(package) if package is not None else None
    return included if version is None else version == 2


def _made_under_fewest(calls: list[PrimitiveCall],
                       seen: dict[tuple[object, ...], list[PrimitiveCall]],
                       whole: set[tuple[object, ...]]) -> list[PrimitiveCall]:
    """``calls`` (the first of each kind, name and place), each once per set of
    conditions it is made under that no other one covers (``conditions.fewest``): nav2's
    ``declare_or_get_parameter`` reads the parameter ``if (param_interface->
    has_parameter(name))`` and, after that branch returns, reads it again, so its call
    site reads it either way; a wrapper that makes one publisher in an ``if`` and the
    same in its ``else`` makes it under neither. A read one of whose copies reads the
    values (its key in ``whole``) is no read of the keys alone."""
    out: list[PrimitiveCall] = []
    for call in calls:
        key = _call_key(call)
        made = seen[key]
        if call.keys_only and key in whole:  # ``whole``: a copy reads the values
            made = [dataclasses.replace(c, keys_only=False) for c in made]
            call = made[0]
        if len(made) < 2:
            out.append(call)
            continue
        ways = [(c.conditions, dataclasses.replace(c, conditions=())) for c in made]
        for conditions, rest in fewest(ways):
            out.append(dataclasses.replace(rest, conditions=conditions))
    return out


def _call_key(call: PrimitiveCall) -> tuple[object, ...]:
    """One call of the node: by kind, name, place and name parameter, the node a
    construction names it for (``links.per_construction``: a class built twice makes
    its calls on each of two nodes), and the image topic a camera_info call is beside
    (a camera publisher class built twice makes two). A name the code resolves, or a
    command-line word it reads, is no parameter read of that name at that place
    (swri_roscpp's ``getParam`` wrapper resolves the name and then reads it). A topic,
    service or action call of a class template is one per type its constructions give
    it (MoveIt's ``ActionBasedControllerHandle<T>`` makes a FollowJointTrajectory, a
    GripperCommand and a ParallelGripperCommand client at one place): its known type
    is part of the key (``_typed_once`` drops the copies of no known type beside it)."""
    return (call.kind, call.name, call.location, call.name_param,
            links.per_construction(call.node_name)[1], call.camera_of, call.resolved,
            call.argument, _interface_type(call))


def _interface_type(call: PrimitiveCall) -> str | None:
    """The known type of a topic, service or action call; None for a parameter's call
    (a ``hasParam`` before a read is one read, typed by the read) or a type not known."""
    if call.kind in _PARAMETER_KINDS or call.type in (None, "?"):
        return None
    return call.type


_PARAMETER_KINDS = frozenset({"read", "write", "declare"})


def _typed_once(calls: list[PrimitiveCall]) -> list[PrimitiveCall]:
    """``calls`` without a topic, service or action call of no known type where one of
    the same kind, name and place has one (a unit that does not see the construction
    that types it: the typed copies say it)."""
    typed = {(c.kind, c.name, c.location) for c in calls if _interface_type(c) is not None}
    return [c for c in calls if c.kind in _PARAMETER_KINDS or c.type not in (None, "?")
            or (c.kind, c.name, c.location) not in typed]


# the diagnostics the visitor makes at a call it keeps, which say something of that call
_OF_A_CALL = frozenset({"CPP_CALL_UNRESOLVED"})
# what says a unit's code loads code by name into its process: a plugin, a nodelet it runs
# as itself, a shared library (``_runs_any``)
_LOADS = frozenset({"CPP_PLUGINS_LOADED", "CPP_NODELET_IN_PROCESS", "CPP_LIBRARY_LOADED"})


def _runs_any(units: Iterable[CppResult], reaching: object, entry: str | None) -> bool:
    """Whether code the node's files do not show may call any of their functions, so a
    function no file of the node calls may still run and its calls stay
    (``links.never_run`` is not applied to them): the node starts from no ``main()``
    read (``_reached``'s answer ``reaching`` is None: what starts it is not known, a
    library's functions are its users'), or is a plugin, nodelet or component class
    (``entry``), whose host may call any method of it and of its bases, virtual or not
    (nav2's costmap calls a layer's non-virtual ``Layer::initialize``), or its code
    loads code by name into its process (``loads_in``, ``_LOADS``), which may call any
    function it is handed an object of (move_group's capabilities, loaded by pluginlib,
    call ``PlanExecution::planAndExecute``, which nothing of move_group's own files
    calls)."""
    return reaching is None or entry is not None or any(
        unit.loads_in or any(d.code in _LOADS for d in unit.diagnostics) for unit in units)


def _exported_here(units: Iterable[CppResult], reaching: object, entry: str | None
                   ) -> Callable[[str], bool] | None:
    """Whether a loader's export of a class (by its USR) builds it in this node
    (``links.NodeFacts.idle``): for a component, plugin or nodelet class (``entry``),
    only that class, which its host builds, not another class its files register (a
    container builds that as a node of its own); for a program with a ``main()``
    that loads no code by name, none; None where that is not known (no ``main()``
    read, or code loaded by name into the process, which may build any)."""
    if reaching is None or any(unit.loads_in or any(d.code in _LOADS for d in unit.diagnostics)
                               for unit in units):
        return None
    if entry is None:
        return lambda usr: False
    name = entry.replace(" ", "").lstrip(":")

    def here(usr: str) -> bool:
        qualified = "::".join(_USR_SCOPE.findall(usr))
        return qualified == name or qualified.endswith("::" + name) or (
            name.endswith("::" + qualified))
    return here


# the namespaces and classes a class's USR is scoped in, outermost first
_USR_SCOPE = re.compile(r"@(?:N|S|C|ST|SP)@([^@#$>]+)")


def _node_result(paths_units: list[tuple[str, CppResult]], complete: bool = True,
                 entry: str | None = None, loadable: Collection[str] = ()) -> CppResult:
    result = CppResult()
    units = [unit for _, unit in paths_units]
    # each call by kind, name and place: one of them, and the conditions the others
    # are made under (a wrapper's call site makes the calls of its branches)
    seen: dict[tuple[object, ...], list[PrimitiveCall]] = {}
    placed: dict[tuple[object, ...], int] = {}  # each key's index in result.calls
    # the calls of which one copy reads values (a ROS 1 presence test, ``hasParam``,
    # reads the keys alone; a ``getParam`` of the same name at the same place, both in
    # one wrapper, costmap_2d's move_parameter, reads the values: so does the call)
    whole: set[tuple[object, ...]] = set()
    facts = [fact for unit in units for fact in unit.facts]
    # where a construction may be missed: the words of the code around the errors the
    # parse left (an error drops its statement), everywhere when a file was not read
    read = {owner for unit in units for owner in unit.defines}
    unseen = {word for unit in units for word in _unit_unseen(unit, read)} | (
        links.opaque_unseen(facts)) if complete else {"*"}
    ordered = sorted(paths_units, key=lambda pair: pair[0])
    reaching = _reached(ordered, unseen, entry)
    loaded = _exported_unbuilt(reaching, units)
    if loaded:  # what code the process never runs passes is passed nowhere
        away = {site for usr, index, _, site in facts
                if index == links.EXPORTED_AT and usr in loaded}
        facts = [fact for fact in facts if fact[3] not in away]
    built = _built_under(facts, _building_unseen(units, facts) if complete else unseen)
    known = links.NodeFacts(facts)  # read once for every unit's calls
    hosting = _runs_any(units, reaching, entry)
    called = call_conditions.shared(facts, unseen, links.constructor_unbuilt(known, unseen),
                                    links.construction_unseen(unseen),
                                    links.never_run(known, unseen) if not hosting else (
                                        lambda usr: False))
    given = links.node_rosnames([unit.rosname for unit in units], known, unseen)
    # the one name the units agree on; else unknown (``links.node_rosnames``), or a
    # process of several nodes named as before from its first file (``_name_nodes``)
    result.rosname = (given[0] if all(n == given[0] for n in given) else "?") if (
        given) else None
    # the owners whose constructor names their node from its parameters, given several
    # values (or none known): their calls are made once per construction (``resolve``)
    written: dict[str, set[str]] = {}
    for unit in units:
        for owner, name in unit.node_names:
            written.setdefault(owner, set()).add(name)
    per_site = {owner: next(iter(names)) for owner, names in written.items()
                if len(names) == 1 and PLACEHOLDER in next(iter(names))
                and "?" in links.resolve_name(next(iter(names)), known, unseen)}
    result.handles_given = links.handles_given(known, unseen)
    for unit in units:
        calls, found = links.resolve(unit.calls, known, unseen, per_site, hosting,
                                     _exported_here(units, reaching, entry))
        # a diagnostic of a call the node does not make (one a header's template or a
        # constructor no file of the node calls makes) is none of the node's
        dropped = {call.location for call in unit.calls} - {call.location for call in calls}
        result.diagnostics.extend(d for d in unit.diagnostics
                                  if d.code not in _OF_A_CALL or d.location not in dropped)
        result.diagnostics.extend(found)
        for call in calls:
            if call.built_in is not None:
                extra = tuple(c for c in built.get(call.built_in, ())
                              if c not in call.conditions)
                call = dataclasses.replace(call, built_in=None,
                                           conditions=(*extra, *call.conditions))
            if call.called_in is not None:
                extra = tuple(c for c in called.get(call.called_in, ())
                              if c not in call.conditions)
                call = dataclasses.replace(call, called_in=None,
                                           conditions=(*extra, *call.conditions))
            # (two calls named '?' by different parameters are two: nav2's
            # CostmapSubscriber, built with the local and the global costmap's topic)
            key = _call_key(call)
            if not call.keys_only:
                whole.add(key)
            if key not in seen:
                seen[key] = [call]
                placed[key] = len(result.calls)
                result.calls.append(call)
                continue
            kept = seen[key][0]
            if kept.type is None and call.type is not None:
                # a wrapper that checks a parameter (``hasParam``) before it reads it:
                # both are made where the wrapper is called; the read gives the type
                kept = seen[key][0] = result.calls[placed[key]] = dataclasses.replace(
                    kept, type=call.type)
            if call.conditions not in (c.conditions for c in seen[key]):
                seen[key].append(call)
    result.calls = _typed_once(_made_under_fewest(result.calls, seen, whole))
    # a copy named by no parameter beside one that is (a header's function that another
    # unit reads without its caller: opennav_docking's parseDockParams) is that one
    named = {(c.kind, c.name, c.location) for c in result.calls if c.name_param is not None}
    result.calls = [c for c in result.calls if c.name_param is not None
                    or (c.kind, c.name, c.location) not in named]
    result.calls = _members_named(result.calls)
    result.diagnostics = list(dict.fromkeys(result.diagnostics))
    _name_nodes(result, ordered, known, unseen, given, entry, (reaching, loaded), loadable)
    result.local_rules = list(dict.fromkeys(
        (links.resolve_name(name, known, unseen), rule)
        for unit in units for name, rule in unit.local_rules))
    result.calls = declared_defaults(result.calls)
    return result


def _members_named(calls: list[PrimitiveCall]) -> list[PrimitiveCall]:
    """The node's calls, where a name is wholly a member that its own file never writes
    (``PrimitiveCall.name_member``) and another file of the node stores one parameter's
    value in that member and nothing else there (``stores``), named by that parameter:
    topic_tools' ToolBaseNode publishes on ``output_topic_`` (tool_base_node.cpp), which
    RelayNode's constructor sets from ``declare_parameter("output_topic", ...)``
    (relay_node.cpp). Reads of different parameters into one member leave it '?'. The
    two marks are a unit's only: cleared here."""
    held: dict[str, set[str]] = {}
    # the parameter's default as a name: a string, or one holding another parameter's
    # value (``input_topic_ + "_relay"``: "?_relay" and that parameter)
    defaults: dict[str, tuple[str | None, str | None]] = {}
    for call in calls:
        if call.stores is not None and call.kind in ("read", "declare"):
            # a file that writes the member otherwise too: not that value alone
            other = call.stores.startswith(OTHER_WRITES)
            usr = call.stores.removeprefix(OTHER_WRITES)
            held.setdefault(usr, set()).add("?" if other else call.name)
            if call.name_default is not None:
                defaults.setdefault(usr, (call.name_default, call.default_param))
            elif isinstance(call.default, str) and call.has_default:
                defaults.setdefault(usr, (call.default, None))
    out: list[PrimitiveCall] = []
    for call in calls:
        if call.name_member is not None or call.stores is not None:
            names = held.get(call.name_member or "", set())
            named = call.name_member is not None and call.name.count("?") == 1 and (
                call.name_param is None and len(names) == 1 and known_name(next(iter(names))))
            default, other_param = defaults.get(call.name_member or "", (None, None)) if (
                named) else (call.name_default, call.default_param)
            call = dataclasses.replace(
                call, name_member=None, stores=None,
                name_param=next(iter(names)) if named else call.name_param,
                name_default=default, default_param=other_param)
        out.append(call)
    return out


def _unit_unseen(unit: CppResult, read: set[str]) -> list[str]:
    """The words where a unit's errors may hide a construction (``CppResult.unseen``);
    for a unit whose ``*`` comes only from handing its node to classes of another
    package (``CPP_NODE_PASSED``) whose code a unit of this node holds (``read``: a
    library it links; navigation2's behavior server gives itself to costmap_2d's
    ``CostmapSubscriber``, read from costmap_subscriber.cpp), what its errors hide
    (``CppResult.hidden``): that code's calls are the node's, read, not unseen."""
    if unit.unseen != ["*"] or not unit.passed or "" in unit.handed or (
        unit.hidden == ["*"]
    ) or any(cls not in read for _, cls in unit.passed) or (
        set(unit.handed) - {owner for owner, _ in unit.passed}
    ) or any(d.code in ("CPP_NODE_TO_UNKNOWN", "CPP_NODE_UNREAD") for d in unit.diagnostics):
        return unit.unseen
    return unit.hidden


def _building_unseen(units: list[CppResult], facts: list[links.Fact]) -> set[str]:
    """The words where a construction of a class of the executable may be missed, for
    the conditions a class is built under (``_built_under``): as ``unseen``, but a unit
    whose node is handed (``*``) only to known code, a function or a class of another
    package given ``this`` (``CPP_NODE_PASSED``: Autoware's ``VehicleInfoUtils(*this)``),
    counts what its errors hide (``CppResult.hidden``) and the names it hands the node
    to, as ``_reached`` does where that code runs. Such code cannot name a class of the
    package that depends on it (packages do not depend on each other in a circle):
    velocity_smoother's four smoothers, each built in one ``case`` of a ``switch`` on
    the algorithm, kept no condition, and the parameters only the smoothers not chosen
    read were 17 false "read but never set"."""
    words: set[str] = set()
    for unit in units:
        if unit.unseen == ["*"] and unit.handed and "" not in unit.handed and (
                unit.hidden != ["*"]):
            words.update(unit.hidden)
        else:
            words.update(unit.unseen)
    return words | links.opaque_unseen(facts)


def _built_under(facts: list[links.Fact], unseen: set[str]) -> dict[str, tuple[Condition, ...]]:
    """Constructor USR -> the source conditions every place of the node's files that
    calls it shares (``links.CONDITIONS``): the calls the constructor makes in a file
    that constructs its class nowhere exist only under them (sick_tim310 makes its
    ``SickTimCommonMockup``, which subscribes ``datagram`` in sick_tim_common_mockup.cpp,
    only ``if (subscribe_datagram)``). None for a constructor with a place that is
    unconditional, or whose class the errors the parse left may construct unseen."""
    sites: dict[str, dict[str, tuple[Condition, ...] | None]] = {}
    for usr, index, value, site in facts:
        if index in links.NOT_CALLS or index in call_conditions.INDICES:
            continue
        at = sites.setdefault(usr, {})
        if index != links.CONDITIONS:
            at.setdefault(site, None)
            continue
        try:
            at[site] = cache.conditions_of_text(value)
        except (ValueError, TypeError, KeyError):
            at[site] = None
    found: dict[str, tuple[Condition, ...]] = {}
    for usr, at in sites.items():
        shared = _shared_under(list(at.values())) if "*" not in unseen and (
            links.class_of(usr) not in unseen) else ()
        if shared:
            found[usr] = shared
    # a class's: what the places that build it with any of its constructors share (a
    # method runs on an object built there; ``links.CLASS_BUILT``), for a class no loader
    # or global names (``call_conditions.NAMED_CLASS``: a plugin's export)
    named = {usr for usr, index, _, _ in facts if index == call_conditions.NAMED_CLASS}
    classes: dict[str, list[tuple[Condition, ...] | None]] = {}
    for usr, at in sites.items():
        if "@F@" in usr and "@ST>" not in usr and "@SP>" not in usr and (
                links.is_constructor_usr(usr)):
            classes.setdefault(usr.split("@F@", 1)[0], []).extend(at.values())
    for cls, held in classes.items():
        # (not a loop's or a ``try``'s, as ``call_conditions`` carries none: a method of
        # an object built in a turn of a loop over a list is no call of the loop's)
        shared = tuple(c for c in _shared_under(held) if c.statement not in (
            call_conditions.NOT_CARRIED)) if "*" not in unseen and cls not in named and (
            cls.rsplit("@", 1)[-1] not in unseen) else ()
        if shared:
            found[f"{links.CLASS_BUILT}{cls}"] = shared
    return found


def _shared_under(held: list[tuple[Condition, ...] | None]) -> tuple[Condition, ...]:
    """The conditions every one of ``held`` (a construction place's, None for one with
    none known) has; none when a place has none."""
    if not held or any(c is None for c in held):
        return ()
    return tuple(c for c in held[0] or () if all(c in other for other in held[1:]
                                                if other is not None))


def _name_nodes(result: CppResult, units: list[tuple[str, CppResult]],
                facts: links.NodeFacts, unseen: Collection[str] = frozenset({"*"}),
                given: Sequence[str] = (), entry: str | None = None,
                reaching: tuple[Any, set[str]] = (None, set()),
                loadable: Collection[str] = ()) -> None:
    """The executable's nodes when its files construct several with fully known names
    (in the order met, files by path), and each call's node (``_node_of``); None where
    no one node can be told (the graph gives those calls to the first node). The calls
    of a node class the executable's ``main()`` (or the registered class ``entry``)
    never builds are left out (``_unbuilt``), and those of the classes it exports for a
    host and never builds (``reaching``: ``_reached``'s answer and
    ``_exported_unbuilt``'s)."""
    owners: dict[str, list[str]] = {}
    made_by: dict[str, list[str]] = {}
    for _, unit in units:
        for maker, made in unit.constructions:
            made_by.setdefault(made, []).append(maker)
        for caller, used in unit.uses:
            # a free function of the workspace that names no node makes its calls on
            # the node of what calls it (foxglove_bridge's ``declareParameters(this)``
            # in its node's constructor, beside main's ``dummy`` node), as a class on
            # the node of what constructs it
            if used.endswith("()") and caller != used and caller not in made_by.get(used, ()):
                made_by.setdefault(used, []).append(caller)
    constructed = {made for _, unit in units for _, made in unit.constructions}
    for _, unit in units:
        for giver, cls in unit.node_handed:
            # a class no code constructs by a call (a member object, built with the
            # class holding it) makes its calls on the node its methods are handed:
            # sbg_ros2_driver's MessagePublisher publishes on the node given to
            # ``initPublishers(node, ...)``, its ConfigStore reads through the local
            # node given to ``loadFromRosNodeHandle(n_private)``
            if cls not in constructed and giver not in made_by.get(cls, ()):
                made_by.setdefault(cls, []).append(giver)
    found, loaded = reaching
    reached, hiding, entered, named, scoped, _exported = found if found is not None else (
        None, unseen, set(), set(), {}, [])
    unbuilt_constructor = links.constructor_unbuilt(facts, unseen)
    idle_names: set[tuple[str, str]] = set()
    for _, unit in units:
        for owner, written in unit.node_names:
            name = links.resolve_name(written, facts, unseen)
            owners.setdefault(owner, [])
            marked = links.constructor_marked(written) if "?" in name else None
            if marked is not None and unbuilt_constructor(marked):
                idle_names.add((owner, name))
            if name not in owners[owner]:
                owners[owner].append(name)
            if "?" not in name and name not in result.rosnames and (
                    reached is None or owner in reached):
                result.rosnames.append(name)
    for owner, names in owners.items():
        # a name a constructor no file of the node calls would give (mavros' delegating
        # ``Router(node_name) : Router(NodeOptions(), node_name)`` beside the
        # ``Router(options, "mavros_router")`` main builds) is none, when another is known
        if any((owner, name) not in idle_names for name in names):
            names[:] = [name for name in names if (owner, name) not in idle_names]
    if reached is not None and result.rosname is not None and not any(
            owner in reached for owner, names in owners.items() if result.rosname in names):
        # named by a class the process never makes (a header's node class beside the
        # helper the node builds: aerostack2's UsbCameraInterfaceNode): the name of one
        # it makes, when one is known; not known when none is
        if result.rosnames:  # the first file's, of the nodes it makes
            result.rosname = next((n for n in given if n in result.rosnames),
                                  result.rosnames[0])
        elif any(result.rosname in names for names in owners.values()):
            result.rosname = "?"
    loads = {owner for _, unit in units for owner in unit.loads_in}
    # what code of another owner than the class itself constructs or calls
    elsewhere = {made for _, unit in units for maker, made in (*unit.constructions, *unit.uses)
                 if maker != made and not maker.startswith(made + "::")}
    unbuilt = _unbuilt(owners, reached, result, hiding, entered, named, scoped, loads,
                       {cls for pair in _exported for cls in pair} | set(loadable),
                       elsewhere) | loaded
    for call in result.calls:  # a class's nodes, one per construction (``links.resolve``)
        holder, own = links.per_construction(call.node_name)
        if own is not None and holder not in unbuilt and own not in result.rosnames and (
                reached is None or holder in reached):
            result.rosnames.append(own)
    if len(result.rosnames) < 2:
        result.rosnames = []
    under = _made_under(units, owners, result.rosnames)
    calls: list[PrimitiveCall] = []
    # the copies made so far by ``_call_key``: equal calls have equal keys, so a copy
    # is looked for among its few namesakes, not among every call of the node
    copies: dict[tuple[object, ...], list[PrimitiveCall]] = {}
    nodes: dict[str, str | None] = {}
    for call in result.calls:
        holder, own = links.per_construction(call.node_name)
        if holder in unbuilt:
            continue
        if own is not None:
            call = dataclasses.replace(call, node_name=holder)
        node = own if own in result.rosnames else _node_of(
            holder, owners, made_by, result.rosnames, nodes, 0)
        # a copy: a translation unit's calls are shared by the nodes that build it
        if call.node_name is None and node is None:
            calls.append(call)
            continue
        for each in [node] if node is not None or own is not None else _makers_nodes(
                holder, owners, made_by, result.rosnames, nodes):
            extra = tuple(c for c in under.get(each or "", ()) if c not in call.conditions)
            copy = dataclasses.replace(call, node_name=each,
                                       conditions=(*extra, *call.conditions))
            same = copies.setdefault(_call_key(copy), [])
            if copy not in same:
                same.append(copy)
                calls.append(copy)
    result.calls = calls


def _makers_nodes(owner: str | None, owners: dict[str, list[str]],
                  made_by: dict[str, list[str]], rosnames: list[str],
                  known: dict[str, str | None]) -> list[str | None]:
    """The nodes an owner that names no node of its own makes its calls on, when several
    of the process's nodes construct it, each known (``_node_of``): each of them, as
    each hands it its own node (a ``Heartbeat(this)`` both nodes build publishes on
    both). ``[None]`` where one of them is not known: the node is not told."""
    if owner is None or owners.get(owner) or not rosnames:
        return [None]
    makers = [_node_of(maker, owners, made_by, rosnames, known, 1)
              for maker in made_by.get(owner, ())]
    if len(makers) < 2 or None in makers:
        return [None]
    return [name for name in rosnames if name in makers]


def _unbuilt(owners: dict[str, list[str]], reached: set[str] | None, result: CppResult,
             unseen: Collection[str], entered: set[str], named: set[str],
             scoped: dict[str, set[str]] | None = None,
             loads: Collection[str] = ("",),
             loadable: Collection[str] = (),
             built_elsewhere: Collection[str] = ()) -> set[str]:
    """The owners of the executable's files that its ``main()`` never runs
    (``_reached``): they make no node and no call in this process. A node class (one
    whose constructor names a node) it never builds (plansys2's compute_bt links
    ExecutorNode and never builds one; its ``transition_event`` publisher was given to
    the process's node), a free function it never calls, and a class whose code only
    such code constructs or calls (``entered``) or names where the parse left an error
    (``named``, the words there) (open-rmf's door_supervisor links the fleet adapter's
    library: its ``agv::Node`` is made only by the adapter's factory). A class that
    nothing in the executable constructs or calls keeps its calls: a host, a
    registration or a call through its base may run its methods (but see
    ``_exported_unbuilt``). When the executable loads plugins or nodelets by name
    (a name written in its code too) in code that runs (``loads``, the owners holding
    such a load; "": anywhere), or components (a factory may build them), only a node
    class that no file of it registers for a loader and no package of the workspace
    declares for one (``loadable``: the classes registered in its files, with the bases
    registered with them, and every plugin, nodelet and component class of the
    workspace's build files and plugin descriptions), and no code of it but the class's
    own constructs or calls (``built_elsewhere``: a class's factory that nothing calls
    builds nothing): a loader builds declared classes alone (plansys2's
    executor_node loads its behaviour-tree builders by name and links ComputeBT, which
    only compute_bt builds), nor a class
    whose name the code around the parse's errors holds (they may hide its
    construction; a word found only in the code of functions names a class there as
    C++ looks it up from them, ``scoped``: open-rmf's
    EasyTrafficLight writes ``Implementation`` for its own, never rmf_task_ros2's
    ``Dispatcher::Implementation``)."""
    if reached is None or "*" in unseen:
        return set()
    scoped = scoped or {}
    by_name = _loads_by_name(reached, loads, (call.name for call in result.calls))
    classes = {owner for owner, names in owners.items()
               if names and owner not in reached and not owner.endswith("()")
               # a class, or a function's local node handle (its USR: ``_reached`` has
               # the function that holds it)
               and ("@" in owner or not _named_in(owner, unseen, scoped))
               and not (by_name and ("@" in owner or owner in loadable
                                     or owner in built_elsewhere))}
    if by_name:
        return classes
    return classes | {owner for call in result.calls
                      if (owner := links.per_construction(call.node_name)[0]) is not None
                      and owner not in reached and (owner.endswith("()") or (
                          (owner in entered or owner.rsplit("::", 1)[-1] in named)
                          and not _named_in(owner, unseen, scoped)))}


def _loads_by_name(reached: set[str], loads: Iterable[str], names: Iterable[str]) -> bool:
    """Whether code of the executable that runs creates classes by name: a plugin or
    nodelet load whose owner runs (``CppResult.loads_in``; "": anywhere), or a call of a
    component container's load service (ros2_canopen's loads node classes so)."""
    return any(owner == "" or owner in reached for owner in loads) or any(
        name.endswith("_container/load_node") for name in names)


def _exported_unbuilt(found: tuple[Any, ...] | None, units: Iterable[CppResult]) -> set[str]:
    """The classes an executable's files export for a host (a plugin's registration)
    that its code never builds or calls a method of, with the bases they give them,
    where ``_reached`` (``found``) tells what runs, no code that runs loads plugins by
    name (``CppResult.loads_in``) and no error may hide a construction: that host
    builds them, in its own process, and their code runs nowhere in this one.
    teb_local_planner's test_optim_node links the planner's library and calls only a
    static method of TebLocalPlannerROS: the subscriptions and reads its
    ``initialize(name, ...)`` makes under the plugin's name are move_base's."""
    if found is None:
        return set()
    reached, hiding, _entered, _named, scoped, exported = found
    units = list(units)
    # (a nodelet the executable runs as itself, ``CPP_NODELET_IN_PROCESS``, may be one
    # of them: pointcloud_to_laserscan_node links its nodelet's library and loads it)
    if not exported or "*" in hiding or _loads_by_name(
            reached, (owner for unit in units for owner in unit.loads_in),
            (call.name for unit in units for call in unit.calls)) or any(
            d.code == "CPP_NODELET_IN_PROCESS" for unit in units for d in unit.diagnostics):
        return set()
    loaded = {cls for cls, base in exported if cls == base and cls not in reached
              and not _named_in(cls, hiding, scoped)}
    return loaded | {base for cls, base in exported if cls in loaded and (
        base not in reached) and not _named_in(base, hiding, scoped)}


def _in_process(units: list[tuple[str, CppResult]], exported: list[tuple[str, str]]
                ) -> set[str]:
    """The exported classes (``exported``: the units' registrations, a class paired
    with itself and with each base) that a ``nodelet::Loader`` load of the executable
    runs in its own process (``CPP_NODELET_IN_PROCESS``, by lookup name): the class
    whose qualified name the lookup name spells with ``/``
    (``apriltag_ros/ContinuousDetector``), else whose last name is the lookup name's,
    else the one class exported when there is one."""
    names = [match.group(1) for _, unit in units for d in unit.diagnostics
             if d.code == "CPP_NODELET_IN_PROCESS"
             and (match := IN_PROCESS.match(d.message)) is not None]
    classes = list(dict.fromkeys(cls for cls, base in exported if cls == base))
    found: set[str] = set()
    for name in names:
        same = [c for c in classes if c.replace("::", "/") == name] or [
            c for c in classes if c.rpartition("::")[2] == name.rpartition("/")[2]] or (
            classes if len(classes) == 1 else [])
        found.update(same)
    return found


def _named_in(cls: str, words: Collection[str], scoped: dict[str, set[str]]) -> bool:
    """Whether the code that may hide a construction (``words``) can name the class
    ``cls``: its own name is one of them, anywhere, or written in a function or a class
    declaration (``scoped``: the owners that run holding it) whose scopes C++ looks it
    up in (its class, the namespaces around it) hold the class, or where the class or
    namespace just around it is named too, in the same code or anywhere
    (``Dispatcher::Implementation``, a ``using namespace``). Not where only an outer
    namespace is: open-rmf's schedule node names ``rmf_traffic_ros2`` and builds
    ParticipantRegistry, whose declaration names its own ``Implementation``, never
    ``rmf_traffic_ros2::schedule::Negotiation::Implementation``."""
    scope, _, own = cls.rpartition("::")
    if own not in words:
        return False
    holders = scoped.get(own)
    if holders is None:
        return True
    around_it = scope.rpartition("::")[2]
    if around_it in words and (scoped.get(around_it) is None
                               or not scoped[around_it].isdisjoint(holders)):
        return True  # named with its class or namespace, or after a using-directive
    for holder in holders:
        parts = holder.removesuffix("()").split("::")
        around = parts[:-1] if holder.endswith("()") else parts
        if any("::".join(around[:depth]) == scope for depth in range(len(around) + 1)):
            return True
    return False


def _reached(units: list[tuple[str, CppResult]], unseen: Collection[str] = (),
             entry: str | None = None
             ) -> tuple[set[str], set[str], set[str], set[str], dict[str, set[str]],
                        list[tuple[str, str]]] | None:
    """The owners whose code the executable runs, when its files hold a ``main()`` or
    register the class ``entry`` (a component's, nodelet's or plugin's, which its
    container or host constructs and calls the methods of: that class and its bases
    start as ``main()`` does, ``_registered``): the
    functions ``main()`` calls or hands on and the classes it constructs or calls the
    methods of, transitively (a class's bases with it, its methods' calls and
    constructions with it). A library the executable links is not run as a whole: its
    free functions and the node classes they make run only when reached (open-rmf's
    door_supervisor links rmf_fleet_adapter's library and builds none of its fleet
    adapter's nodes). What the initialisers of variables of namespace scope name runs
    too (gtest's TEST_F registers its test class so). Where a unit whose code runs
    leaves a call unseen (``CppResult.unseen``), every free function named in the code
    around it runs too, and every free function where code of it that runs hands a
    node to code the parse does not read (``*``); a class named there is
    ``_unbuilt``'s to keep.
    With them, the words of ``unseen`` that are no unit's (the opaque constructions' of
    the node's facts; ``*`` where a file of the node is not read) and those of the
    units that run: what may hide a construction in this process; and the owners some
    code of the executable constructs or calls (its own too: a class's factory method
    making it; with ``entry``, the other classes its files register, which their own
    containers construct), and the words every unit's code leaves unseen (a class named there may
    be constructed there: open-rmf's Dispatcher makes its private implementation
    through rmf_utils' make_impl, a template the parse may not have; a word found only
    in functions is hiding where one of them runs). None without a
    ``main()`` or a registration of ``entry`` (a class no registration the parse read
    names: what its container runs is not known)."""
    edges: dict[str, list[str]] = {}
    functions: set[str] = set()
    # each unit's owners, unseen words, the owners that hand its node on (``*``), the
    # words of its errors, what ``*`` comes down to (``CppResult.hidden``), and the
    # owners that build with the node a class whose code no unit holds
    held: list[tuple[set[str], list[str], set[str], dict[str, set[str]], list[str],
                     set[str]]] = []
    named: set[str] = set()  # every unit's unseen words
    # the classes whose code some unit of the executable holds
    read = {owner for _, unit in units for owner in unit.defines}
    for _, unit in units:
        for maker, made in (*unit.constructions, *unit.uses):
            edges.setdefault(maker, []).append(made)
            functions.update(o for o in (maker, made) if o.endswith("()"))
        # a unit's code is what its own source defines (a header's is in every unit
        # including it); the functions that may run, those and any that makes a call
        here = set(unit.defines)
        functions.update(owner for owner in here if owner.endswith("()"))
        functions.update(owner for call in unit.calls
                         if (owner := call.node_name) is not None and owner.endswith("()"))
        within: dict[str, set[str]] = {}
        for word, owner in unit.unseen_in:
            within.setdefault(word, set()).add(owner)
        unread = {owner for owner, cls in unit.passed if cls not in read}
        held.append((here, unit.unseen, set(unit.handed), within, unit.hidden, unread))
        named.update(unit.unseen)
        named.update(within)
    starts = {owner for owner in functions if owner == "main()" or owner.endswith("::main()")}
    # the classes the executable's code names as owners (a static method's scope is one)
    classes = {owner for owner in (*read, *edges, *(t for ts in edges.values() for t in ts))
               if not owner.endswith("()")}
    registered = _registered(units, entry)
    for cls, base in registered:
        if base == cls:
            starts.add(cls)
        else:
            edges.setdefault(cls, []).append(base)
    # the other classes registered beside it: their containers construct them, not this
    # node's (two nodelets of one file)
    hosted = {cls for _, unit in units for cls, base in unit.registered
              if cls == base} if registered else set()
    # with a main(): the classes registered for a loader or container elsewhere (a
    # plugin's export), and their bases: built by that host, as a node or plugin of
    # its own, not by this process unless its code builds them (``_unbuilt``)
    exported = [] if registered else list(dict.fromkeys(
        pair for _, unit in units for pair in unit.registered))
    if not starts:
        return None
    # a nodelet main() loads under the node's own name (``CPP_NODELET_IN_PROCESS``):
    # the exported class it names runs here as an entry does, with what it builds
    # (apriltag_ros' continuous node: ContinuousDetector's TagDetector, in another source)
    starts.update(_in_process(units, exported))
    starts.add(STATIC)
    reached: set[str] = set()
    words = outside = set(unseen) - named
    anywhere = set(outside)  # the words not held by functions alone
    scoped: dict[str, set[str]] = {}  # the others: the owners that run holding each
    while starts:
        reached |= starts
        stack = list(starts)
        while stack:
            for made in edges.get(stack.pop(), ()):
                if made not in reached:
                    reached.add(made)
                    stack.append(made)
        # a unit runs when some code of it runs (one whose code is not known, or
        # holds no definition: it may); its node handed to unknown code (``*``) only
        # where the code that hands it runs (rmf_task_ros2's Dispatcher hands its own
        # node on, and only its schema's static initialiser runs in door_supervisor)
        anywhere, scoped = set(outside), {}
        for here, said, handed, within, hidden, unread in held:
            if here and here.isdisjoint(reached):
                continue
            if said == ["*"] and handed and "" not in handed and handed.isdisjoint(reached):
                continue
            if said == ["*"] and handed and "" not in handed and hidden != ["*"] and (
                    unread.isdisjoint(reached)):
                # the node handed, where this code runs, only to code no unit of the
                # executable holds (a vendor's template: rmf_traffic_ros2's Negotiation
                # gives it to rmf_utils' make_unique_impl<Implementation>) or to a class
                # whose code one holds (read where it runs): such code builds nothing
                # of the executable's but what the statement hands it, which the unit
                # reads as its own references; what is hidden is what its errors hide
                said = hidden
            # a word found only in functions counts where one of them runs
            for word in said:
                if word not in within:
                    anywhere.add(word)
                elif not within[word].isdisjoint(reached):
                    scoped.setdefault(word, set()).update(within[word] & reached)
        words = anywhere | set(scoped)
        starts = {f for f in functions - reached
                  if "*" in words or _named(f, words, classes, scoped)}
        # the free functions a class may run whose construction the parse cannot see
        # (its name among the words: a ``make_shared<Server<T>>`` of a function
        # template, navigation2's ``nav2::ServiceServer``, whose constructor calls
        # ``nav2::setIntrospectionMode``); the class itself stays ``_unbuilt``'s to keep
        starts |= {f for cls in classes - reached if _named_in(cls, words, scoped)
                   for f in edges.get(cls, ()) if f.endswith("()") and f not in reached}
    scoped = {word: owners for word, owners in scoped.items() if word not in anywhere}
    return (reached, words, {made for targets in edges.values() for made in targets} | hosted,
            named, scoped, exported)


def _registered(units: list[tuple[str, CppResult]], entry: str | None
                ) -> list[tuple[str, str]]:
    """The class ``entry`` as ``units`` register it (``CppResult.registered``), by its
    qualified name or, written shorter (a plugin description's ``type`` after a
    using-directive), the end of one: (class, class) for each such class, then every
    (class, base) of the registrations (its bases, transitively). None for a class no
    registration names, nor for a class template's specialisation with arguments
    (mavros' ``PluginFactoryTemplate<X>`` builds ``X``, which the parse does not follow):
    what runs is not known."""
    if entry is None:
        return []
    name = entry.replace(" ", "").lstrip(":")
    if "<" in name:
        if not name.endswith("<>"):
            return []
        name = name.removesuffix("<>")  # nav2's DriveOnHeading<>: its default arguments
    pairs = list(dict.fromkeys(pair for _, unit in units for pair in unit.registered))
    classes = [(cls, base) for cls, base in pairs if cls == base and (
        cls == name or cls.endswith("::" + name) or name.endswith("::" + cls))]
    return [*classes, *(pair for pair in pairs if pair[0] != pair[1])] if classes else []


def _named(function: str, words: Collection[str], classes: Collection[str],
           scoped: dict[str, set[str]] | None = None) -> bool:
    """Whether code that may hide a call (``words``) can call ``function``: its own name
    is one of them, and for a static method (``ns::C::m()``, of a class the executable's
    files define: one it constructs or calls, or whose static methods a unit defines)
    its class's too, as C++ calls one from outside its class (``C::make_shared(...)``):
    ``std::make_shared`` near an error calls no ``ActionExecutorClient::make_shared``
    (plansys2's compute_bt), the word ``load`` of an opaque constructor's class no
    ``LaneletLoader::load`` (scenario_simulator_v2's preprocessor); unless the name is
    written only in code of that class (``scoped``: the owners holding it), which calls
    it bare."""
    own = _simple(function)
    if own not in words:
        return False
    scope = function.removesuffix("()").rpartition("::")[0]
    if scope not in classes or scope.rpartition("::")[2] in words:
        return True
    holders = (scoped or {}).get(own, set())
    return any(h == scope or h.startswith(scope + "::") for h in holders)


def _simple(function: str) -> str:
    """A free function's own name, as code near a parse error writes it: ``f`` of
    ``ns::f()``."""
    return function.removesuffix("()").rsplit("::", 1)[-1]


def _made_under(units: list[tuple[str, CppResult]], owners: dict[str, list[str]],
                rosnames: list[str]) -> dict[str, tuple[Condition, ...]]:
    """The source conditions under which the process makes each of its nodes but the
    first: those every construction of the node's class shares, in any file of the
    executable (ublox_gps_node makes its raw_data_pa node only ``if
    (getRosBoolean(this, "raw_data_stream.enable"))``). Each of the node's calls holds
    them: the node, and all it does, exists only where they hold."""
    found: dict[str, tuple[Condition, ...]] = {}
    for owner, names in owners.items():
        if len(names) != 1 or names[0] not in rosnames[1:]:
            continue
        sites = [made for _, unit in units for cls, made in unit.made_under if cls == owner]
        if not sites:
            continue
        shared = tuple(c for c in sites[0] if all(c in other for other in sites[1:]))
        if shared:
            found[names[0]] = shared
    return found


MAX_CONSTRUCTION_DEPTH = 8


def _node_of(owner: str | None, owners: dict[str, list[str]],
             made_by: dict[str, list[str]], rosnames: list[str],
             known: dict[str, str | None], depth: int) -> str | None:
    """The node an owner's calls are made on: the one name its constructor gives, else
    the one node of every owner that constructs it (bounded, cycles give None)."""
    if owner is None or not rosnames:
        return None
    if owner in known:
        return known[owner]
    known[owner] = None  # while it is being found: a cycle gives None
    named = owners.get(owner)
    found: str | None = None
    if named:
        found = named[0] if len(named) == 1 and named[0] in rosnames else None
    elif depth < MAX_CONSTRUCTION_DEPTH:
        makers = {_node_of(maker, owners, made_by, rosnames, known, depth + 1)
                  for maker in made_by.get(owner, ())}
        found = makers.pop() if len(makers) == 1 else None
    known[owner] = found
    return found


def _units(texts: dict[str, str], ros2: dict[str, bool], setup: IncludeSetup,
           store: cache.Cache | None, jobs: int | None, digests: dict[str, str],
           wanted: Wanted = True, meanwhile: Callable[[], None] | None = None
           ) -> dict[str, CppResult]:
    """Each translation unit's result, from the cache or parsed (in parallel); the
    digest of each in ``digests``. Without ``wanted`` a kept result is not read back
    (only its digest) and is left out; a function ``wanted`` is given every unit's
    digest once they are known and says the units whose kept results to read back (the
    others are left out). ``meanwhile`` is called once: while the workers parse, else
    at the end."""
    keys = {path: cache.key(setup.workspace.relpath(path), text,
                            [*setup.arguments(False, path), f"ros2={ros2[path]}"],
                            setup.generated)
            for path, text in texts.items()}
    done: dict[str, CppResult] = {}
    if store is not None:
        for path, entry in keys.items():
            if wanted is not True:
                kept = store.load(entry, False)
                if kept is not None:
                    digests[path] = kept[1]
                continue
            found = _kept_result(store, entry)
            if found is not None:
                done[path], digests[path] = found
    todo = [path for path in texts if path not in done and path not in digests]
    tasks = [(path, texts[path], ros2[path]) for path in todo]
    workers = min(len(todo), jobs or os.cpu_count() or 1)
    parsed: list[tuple[CppResult, list[str], str, str]]
    if todo:
        setup.materialise()
    for path in todo:  # the PCHs (one per C++ standard), built here, shared by workers
        setup.arguments(source=path)
    if workers > 1:
        # one unit per task, the longest sources first: a worker that is done takes the
        # next, so the workers end within about one unit of each other (in chunks of an
        # eighth of the units, one worker could wait a whole chunk for the other)
        order = sorted(range(len(tasks)), key=lambda index: -len(tasks[index][1]))
        # a unit's cache entry is written as its result comes back, while the workers
        # parse the next ones
        by_task = {}
        with worker_pool(workers, initializer=_start_worker, initargs=(setup,)) as pool:
            results = pool.map(_worker_unit, [tasks[i] for i in order])
            if meanwhile is not None:  # every task is submitted: the workers are busy
                meanwhile()
                meanwhile = None
            for index, outcome in zip(order, results, strict=True):
                raise_if_stopped()  # a stop dropped in a hook of a worker's fork
                by_task[index] = outcome
                _store(store, keys[todo[index]], outcome)
        parsed = [by_task[index] for index in range(len(tasks))]
    else:
        parsed = [_unit_and_data(*task, setup) for task in tasks]
        for path, outcome in zip(todo, parsed, strict=True):
            _store(store, keys[path], outcome)
    for path, (unit, _headers, _data, digest) in zip(todo, parsed, strict=True):
        done[path] = unit
        digests[path] = digest
    if meanwhile is not None:
        meanwhile()
    if callable(wanted) and store is not None:
        for path in wanted(dict(digests)):
            if path in done or path not in keys:
                continue
            found = _kept_result(store, keys[path])
            if found is not None and found[1] == digests[path]:
                done[path] = found[0]
                continue
            # gone since (another run pruned it): parsed again, in this process
            setup.materialise()
            outcome = _unit_and_data(path, texts[path], ros2[path], setup)
            _store(store, keys[path], outcome)
            done[path] = outcome[0]
    return {path: done[path] for path in texts if path in done}


def _kept_result(store: cache.Cache, key: str) -> tuple[CppResult, str] | None:
    """A unit's result the cache keeps under ``key``, read back, and its digest; None
    when there is none, or it does not read back."""
    kept = store.load(key)
    result = _result_from_data(kept[0]) if kept is not None and kept[0] is not None else None
    return None if result is None or kept is None else (result, kept[1])


def _store(store: cache.Cache | None, key: str,
           outcome: tuple[CppResult, list[str], str, str]) -> None:
    """Keep a parsed unit's result in the cache (not one that must not be kept: no
    headers)."""
    _unit, headers, data, digest = outcome
    if store is not None and headers:
        store.store(key, headers, data, digest)


_WORKER_SETUP: IncludeSetup | None = None


def _start_worker(setup: IncludeSetup) -> None:
    global _WORKER_SETUP
    _WORKER_SETUP = setup


def _worker_unit(task: tuple[str, str, bool]
                 ) -> tuple[CppResult, list[str], str, str]:
    assert _WORKER_SETUP is not None
    return _unit_and_data(*task, _WORKER_SETUP)


# the youngest generation's threshold of the cyclic garbage collector while a unit is
# read: its walk makes millions of small objects that live until the unit is done and
# are then freed by their reference counts (``CallFinder.release``); at the default
# (700) the collector walks them over and over, a sixth of the extraction's CPU on four
# navigation2 packages. Still bounded: a collection after this many new objects
YOUNG_THRESHOLD = 1_000_000


def _unit_and_data(path: str, text: str, ros2: bool, setup: IncludeSetup
                   ) -> tuple[CppResult, list[str], str, str]:
    """``_translation_unit`` with the result as the cache keeps it (its JSON text) and its
    digest, made where the unit was parsed (in a worker: not in the serial part of the
    run, which takes a text back at the cost of a string, not of a tree of objects)."""
    try:
        with held_back(YOUNG_THRESHOLD), cpu_limit(UNIT_CPU_SECONDS):
            unit, headers = _translation_unit(path, text, ros2, setup)
    except OverTime as over:
        unit, headers = CppResult(), []  # not kept: a later run tries again
        unit.unseen = ["*"]
        unit.diagnostics.append(diag.make(
            "CPP_TIME_LIMIT", setup.workspace.location(path), detail=str(over)))
    data = _result_data(unit)
    return unit, headers, json.dumps(data), cache.digest(data)


def _result_data(result: CppResult) -> dict[str, Any]:
    """A unit's or a node's result as the cache keeps it (``cache.to_data``)."""
    data = cache.to_data(result.calls, result.rosname, result.diagnostics, result.facts,
                         result.node_names, result.constructions, result.unseen,
                         result.made_under, result.uses, result.defines, result.handed,
                         result.unseen_in, result.passed, result.hidden, result.registered,
                         result.loads_in, result.node_handed)
    if result.rosnames:  # a node's
        data["rosnames"] = list(result.rosnames)
    if result.handles_given:  # a node's
        data["handles_given"] = {k: list(v) for k, v in result.handles_given.items()}
    if result.local_rules:
        data["local_rules"] = [list(pair) for pair in result.local_rules]
    return data


def _result_from_data(data: dict[str, Any]) -> CppResult | None:
    """``_result_data`` read back; None for data that is not such."""
    try:
        (calls, rosname, found, facts, named, made, unseen, under, uses, defines, handed,
         unseen_in, passed, hidden, registered, loads_in, node_handed) = cache.from_data(data)
        rosnames = data.get("rosnames", [])
        if not (isinstance(rosnames, list) and all(isinstance(n, str) for n in rosnames)):
            return None
    except (ValueError, TypeError, KeyError):
        return None
    result = CppResult(calls, rosname, found, facts, rosnames, named, made, uses, defines,
                       under, unseen, handed, unseen_in, passed, hidden, registered, loads_in)
    result.node_handed = node_handed
    given = data.get("handles_given", {})
    if not isinstance(given, dict) or not all(
            isinstance(v, list) and all(isinstance(x, str) for x in v) for v in given.values()):
        return None
    result.handles_given = {str(k): list(v) for k, v in given.items()}
    rules = data.get("local_rules", [])
    if not isinstance(rules, list) or not all(
            isinstance(pair, list) and len(pair) == 2 and all(isinstance(x, str) for x in pair)
            for pair in rules):
        return None
    result.local_rules = [(name, rule) for name, rule in rules]
    return result


# pluginlib's ClassLoader (ROS 1 and 2) and class_loader: a plugin class made by name
_PLUGIN_LOAD = re.compile(
    r"(?:\.|->)\s*(?:template\s+)?(createSharedInstance|createUniqueInstance|"
    r"createUnmanagedInstance|createInstance)\s*(?:<[^;(]*>)?\s*\(")
_PLUGIN_LOADER = re.compile(r"pluginlib|class_loader|ClassLoader")
# BehaviorTree.CPP's factory registering the node classes of a library it opens by name
# (``factory.registerFromPlugin(loader.getOSName("br2_move_bt_node"))``, book_ros2's
# patrolling_main): the trees it then builds make those classes' calls on the node
_TREE_NODES_LOAD = re.compile(r"(?:\.|->)\s*(registerFromPlugin)\s*\(")
_NODELET_LOADER = re.compile(r"nodelet\s*::\s*Loader\b|nodelet/loader\.h")
MAX_PLUGIN_LOADS = 5  # sites said per file


def plugin_loads(path: str, text: str, workspace: Workspace) -> list[Diagnostic]:
    """The lines of ``text`` (the unit's own source) that create plugin instances
    through pluginlib or class_loader, or nodelets through a ``nodelet::Loader``
    (``CPP_PLUGINS_LOADED``): what the node runs there is not in its code
    (``extract.completeness`` keeps them on the node)."""
    # the loader is often a member declared in the class's header: the three names of
    # its own are enough; ``createInstance`` counts only beside a loader's name, a
    # ``load(...)`` only in a file that names nodelet's Loader
    loader = _PLUGIN_LOADER.search(text) is not None
    sites = list(_PLUGIN_LOAD.finditer(text))
    if _NODELET_LOADER.search(text) is not None:
        sites = sorted([*sites, *NODELET_LOAD.finditer(text)], key=lambda m: m.start())
    sites = sorted([*sites, *_TREE_NODES_LOAD.finditer(text)], key=lambda m: m.start())
    return _load_lines("CPP_PLUGINS_LOADED", path, text, workspace,
                       (m for m in sites if m.group(1) != "createInstance" or loader),
                       ("//", "*", "/*"), lambda m: "BehaviorTree.CPP" if (
                           m.group(1) == "registerFromPlugin") else "pluginlib")


def _load_lines(code: str, path: str, text: str, workspace: Workspace,
                sites: Iterable[re.Match[str]], comments: tuple[str, ...],
                loader: Callable[[re.Match[str]], str] | None = None) -> list[Diagnostic]:
    """A ``code`` diagnostic at each of ``sites`` (group 1: the loader's name) whose line
    of ``text`` is no comment (``comments``: how one starts), with the line's text (and
    the library that loads there, ``loader``); at most ``MAX_PLUGIN_LOADS``."""
    found: list[Diagnostic] = []
    for match in sites:
        start = text.rfind("\n", 0, match.start()) + 1
        end = text.find("\n", match.end())
        line = text[start:end if end != -1 else len(text)]
        if line.lstrip().startswith(comments):
            continue
        number = text.count("\n", 0, match.start()) + 1
        fields = {"loader": loader(match)} if loader is not None else {}
        found.append(diag.make(code, workspace.location(path, number,
                                                        match.start(1) - start + 1),
                               text=line.strip()[:120], **fields))
        if len(found) == MAX_PLUGIN_LOADS:
            break
    return found


# POSIX's and Windows' loaders of a shared library by name
_LIBRARY_LOAD = re.compile(
    r"(?<![\w.>:])(?:::\s*)?(dlopen|LoadLibrary[AW]?|LoadLibraryEx[AW]?)\s*\(")


def library_loads(path: str, text: str, workspace: Workspace,
                  tu: TranslationUnit | None = None) -> list[Diagnostic]:
    """The lines of ``text`` (the unit's own source) that open a shared library by name
    (``CPP_LIBRARY_LOADED``, a cause of partial): MOLA's launcher dlopen()s the modules
    its configuration lists; what they do on the node is not in its code. With the
    unit's parse ``tu``, not a load of a library the code names by a string literal
    (itself or through a macro) that no package of the workspace builds
    (``_vendor_library``): a vendor's library, like any the node links; nor one in code
    the preprocessor leaves out of this build (vectornav's dllvalidator.cpp, whose
    ``LoadLibraryEx`` is all under ``#if defined WIN32 && defined DLL_VALIDATOR``)."""
    sites: Iterable[re.Match[str]] = _LIBRARY_LOAD.finditer(text)
    if tu is not None:
        skipped = recall.skipped_lines(tu).get(os.path.abspath(path), [])
        sites = (m for m in sites if not any(
            start <= text.count("\n", 0, m.start()) + 1 <= end for start, end in skipped)
            and not _vendor_library(path, text, m, tu, workspace))
    return _load_lines("CPP_LIBRARY_LOADED", path, text, workspace, sites,
                       ("//", "*", "/*", "#"))


# a load's first argument (or one a call passes for its name): a string literal with no
# escape, a macro's name; then the argument's end
_LITERAL_ARGUMENT = re.compile(r'\s*"([^"\\\n]+)"\s*([,)])')
_MACRO_ARGUMENT = re.compile(r"\s*([A-Za-z_]\w*)\s*([,)])")
MAX_PASSED_DEPTH = 4  # functions that pass a library's name on, read back
_LIBRARY_FILE = re.compile(r"^(?:.*/)?(?:lib)?([\w.+-]+?)(?:\.so(?:\.[\d.]*)?|\.dll|\.dylib)?$")


def _vendor_library(path: str, text: str, site: re.Match[str], tu: TranslationUnit,
                    workspace: Workspace) -> bool:
    """Whether the load at ``site`` opens a library the code names by a string literal
    (kinova_driver's ``dlopen(KINOVA_USB_LIBRARY, ...)``, a macro of
    ``"Kinova.API.USBCommandLayerUbuntu.so"``) whose name no ``add_library`` of the
    workspace's CMake files makes (a vendor's library, not ROS code of the workspace).
    Read off the text and the parse's macro definitions: the call itself may not be
    in the parse (``dlfcn.h`` is no stand-in). A name that is a parameter of the
    function the load is in is each literal the unit's calls of that function pass
    (kinova_driver's later ``loadLibraries(const char *command_lib, ...)``, called with
    ``KINOVA_USB_LIBRARY`` or ``KINOVA_ETH_LIBRARY``), when there are calls and every
    one passes a literal, and no other source of the package names the function
    followed by ``(`` (a call the unit does not see may pass any name)."""
    names = _loaded_names(path, text, site.end(), tu, _called_elsewhere(path, workspace))
    return bool(names) and all(_not_built(name, workspace) for name in names)


def _called_elsewhere(path: str, workspace: Workspace) -> Callable[[str], bool]:
    """Whether a C or C++ source of the package ``path`` is in, other than ``path``, names
    a function followed by ``(``."""
    roots = [p.root for p in workspace.packages.values()
             if path.startswith(os.path.join(p.root, ""))]
    texts: list[str] = []

    def named(name: str) -> bool:
        if not texts and roots:
            root = max(roots, key=len)
            for folder, _dirs, files in os.walk(root):
                for file in files:
                    full = os.path.join(folder, file)
                    if full != path and file.endswith((".c", ".cc", ".cpp", ".cxx")):
                        texts.append(read_text(full, workspace.location(full))[0] or "")
        called = re.compile(r"\b" + re.escape(name) + r"\s*\(")
        return any(called.search(text) for text in texts)
    return named


def _loaded_names(path: str, text: str, offset: int, tu: TranslationUnit,
                  elsewhere: Callable[[str], bool], ends: str = ",",
                  depth: int = 0) -> list[str]:
    """The literal names the argument written at ``offset`` of ``text`` stands for (see
    ``_vendor_library``), followed by one of ``ends``; none when one of them is not a
    literal."""
    literal = _LITERAL_ARGUMENT.match(text, offset)
    if literal is not None and literal.group(2) in ends:
        return [literal.group(1)]
    macro = _MACRO_ARGUMENT.match(text, offset)
    if macro is None or macro.group(2) not in ends:
        return []
    cursor = _cursor_at(tu, path, text, macro.start(1))
    if cursor is None:
        return []
    if cursor.kind == CursorKind.MACRO_INSTANTIATION:
        written = _macro_literal(cursor, macro.group(1))
        return [written] if written is not None else []
    # a parameter of the function the load is in: read off the function, as the parse
    # may have dropped the statement (no declaration of ``dlopen``: kinova_api.cpp)
    parm = cursor.referenced if cursor.kind == CursorKind.DECL_REF_EXPR else (
        _parameter_named(tu, path, text.count("\n", 0, offset) + 1, macro.group(1)))
    if parm is None or parm.kind != CursorKind.PARM_DECL or (
            parm.spelling != macro.group(1) or depth >= MAX_PASSED_DEPTH):
        return []
    return _passed_literals(path, text, parm, tu, elsewhere, depth + 1)


def _parameter_named(tu: TranslationUnit, path: str, line: int, name: str) -> Cursor | None:
    """The parameter ``name`` of the function defined in the unit's source ``path`` whose
    body holds ``line``."""
    stack = list(tu.cursor.get_children())
    while stack:
        node = stack.pop()
        extent = node.extent
        where = extent.start.file
        if where is None or os.path.abspath(where.name) != path or not (
                extent.start.line <= line <= extent.end.line):
            continue
        if node.kind in (CursorKind.NAMESPACE, CursorKind.CLASS_DECL,
                         CursorKind.STRUCT_DECL):
            stack.extend(node.get_children())
        elif node.is_definition():
            return next((c for c in node.get_children()
                         if c.kind == CursorKind.PARM_DECL and c.spelling == name), None)
    return None


def _cursor_at(tu: TranslationUnit, path: str, text: str, start: int) -> Cursor | None:
    """The parse's cursor at offset ``start`` of ``text`` (the unit's source ``path``)."""
    line = text.count("\n", 0, start) + 1
    column = len(text[text.rfind("\n", 0, start) + 1:start].encode("utf-8")) + 1
    try:
        return Cursor.from_location(tu, tu.get_location(path, (line, column)))
    except (ValueError, TypeError, AttributeError):
        return None


def _macro_literal(cursor: Cursor, name: str) -> str | None:
    """The string literal the macro ``name`` instantiated at ``cursor`` is defined as."""
    try:
        defined = cursor.referenced
        tokens = [t.spelling for t in defined.get_tokens()] if defined is not None else []
    except (ValueError, TypeError, AttributeError):
        return None
    if len(tokens) != 2 or tokens[0] != name:
        return None
    quoted = _LITERAL_ARGUMENT.fullmatch(tokens[1] + ",")
    return quoted.group(1) if quoted is not None else None


def _passed_literals(path: str, text: str, parm: Cursor, tu: TranslationUnit,
                     elsewhere: Callable[[str], bool], depth: int) -> list[str]:
    """The literals (written, or macros of one) the calls in the unit's own source pass
    for ``parm``; none when there is no call, one passes anything else, or another
    source may call the function (``elsewhere``)."""
    function = parm.semantic_parent
    if function is None or elsewhere(function.spelling):
        return []
    params = [c for c in function.get_children() if c.kind == CursorKind.PARM_DECL]
    index = next((i for i, p in enumerate(params) if p == parm), None)
    target = function.canonical
    if index is None or target is None:
        return []
    found: list[str] = []
    for top in tu.cursor.get_children():
        where = top.location.file
        if where is None or os.path.abspath(where.name) != path:
            continue
        for node in top.walk_preorder():
            called = node.referenced if node.kind == CursorKind.CALL_EXPR else None
            if called is None or called.canonical != target:
                continue
            args = list(node.get_arguments())
            if index >= len(args):
                return []
            at = args[index].extent.start
            if at.file is None or os.path.abspath(at.file.name) != path:
                return []
            names = _loaded_names(path, text, _offset(text, at.line, at.column), tu,
                                  elsewhere, ",)", depth)
            if not names:
                return []
            found.extend(names)
    return found


def _offset(text: str, line: int, column: int) -> int:
    """The offset in ``text`` of a 1-based line and byte column."""
    start = 0
    for _ in range(line - 1):
        start = text.index("\n", start) + 1
    return start + len(text[start:].encode("utf-8")[:column - 1].decode("utf-8", "replace"))


def _not_built(written: str, workspace: Workspace) -> bool:
    """Whether no ``add_library`` of the workspace's CMake files makes the library whose
    file name is ``written``."""
    named = _LIBRARY_FILE.match(written)
    if named is None:
        return False
    made = re.compile(r"\badd_library\s*\(\s*(?:lib)?" + re.escape(named.group(1)) + r"\b")
    for package in workspace.packages.values():
        cmake = os.path.join(package.root, "CMakeLists.txt")
        if os.path.isfile(cmake) and made.search(
                read_text(cmake, workspace.location(cmake))[0] or ""):
            return False
    return True


def _translation_unit(path: str, text: str, ros2: bool,
                      setup: IncludeSetup) -> tuple[CppResult, list[str]]:
    """What one source file gives, and the workspace / synthesised headers it read
    (empty when the result must not be cached)."""
    workspace = setup.workspace
    before = len(setup.diagnostics)
    setup.unit_missing = []
    values.forget_globals()
    data = text.encode("utf-8")

    known: dict[str, bool] = {}  # clang names the same few files for every error

    def owned(name: str) -> bool:
        found = known.get(name)
        if found is None:
            full = os.path.abspath(name)
            found = known[name] = full == path or (
                workspace.holds(full) and not full.startswith(
                    (setup.generated + os.sep, STANDIN + os.sep)))
        return found

    package = workspace.package_of(path)
    home = package.root + os.sep if package is not None and package.root else None

    def local(name: str) -> bool:  # a file of the unit's own package (``reach``)
        return home is None or os.path.abspath(name).startswith(home)

    def where(cursor: Cursor) -> Location:
        loc = cursor.location
        if loc.file is None:
            return workspace.location(path)
        return workspace.location(os.path.abspath(loc.file.name), loc.line, loc.column)

    # the unit's own wrappers of the API, once a walk found them: a second parse declares
    # the names of the errors in functions that call them (``_again_for``)
    wrappers: tuple[frozenset[str], frozenset[str]] | None = None
    read: list[str] = []  # the workspace files the ROS 1 client test reads
    clients = None if ros2 else ros1_clients(path, workspace, setup.generated, read)
    while True:
        result = CppResult()
        source = SourceCache(workspace.holds, {path: data})
        tu = _parse(path, text, setup, workspace, result, source, owned, ros2, wrappers,
                    clients)
        if tu is None:
            result.unseen = ["*"]
            return result, []
        errors = [e for e in _errors(tu) if e.name is not None and owned(e.name)]
        fieldless = _header_facts(setup).fieldless(setup)
        for error in errors[:MAX_ERRORS_PER_FILE]:
            assert error.path is not None
            code = ("CPP_MESSAGE_FIELD" if _message_field(error, fieldless, source)
                    else "CPP_PARSE_ERROR")
            result.diagnostics.append(diag.make(
                code, workspace.location(error.path, error.line, error.column),
                detail=error_detail(error.spelling, setup.generated)))
        # the header of the names declared permissively, when this parse has them
        declared = os.path.join(setup.generated, synthesis.HEADER_NAME) if any(
            d.code == "CPP_NAMES_DECLARED" for d in result.diagnostics) else None
        # the headers the unit includes that are empty stand-ins: a class declared
        # permissively may be of the package one of them names (``CallFinder._unseen_of``)
        absent = _missing_headers(tu, setup)
        finder = CallFinder(tu, source, owned, where, ros2=ros2, declared=declared,
                            clients=clients, local=local,
                            ros_class=ros_classes(path, workspace, read, absent),
                            missing_headers=[] if clients is None else absent)
        finder.run()
        places = _Places(finder, source)
        # (said above; what hides nothing is left out of what may hide a call)
        errors = [e for e in errors if not places.logged(e)]
        hidden = _hidden(path, errors, places, fieldless, workspace)
        if wrappers is None:
            wrappers = _again_for(tu, errors, finder, hidden, source, fieldless)
            if wrappers is not None:
                finder.release()
                continue
        break
    # a nodelet load the walk found run under the node's own name, and a plugin class
    # created by a name written in the code, are said so instead
    own = {(d.location.file, d.location.line) for d in finder.diagnostics
           if d.code in ("CPP_NODELET_IN_PROCESS", "CPP_PLUGIN_IN_PROCESS")}
    loads = [d for d in plugin_loads(path, text, workspace)
             if (d.location.file, d.location.line) not in own]
    result.diagnostics.extend(loads)
    result.loads_in = sorted({owner_of(function) if (function := places.innermost(
        os.path.abspath(path), d.location.line)) is not None else "" for d in loads} | (
        finder.loads_in))
    result.diagnostics.extend(library_loads(path, text, workspace, tu))
    result.calls = sorted(finder.calls, key=lambda c: (
        c.location.file or "", c.location.line, c.location.column))
    result.diagnostics.extend(finder.diagnostics)
    result.diagnostics.extend(hidden)
    library = versions.RCLCPP if ros2 else versions.ROSCPP
    if library.version(setup.distro) is None and not setup.system_headers:
        again = functools.partial(_other_version, path, text, setup, owned, ros2, wrappers,
                                  clients, where, local)
        result.diagnostics.extend(_version_unknown(tu, source, owned, workspace, library,
                                                   setup.distro, result, again))
    result.diagnostics.extend(_target_unknown(tu, source, owned, workspace))
    # what the parses added: the headers the unit includes that a parse stood in for,
    # this unit's or an earlier one's (``stood_in``), not only those it repaired itself
    result.diagnostics[:0] = [*setup.unit_missing, *(
        d for d in setup.diagnostics[before:] if d.code != "CPP_INCLUDE_MISSING")]
    result.rosname = finder.rosname if finder.rosname is not None or (
        not finder.rosname_unbuilt) else links.UNBUILT_NAMES.join(finder.rosname_unbuilt)
    result.facts = finder.facts
    result.node_names = finder.node_names
    result.local_rules = finder.local_rules
    result.constructions = finder.constructions
    result.node_handed = finder.node_handed
    result.uses = finder.uses
    result.defines = finder.defines
    result.registered = finder.registered
    result.made_under = finder.made_under
    # the node handed to code the parse does not read (another package's class, a
    # function it does not know) may construct anything there
    held: dict[bytes, set[str]] = {}
    around = _unseen(errors, places, held)
    # a word of a declaration of a class built here without its constructor's code
    # names what C++ finds from that class (``Implementation``, a pimpl class's own:
    # not open-rmf's Negotiation::Implementation), unless code outside any function
    # around an error holds it too
    for word, classes in finder.unseen_in.items():
        if word not in around or word in held:
            held.setdefault(word, set()).update(classes)
    words = around | finder.unseen
    result.unseen = ["*"] if any(d.code in _HANDED for d in result.diagnostics) else sorted(
        word.decode() for word in words)
    # also where the node is handed on (``*``): the words of the code that hands it,
    # which may construct what it names there (``_reached``)
    result.unseen_in = sorted((word.decode(), owner) for word, owners in held.items()
                              for owner in owners)
    if result.unseen == ["*"]:
        result.handed = sorted(finder.handed) if finder.handed else [""]
        result.passed = sorted(finder.passed)
        # what the ``*`` comes down to: those words, and the names the node is handed to
        # (the workspace's own code whose declaration the parse lost may be one), each
        # where the code that hands it on runs
        told = {word.decode() for word in words}
        result.hidden = ["*"] if "*" in told or any(
            d.code == "CPP_NODE_UNREAD" for d in result.diagnostics) else sorted(
            told | {name for _, name in finder.handed_to})
        result.unseen_in = sorted({*result.unseen_in, *(
            (name, owner) for owner, name in finder.handed_to if name not in told)})
    if (result.unseen or finder.opaque_words) and result.unseen != ["*"]:
        result.facts = [*result.facts, *call_conditions.hidden_facts(
            finder.unit_cursor(), finder.owned, _error_words(errors, places))]
    finder.release()
    # and the sources of the packages read for a global's writes (``unwritten_global``)
    headers = [path, *read, *(f for root in sorted(values.CONSULTED)
                              for f in values.package_sources(root))]
    for include in tu.get_includes():
        name = os.path.abspath(include.include.name)
        if workspace.holds(name) or name.startswith(setup.generated + os.sep) or (
            setup.system_headers and not name.startswith(STANDIN + os.sep)
        ):
            headers.append(name)
    return result, sorted(set(headers))


_MAY_HIDE = frozenset({"CPP_CALL_MISSED", "CPP_ERROR_NEAR_CALL"})


def _again_for(tu: TranslationUnit, errors: list[_Error], finder: CallFinder,
               hidden: list[Diagnostic], source: SourceCache, fieldless: set[str]
               ) -> tuple[frozenset[str], frozenset[str]] | None:
    """The unit's wrappers (names, and those called with no argument), when the unit is
    to be parsed again with them: an error left can hide a call (``hidden``) and sits in
    a function that calls only the unit's own wrappers, so the synthesis, which knows
    the API's call sites only, left its names undeclared (navigation2's vector object
    server: ``uuid_parse`` of the missing <uuid/uuid.h> beside ``declare_or_get_parameter``
    of nav2_ros_common). None otherwise."""
    names = frozenset(n for n in finder.wrappers.site_names if n)
    if not names or not errors or not any(d.code in _MAY_HIDE for d in hidden):
        return None
    wrappers = (names, finder.wrappers.site_names_bare)
    functions: dict[str, list[recall.Function]] = {}
    plain = _hiding(tu, errors, source, fieldless, functions, _Sites())
    more = _hiding(tu, errors, source, fieldless, functions, _Sites(wrappers))
    return wrappers if len(more) > len(plain) else None


def _target_unknown(tu: TranslationUnit, source: SourceCache,
                    owned: Callable[[str], bool], workspace: Workspace) -> list[Diagnostic]:
    """``CPP_TARGET_UNKNOWN`` at the first ROS call of each branch of a condition on
    the processor that the parse left out, in the unit's workspace files (``targets``)."""
    found: list[Diagnostic] = []
    for name, skipped in sorted(recall.skipped_lines(tu).items()):
        text = source.text(name) if owned(name) else None
        if not text:
            continue
        for line, call, condition in targets.unknown_target_calls(text, skipped):
            found.append(diag.make("CPP_TARGET_UNKNOWN", workspace.location(name, line),
                                   text=call.strip()[:80], condition=condition))
    return found


def _version_unknown(tu: TranslationUnit, source: SourceCache,
                     owned: Callable[[str], bool], workspace: Workspace,
                     library: versions.Library, distro: str | None,
                     result: CppResult | None = None,
                     again: Callable[
                         [tuple[int, int, int], dict[str, list[versions.Branch]]],
                         tuple[list[PrimitiveCall], dict[str, list[versions.Branch]]] | None]
                     | None = None
                     ) -> list[Diagnostic]:
    """With no distribution of ``library`` known (the stand-ins' default version chose
    the branches of a condition on it: ``versions``), the calls of ``result`` in a
    branch of such a condition made under the branch's condition; the unit parsed
    ``again`` with another version (``Library.others``) while a branch the parse left out
    holds a ROS call (or is of a chain another branch of which makes one), and the
    calls of those branches that parse read added under theirs; a call every branch of
    a chain makes, once and under no condition of the version (``_made_by_each_branch``);
    ``CPP_VERSION_UNKNOWN`` at the first ROS call of each branch left out that no parse
    read, in the unit's workspace files."""
    skipped = recall.skipped_lines(tu)
    names = {os.path.abspath(path) for path in skipped}
    if result is not None:  # the files of the calls, for a branch the parse read
        names |= {os.path.abspath(os.path.join(workspace.root, c.location.file))
                  for c in result.calls if c.location.file}
    held: dict[str, list[versions.Branch]] = {}  # per file, its branches
    left: dict[str, list[tuple[versions.Branch, recall.Site | None]]] = {}  # left out
    first = list(result.calls) if result is not None else []
    for name in sorted(names):
        text = source.text(name) if owned(name) else None
        if not text or not versions.blocks_naming(text, versions.name_pattern(library)):
            continue
        held[name] = versions.branches(text, library)
        relative = workspace.relpath(name)
        # the chains with a call in a branch the parse read: the others may make it too
        making = {b.chain for b in held[name] if any(
            c.location.file == relative and b.holds(c.location.line) for c in first)}
        sites = None
        for branch in held[name]:
            if not versions.skipped_for(branch, skipped.get(name, [])):
                continue
            sites = recall.call_sites(text) if sites is None else sites
            site = recall.first_site(sites, branch.first, branch.last)
            if site is not None or branch.chain in making:
                left.setdefault(name, []).append((branch, site))
    read_all = {(name, b) for name, branches in held.items() for b in branches
                if not versions.skipped_for(b, skipped.get(name, []))}
    more: list[PrimitiveCall] = []  # the calls the other parses read
    if result is not None and again is not None:
        others = library.others(text for found in left.values() for b, _site in found
                                for text in (b.text, *b.before))
        for _parse_again in range(versions.MAX_OTHER_PARSES):
            # the newest version that may take a branch left out
            other = next((v for v in others if any(
                b.taken(library, v) is not False
                for found in left.values() for b, _site in found)), None)
            if other is None:
                break
            others.remove(other)
            wanted = {name: [branch for branch, _site in found]
                      for name, found in left.items()}
            parsed = again(other, wanted)
            if parsed is None:
                continue
            calls, read = parsed
            more.extend(calls)
            read_all |= {(name, b) for name, branches in read.items() for b in branches}
            for name in list(left):
                left[name] = [(b, s) for b, s in left[name] if b not in read.get(name, ())]
                if not left[name]:
                    del left[name]
    if result is not None and held:
        free, dropped = _made_by_each_branch(first, more, held, read_all, workspace)
        result.calls = sorted(
            (_under_branches(call, held, workspace, free.get(id(call), frozenset()))
             for call in [*first, *(c for c in more if id(c) not in dropped)]),
            key=lambda c: (c.location.file or "", c.location.line, c.location.column))
    found: list[Diagnostic] = []
    for name, branches in sorted(left.items()):
        for branch, site in branches:
            if site is None:  # (no ROS call of its own: only what the others make)
                continue
            found.append(diag.make(
                "CPP_VERSION_UNKNOWN", workspace.location(name, site.line),
                text=site.text.strip()[:80], condition=branch.text, library=library.name,
                version=library.describe(distro)))
    return found


def _same_call(call: PrimitiveCall) -> tuple[object, ...]:
    """What makes two calls of two branches the same call of the node, wherever they
    are written."""
    return (call.kind, call.name, call.type, call.name_param, call.node_name)


def _made_by_each_branch(first: list[PrimitiveCall], more: list[PrimitiveCall],
                         held: dict[str, list[versions.Branch]],
                         read: set[tuple[str, versions.Branch]], workspace: Workspace
                         ) -> tuple[dict[int, frozenset[frozenset[int]]], set[int]]:
    """The calls every branch of a version chain with an ``#else`` makes, each branch
    read (navigation2's tf2_factories.hpp makes the TransformBroadcaster with ``*node``
    from Rolling on, with ``node`` before): no condition of the version, one call. By
    ``id``: the chains (their directive lines) each call of ``first`` (the parse's own)
    is made in whatever the version, and the calls of ``more`` (the other parses') that
    say the same again."""
    free: dict[int, frozenset[frozenset[int]]] = {}
    dropped: set[int] = set()
    for name, branches in held.items():
        relative = workspace.relpath(name)
        chains: dict[frozenset[int], list[versions.Branch]] = {}
        for branch in branches:
            chains.setdefault(branch.chain, []).append(branch)
        for chain, members in chains.items():
            members.sort(key=lambda b: b.first)
            if members[-1].statement != "#else" or not all(
                    (name, b) in read for b in members):
                continue
            made = [[c for c in [*first, *more] if c.location.file == relative
                     and b.holds(c.location.line)] for b in members]
            common = set.intersection(*({_same_call(c) for c in calls} for calls in made))
            owned = {id(c) for c in first}
            for calls in made:
                for call in calls:
                    if _same_call(call) not in common:
                        continue
                    if id(call) in owned:
                        free[id(call)] = free.get(id(call), frozenset()) | {chain}
                    else:
                        dropped.add(id(call))
    return free, dropped


def _under_branches(call: PrimitiveCall, held: dict[str, list[versions.Branch]],
                    workspace: Workspace, free: frozenset[frozenset[int]] = frozenset()
                    ) -> PrimitiveCall:
    """``call`` made under the condition of each version branch of ``held`` (per file)
    it is in, outermost first, but those of the chains ``free`` (``_made_by_each_branch``)."""
    for name, branches in held.items():
        if workspace.relpath(name) != call.location.file:
            continue
        around = [b for b in branches if b.holds(call.location.line) and b.chain not in free]
        if around:
            around.sort(key=lambda b: b.first)
            made = tuple(b.condition(workspace.location(name, b.first)) for b in around)
            return dataclasses.replace(call, conditions=(*made, *call.conditions))
    return call


# the calls a parse with another version of the client library read in a branch of a workspace
# header, per (file, its text's digest, the branch's lines, the version, ROS 2),
# None when that parse did not read it whole: the units that include the header read
# it alike (navigation2's node_utils.hpp, in nearly every unit of its 40 nodes), so one
# parse serves them all (``_other_version``)
_OTHER_READ: dict[tuple[str, str, int, int, str, bool], tuple[PrimitiveCall, ...] | None] = {}
MAX_OTHER_READ = 4096


def _other_version(path: str, text: str, setup: IncludeSetup, owned: Callable[[str], bool],
                   ros2: bool, wrappers: tuple[frozenset[str], frozenset[str]] | None,
                   clients: Callable[..., str | None] | None,
                   where: Callable[[Cursor], Location], local: Callable[[str], bool],
                   version: tuple[int, int, int], wanted: dict[str, list[versions.Branch]]
                   ) -> tuple[list[PrimitiveCall], dict[str, list[versions.Branch]]] | None:
    """The unit parsed again with its client library announcing ``version``
    (``versions``): the calls it extracts in the branches of ``wanted`` (per file) it
    reads, and those branches, each read whole (not skipped, and no error of that parse
    in it); None when it cannot be parsed. A branch of a header that an earlier unit's
    parse with ``version`` read (or not) is taken from it (``_OTHER_READ``): no parse
    when that is all."""
    workspace = setup.workspace
    source = SourceCache(workspace.holds, {path: text.encode("utf-8")})
    calls: list[PrimitiveCall] = []
    read: dict[str, list[versions.Branch]] = {}
    keys: dict[tuple[str, versions.Branch], tuple[str, str, int, int, str, bool]] = {}
    release = ".".join(map(str, version))  # the version, in the keys
    todo: dict[str, list[versions.Branch]] = {}
    for name, branches in wanted.items():
        data = source.get(name) if name != path else None
        digest = hashlib.sha256(data).hexdigest() if data is not None else None
        for branch in branches:
            if digest is None:
                todo.setdefault(name, []).append(branch)
                continue
            key = keys[name, branch] = (name, digest, branch.first, branch.last, release,
                                         ros2)
            if key not in _OTHER_READ and setup.other_folder is not None:
                found_before = cache.load_other(setup.other_folder, cache.other_key(*key),
                                                setup.generated)
                if found_before is not None:  # an earlier run's parse read it
                    _OTHER_READ[key] = found_before[0]
            if key not in _OTHER_READ:
                todo.setdefault(name, []).append(branch)
            elif (kept := _OTHER_READ[key]) is not None:
                calls.extend(kept)
                read.setdefault(name, []).append(branch)
    if not todo:
        return calls, read
    with setup.announcing(versions.RCLCPP if ros2 else versions.ROSCPP, version):
        tu = _parse(path, text, setup, workspace, CppResult(), source, owned, ros2,
                    wrappers, clients)
        if tu is None:
            return None
        skipped = recall.skipped_lines(tu)
        wrong: dict[str, list[int]] = {}
        for error in _errors(tu):
            if error.path is not None:
                wrong.setdefault(os.path.abspath(error.path), []).append(error.line)
        whole = {name: [b for b in branches
                        if not versions.skipped_for(b, skipped.get(name, []))
                        and not any(b.first < line < b.last for line in wrong.get(name, ()))]
                 for name, branches in todo.items()}
        found: list[PrimitiveCall] = []
        if any(whole.values()):
            finder = CallFinder(tu, source, owned, where, ros2=ros2, local=local,
                                clients=clients)
            finder.run()
            found = finder.calls
            finder.release()
        # the headers that parse read, which an earlier run's branch must find unchanged
        # (not the unit's own source: the branch is any unit's that includes the header)
        headers = [header for header in _unit_headers(tu) if header != os.path.abspath(path)
                   and (workspace.holds(header)
                        or header.startswith(setup.generated + os.sep))]
    if len(_OTHER_READ) > MAX_OTHER_READ:
        _OTHER_READ.clear()
    for name, branches in todo.items():
        relative = workspace.relpath(name)
        for branch in branches:
            made = tuple(c for c in found if c.location.file == relative
                         and branch.holds(c.location.line))
            taken = branch in whole[name]
            if taken:
                calls.extend(made)
                read.setdefault(name, []).append(branch)
            if (name, branch) in keys:
                _OTHER_READ[keys[name, branch]] = made if taken else None
                if setup.other_folder is not None:
                    cache.store_other(setup.other_folder, cache.other_key(*keys[name, branch]),
                                      headers, setup.generated, made if taken else None)
    return calls, read


def _hidden(path: str, errors: list[_Error], places: _Places, fieldless: set[str],
            workspace: Workspace) -> list[Diagnostic]:
    """Where the errors left can hide a ROS call (``recall``): the API call sites of the
    unit's source and of the workspace headers with errors that have no call extracted
    near them (nor a call of the same name the parse resolved to another function), and
    the errors inside a function that holds such a site. None in a unit without
    errors: there the parse read every call, and the walk judged each."""
    finder, source = places.finder, places.source
    near: dict[str, list[recall.Site]] = {}
    std = _declared_in(finder.tu)
    errors = [e for e in errors if not (_message_field(e, fieldless, source)
                                        or _std_by_adl(e, source, std)
                                        or _DECLARATION_ONLY.match(e.spelling)
                                        or _PERMISSIVE_CAST.match(e.spelling))
              or _in_ros_call(e, source, near)]
    errors = [e for e in errors if not _of_kept_call(e, finder.kept_unresolved)]
    wrappers = sorted(n for n in finder.wrappers.site_names if n)
    bare = finder.wrappers.site_names_bare
    errors = [e for e in errors if not _of_quiet_overloads(e, places, wrappers, bare)]
    if not errors:
        return []
    files = dict.fromkeys([path, *(e.path for e in errors if e.path is not None)])
    functions: dict[str, list[recall.Function]] = {}
    silent: dict[str, list[tuple[int, int]]] = {}
    for function in finder.functions:
        start, end = function.extent.start, function.extent.end
        if start.file is None:
            continue
        name = os.path.abspath(start.file.name)
        functions.setdefault(name, []).append((start.line, end.line, function.spelling,
                                               function.kind == CursorKind.FUNCTION_DECL))
        if function.kind != CursorKind.FIELD_DECL and finder.wrappers.silent(function):
            silent.setdefault(name, []).append((start.line, end.line))
    # (and code that does not run in this unit: ``reach``)
    for function in [*finder.wrappers.silent_lambdas(), *finder.unreached]:
        start, end = function.extent.start, function.extent.end
        if start.file is not None:
            silent.setdefault(os.path.abspath(start.file.name), []).append(
                (start.line, end.line))
    lines: dict[str | None, set[int]] = {}
    for call in finder.calls:
        lines.setdefault(call.location.file, set()).add(call.location.line)
    for name, line in finder.resolved:
        lines.setdefault(workspace.relpath(name), set()).add(line)
    for name, ranges in recall.skipped_lines(finder.tu).items():
        silent.setdefault(name, []).extend(ranges)  # no code of this build
    found: list[Diagnostic] = []
    for name in files:
        sites = places.sites(name)
        if not sites:
            continue
        relative = workspace.relpath(name)
        for site in recall.missed(sites, lines.get(relative, set()), silent.get(name, ())):
            found.append(diag.make("CPP_CALL_MISSED", workspace.location(name, site.line),
                                   text=site.text))
        for error in errors:
            if error.path != name:
                continue
            around = recall.holding(error.line, functions.get(name, ()), sites)
            if around is not None:
                found.append(diag.make(
                    "CPP_ERROR_NEAR_CALL", workspace.location(name, error.line, error.column),
                    function=around[2], start=around[0], end=around[1],
                    detail=error.spelling))
    found.extend(_node_given(errors, places, workspace))
    return found[:recall.MAX_REASONS]


# what clang says of a call no overload takes or several take equally
_CALL_ERROR = re.compile(r"call to (?:member function |function )?'([^']+)'")


def _of_kept_call(error: _Error, kept: set[tuple[str, int, str]]) -> bool:
    """Whether ``error`` is clang's about a call the walk kept by its name all the same
    (cob_linear_nav's ``private_nh.setParam("global_frame", req.data)``, ``data`` of a
    service whose package is not in the workspace: "call to member function 'setParam'
    is ambiguous"): that call is in the model, so the error hides none."""
    found = _CALL_ERROR.search(error.spelling)
    return found is not None and error.name is not None and (
        error.name, error.line, found.group(1)) in kept


def _of_quiet_overloads(error: _Error, places: _Places, wrappers: list[str],
                        bare: Iterable[str]) -> bool:
    """Whether ``error`` is clang's "call to 'f' is ambiguous" of a function ``f`` whose
    every overload is a function of the unit's own files that makes no ROS call, on a
    line that holds none either: riptide_imu's ``toMsg(cd.quaternion())``, where its
    two overloads take ``vn::math::vec4f`` and ``vec3f`` of a library not here, both
    built from anything by the parse; whichever runs, it only fills a message, so the
    error, in the callback that publishes it, hides no ROS call. Or "call to constructor
    of 'C' is ambiguous" of a class of the unit's own files whose constructors make no
    ROS call, nor its members' initialisers, and that has no base (HEBI's
    ``TeachRepeatNode teach_repeat_node(*arm)``, the vendor's arm a permissive value that
    converts to the constructor's ``Arm&`` and to the class's own copy alike)."""
    if "is ambiguous" not in error.spelling or error.path is None:
        return False
    finder, source = places.finder, places.source
    built = _CONSTRUCTOR_ERROR.search(error.spelling)
    if built is not None:
        overloads = [f for f in [*finder.functions, *finder.unreached]
                     if f.kind == CursorKind.CONSTRUCTOR
                     and f.semantic_parent is not None
                     and f.semantic_parent.type.spelling == built.group(1)]
        if not overloads:
            return False
        owner = overloads[0].semantic_parent
        members = [c for c in owner.get_children() if c.kind == CursorKind.FIELD_DECL]
        if any(c.kind == CursorKind.CXX_BASE_SPECIFIER for c in owner.get_children()) or (
                _sites_in(members, source, wrappers, bare, finder.ros2)):
            return False
    else:
        called = _CALL_ERROR.search(error.spelling)
        if called is None:
            return False
        name = called.group(1).rsplit("::", 1)[-1]
        if name in _api_names() or name in wrappers:
            return False
        overloads = [f for f in finder.functions if f.spelling == name
                     and f.kind in (CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD,
                                    CursorKind.FUNCTION_TEMPLATE)]
        if not overloads:
            return False
    if any(not function.is_definition() for function in overloads) or _sites_in(
            overloads, source, wrappers, bare, finder.ros2):
        return False
    text = source.text(error.path)
    return text is not None and all(
        site.line != error.line
        for site in recall.call_sites(text, wrappers, bare, finder.ros2))


# clang's "call to constructor of 'C' is ambiguous"
_CONSTRUCTOR_ERROR = re.compile(r"^call to constructor of '([^']+)' is ambiguous")


def _sites_in(cursors: Iterable[Cursor], source: Any, wrappers: list[str],
              bare: Iterable[str], ros2: bool) -> bool:
    """Whether a ROS call site lies in the lines of one of ``cursors`` (or one is not in
    a file the unit's source reads, so that it cannot be told)."""
    for cursor in cursors:
        start, end = cursor.extent.start, cursor.extent.end
        if start.file is None:
            return True
        text = source.text(os.path.abspath(start.file.name))
        if text is None or any(start.line <= site.line <= end.line
                               for site in recall.call_sites(text, wrappers, bare, ros2)):
            return True
    return False


ROSCPP = "roscpp"
# what ROS 1 code that communicates names: a handle, or the free parameter functions
_ROS1_CLIENT_CODE = re.compile(r"\bNodeHandle\b|\bros\s*::\s*(?:param|topic|service)\s*::")
_SOURCE_SUFFIXES = (".cpp", ".cc", ".cxx", ".c++", ".h", ".hpp", ".hh", ".hxx")
MAX_CLIENT_FILES = 400  # files of a package read to find where a class is defined


def ros1_clients(path: str, workspace: Workspace, generated: str,
                 read: list[str]) -> Callable[..., str | None]:
    """The package, if any, whose class (qualified) may make ROS calls of its own in
    code a ROS 1 unit builds without reading it (``CallFinder._unseen_class``), for a
    class and the package named by its namespace's first part; when that part is no
    dependency, a dependency whose name begins with it and holds the namespace's next
    part (MoveIt's ``moveit::planning_interface::MoveGroupInterface``, of
    moveit_ros_planning_interface).
    Not a class of a package the stand-in headers provide, nor a message or service
    (of the catalogue, or named as a header the unit includes: ``<pkg/Name.h>`` is how
    ROS 1 generates them). A workspace package's when it depends on roscpp and the
    files that define the class's constructors (when found) name a NodeHandle or the
    parameter, topic or service functions; another package's when the unit's package
    declares it as a dependency and it is installed with a package.xml that depends on
    roscpp, or found nowhere (its headers are missing: what it does is not known) and
    not in the table of dependencies known to make no ROS calls (``no_clients``); not,
    the package not in the workspace, a class that table lists as making none
    (``no_client_classes``). A
    dependency counts when the unit's package declares it or a workspace package it
    depends on exports it (``_visible``). The workspace files it reads (manifests, the
    files that define a class) go to ``read``, so a cached result is used only while
    they are unchanged."""
    package = workspace.package_of(path)
    if package is not None and package.root:
        read.append(manifest_of(package.root))
    declared = _visible(package, workspace, read) if package is not None else set()
    # the unit's package's own dependencies first, then those it reaches through them
    direct = {d.name for d in package.dependencies} if package is not None else set()
    known: dict[tuple[str, str], bool] = {}

    def one(name: str, cls: str) -> bool:
        found = known.get((name, cls))
        if found is None:
            found = known[(name, cls)] = _client(name, cls, declared, workspace, generated,
                                                 read)
        return found

    def client(name: str, cls: str, unread: bool = False, header: bool = False
               ) -> str | None:
        if unread:
            # a class our stand-ins declare without reading its code (HAROS_UNREAD:
            # costmap_2d's Costmap2DROS): the package's, when the unit may include it
            return name if name in declared else None
        if header:
            # ``name`` begins a missing header the class is declared in, by folder
            # (``header_packages``): that dependency's, when it may make calls
            return next((d for d in header_packages(name, declared, direct) if one(d, cls)),
                        None)
        if name in declared or name in workspace.packages:
            return name if one(name, cls) else None
        parts = cls.split("::")
        named = sorted(d for d in declared if d.startswith(name + "_") and parts[1] in d) if (
            len(parts) >= 3) else []
        # or a dependency named after one of the class's names, as ROS packages often are
        # after their main class (ROBOTIS-OP3's ``RobotisController``, of
        # robotis_controller, in namespace robotis_framework: its singleton reached
        # through ``RobotisController::getInstance()``, its header missing)
        named += [snake for snake in (ros2_interfaces.snake_case(part) for part in parts)
                  if snake in declared and snake != name and snake not in named]
        return next((d for d in named if one(d, cls)), None)

    return client


# the dependencies of a package whose headers the packages depending on it see (REP 140:
# ``depend`` and ``build_export_depend``; format 1's ``run_depend`` is both)
_EXPORTED = frozenset({"depend", "build_export_depend", "run_depend"})


_QT_CLASS = re.compile(r"Q[A-Z]\w*")


def header_packages(top: str, visible: Collection[str],
                    direct: Collection[str] = ()) -> list[str]:
    """The packages a unit may include (``visible``) that the first folder ``top`` of a
    missing header names (``visitor.header_folder``: the header declares the class by
    the folder below it), the likeliest first: that package, else those whose names
    begin with it, the unit's own dependencies (``direct``) before those it reaches
    through them. MoveIt's ``<moveit/robot_model_loader/robot_model_loader.h>``, whose
    ``robot_model_loader::RobotModelLoader`` reaches a unit through a dependency named
    ``moveit_*`` (moveit_ros_planning_interface brings moveit_ros_planning's headers).
    One rule for both questions asked of such a class: whether it is a ROS package's
    (``ros_classes``) and whose code it runs (``ros1_clients``)."""
    return [d for d in sorted(visible, key=lambda d: (d != top, d not in direct, d))
            if d == top or d.startswith(top + "_")]


def ros_classes(path: str, workspace: Workspace, read: list[str],
                missing_headers: Sequence[str] = ()) -> Callable[[str], bool]:
    """Whether a class the parse knows only by its (qualified) name may be a ROS
    package's, whose code may make ROS calls on an object of it: one in the global
    namespace (not known), or whose namespace's first part is a workspace package, a
    package the unit's package may include (``_visible``) or the beginning of one's name
    (MoveIt's ``moveit::`` of moveit_ros_planning_interface), or is a folder of one of
    the unit's ``missing_headers`` whose first folder names such a package
    (``header_packages``: MoveIt's ``planning_interface::PlannerManager`` of
    ``<moveit/planning_interface/planning_interface.h>``, moveit_core's). Not another
    library's: librealsense's ``rs2::sensor``, which realsense2_camera's RosSensor
    derives from, is of no package the unit depends on by that name. The manifests read
    go to ``read``."""
    package = workspace.package_of(path)
    if package is not None and package.root:
        read.append(manifest_of(package.root))
    visible = _visible(package, workspace, read) if package is not None else set()

    def named(first: str) -> bool:
        return first in workspace.packages or first in visible or any(
            name.startswith(first + "_") for name in visible)

    def ros(cls: str) -> bool:
        first = cls.lstrip(":").split("::", 1)[0]
        if "::" not in cls.lstrip(":") or not first:
            # in the global namespace: not known, but for Qt's classes (``Q`` and a
            # capital: rviz's PropertyTreeModel calls QAbstractItemModel's createIndex)
            return _QT_CLASS.fullmatch(first) is None
        if named(first):
            return True
        top = header_folder(cls, missing_headers)
        if top is not None and (top in workspace.packages or bool(header_packages(top, visible))):
            return True
        by_name = named_header_folder(cls, missing_headers)
        return by_name is not None and (by_name in workspace.packages or by_name in visible)
    return ros


def _visible(package: Package, workspace: Workspace, read: list[str]) -> set[str]:
    """The packages whose headers a unit of ``package`` may include: its dependencies,
    and those the workspace packages among them export (``_EXPORTED``), in turn. A node
    that includes a workspace library's header reaches the classes that header names
    (hector_exploration_node builds costmap_2d's Costmap2DROS through
    hector_exploration_planner, which depends on costmap_2d; it declares only the
    planner). The manifests read go to ``read``."""
    from ... import cmake  # the C++ extractor is imported by the pipeline, after cmake

    found = {d.name for d in package.dependencies}
    if package.root and package.build_type == "catkin":
        # and the ROS packages its build finds that its package.xml does not name: the
        # build has their headers (vizzy_control's gaze_sim builds moveit's
        # MoveGroupInterface, which subscribes joint_states; no moveit package declared,
        # the node was complete and the launch file's joint_states remap "unused")
        read.append(os.path.join(package.root, "CMakeLists.txt"))
        found.update(cmake.catkin_components(package, workspace))
    todo = sorted(found)
    seen = {package.name}
    while todo:
        name = todo.pop()
        other = workspace.packages.get(name)
        if name in seen or other is None:
            continue
        seen.add(name)
        if other.root:
            read.append(manifest_of(other.root))
        for dep in other.dependencies:
            if dep.kind in _EXPORTED and dep.name not in found:
                found.add(dep.name)
                todo.append(dep.name)
    return found


def _client(name: str, cls: str, declared: set[str], workspace: Workspace,
            generated: str, read: list[str]) -> bool:
    if any(os.path.isdir(os.path.join(folder, name)) for folder in (STANDIN, FALLBACK)) or (
        interface_package(name)
    ):
        return False
    last = cls.rsplit("::", 1)[-1]
    for each in {last, re.sub(r"(?:Request|Response)$", "", last)}:
        if known_interface(name, each) is not None or os.path.isfile(
                os.path.join(generated, name, each + ".h")):
            return False
    other = workspace.packages.get(name)
    if other is None and cls in no_client_classes().get(name, ()):
        return False  # a class of a ROS package, read in its source: no ROS call
    if any(cls in names for package, names in no_client_classes().items()
           if package != name and package not in workspace.packages and "::" in cls
           and not cls.startswith(package + "::")):
        # named in full in the table under another package than the one it is credited
        # to (moveit_core's robot_state::RobotState, credited to the unit's MoveIt
        # dependency by the header's folder): that package's, read in its source
        return False
    if other is not None:
        if not any(d.name == ROSCPP for d in other.dependencies):
            return False
        if other.root:
            read.append(manifest_of(other.root))
        code = _defining_code(other.root, last, read, _library_sources(other, workspace))
        return code is None or _ROS1_CLIENT_CODE.search(code) is not None
    if name not in declared:
        return False
    folder = workspace.find(name)
    manifest = os.path.join(folder, "package.xml") if folder else None
    if manifest is None or not os.path.isfile(manifest):
        return name not in no_clients()  # found nowhere: unknown, unless the table knows
    parsed, _ = parse_manifest(manifest, workspace.location(manifest), folder or "",
                               workspace.environment)
    return parsed is None or any(d.name == ROSCPP for d in parsed.dependencies)


NO_CLIENTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "nonclients.yaml")


@functools.lru_cache(maxsize=1)
def no_clients() -> frozenset[str]:
    """The dependencies known to make no ROS calls though their manifests are not at hand
    (``nonclients.yaml``, each list with its source): rosdep keys of system libraries
    (``tinyxml2``, ``libpcl-all-dev``) and third-party libraries released into ROS 1
    whose package.xml depends on no ROS client library (``gtsam``, ``octomap``)."""
    with open(NO_CLIENTS, encoding="utf-8") as handle:
        data = safe_yaml.load(handle.read())
    return frozenset([*data["system"], *data["released"]])


@functools.lru_cache(maxsize=1)
def no_client_classes() -> dict[str, frozenset[str]]:
    """Classes (qualified) of ROS packages that make ROS calls elsewhere, whose
    constructors and what they run make none, each package's list read in its source
    (``nonclients.yaml``'s ``classes``): costmap_2d's ``Costmap2D``, the grid that
    frontier explorers and planners build; ros_control's joint limits handles and
    interfaces (its ``getJointLimits(name, nh, limits)`` reads parameters: a function,
    not a class, still unknown where the header is missing); a name with ``::`` is
    written in full (MoveIt's ``moveit::core::RobotState``, whose namespace is not its
    package's name, and its alias ``robot_state::RobotState``). Used where the package
    is not in the workspace (a workspace package's code is read instead)."""
    with open(NO_CLIENTS, encoding="utf-8") as handle:
        data = safe_yaml.load(handle.read())
    return {package: frozenset(name if "::" in name else f"{package}::{name}"
                               for name in entry["names"])
            for package, entry in data["classes"].items()}


def _library_sources(package: Package, workspace: Workspace) -> list[str]:
    """The C++ sources of the libraries ``package``'s CMake builds (absolute), where the
    code of a class it exports is: read before the rest of its folder, whose first
    ``MAX_CLIENT_FILES`` files may all be vendored code (quadruped-robot's quadruped
    holds 396 C++ files of ``extern/`` libraries and 74 headers before its ``src/``)."""
    from ...cmake import CMAKE_BUILD_TYPES, targets_of

    if package.build_type not in CMAKE_BUILD_TYPES or not package.root:
        return []
    targets, _ = targets_of(package, workspace)
    return list(dict.fromkeys(
        source if os.path.isabs(source) else os.path.join(package.root, source)
        for target in targets if target.kind == "library"
        for source in target.sources if source.endswith(_SOURCE_SUFFIXES)))


def _defining_code(root: str, cls: str, read: list[str], first: Sequence[str] = ()
                   ) -> str | None:
    """The text of the files under ``root`` that define a constructor of ``cls`` out of
    its class (``cls::cls(``), joined; else of those that define the class itself
    (``class cls {``, its constructors inline); "" when ``cls`` is only an alias or an
    enumeration there (``using Covariance3d = ...``, ``enum class cls``: no code of its
    own); None when no file says. The files ``first`` (the package's libraries'
    sources, ``_library_sources``) are read before the folder's, beside its limit."""
    name = re.escape(cls)
    defines = re.compile(rf"\b{name}\s*::\s*{name}\s*\(")
    declares = re.compile(rf"\b(?:class|struct)\s+(?:\w+\s+)?{name}\b[^;{{]*{{")
    plain = re.compile(rf"\busing\s+{name}\s*=|\btypedef\b[^;]*\b{name}\s*;|"
                       rf"\benum\s+(?:class\s+|struct\s+)?{name}\b")
    found: list[str] = []
    classes: list[tuple[str, str]] = []
    alias = False
    for full in [*first, *_client_files(root, set(first))]:
        try:
            if os.path.getsize(full) > MAX_FILE_BYTES:
                continue
            with open(full, encoding="utf-8", errors="replace") as handle:
                text = handle.read()
        except OSError:
            continue
        if defines.search(text):
            found.append(text)
            read.append(full)
        elif declares.search(text):
            classes.append((full, text))
        elif plain.search(text):
            alias = True
            read.append(full)
    if found:
        return "\n".join(found)
    if classes:
        read.extend(full for full, _ in classes)
        return "\n".join(text for _, text in classes)
    return "" if alias else None


def _client_files(root: str, skipped: set[str]) -> Iterator[str]:
    """The first ``MAX_CLIENT_FILES`` C++ files under ``root`` (sorted), less
    ``skipped``."""
    seen = 0
    for folder, dirs, files in os.walk(root):
        dirs.sort()
        for file in sorted(files):
            full = os.path.join(folder, file)
            if not file.endswith(_SOURCE_SUFFIXES) or full in skipped:
                continue
            seen += 1
            if seen > MAX_CLIENT_FILES:
                return
            yield full


def error_detail(spelling: str, generated: str) -> str:
    """A clang error as said: a header we synthesised is named without the run's
    temporary folder (``haros_synthesised_names.h:124:3``), so the message is the same in
    every run and in the cache."""
    return spelling.replace(generated.rstrip(os.sep) + os.sep, "")


_HANDED = frozenset({"CPP_NODE_PASSED", "CPP_NODE_TO_UNKNOWN", "CPP_NODE_UNREAD"})
_CLASSES = frozenset({CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL, CursorKind.CLASS_TEMPLATE})
# what follows a class's name written as the scope of a call of its static method
_STATIC_CALL = re.compile(rb"\s*::\s*(?:template\s+)?[A-Za-z_]\w*\s*(?:<[^;{}()]*>\s*)?\(")
# the children of a function's cursor that belong to its declarator
_DECLARATOR = frozenset({
    CursorKind.TYPE_REF, CursorKind.NAMESPACE_REF, CursorKind.TEMPLATE_REF,
    CursorKind.PARM_DECL, CursorKind.TEMPLATE_TYPE_PARAMETER,
    CursorKind.TEMPLATE_NON_TYPE_PARAMETER, CursorKind.TEMPLATE_TEMPLATE_PARAMETER})


class _Places:
    """What a unit's errors are inside, each worked out once per unit: ``_unseen``,
    ``_node_given`` and ``_error_words`` ask it of the same errors, and many errors of a
    unit are in one function (the innermost function holding a line, the words of the
    code an error can hide a statement in, the words that name the node there)."""

    def __init__(self, finder: CallFinder, source: SourceCache) -> None:
        self.finder = finder
        self.source = source
        self._innermost: dict[tuple[str, int], Cursor | None] = {}
        self._words: dict[tuple[str, int], frozenset[bytes] | None] = {}
        self._names: dict[int, tuple[Cursor, frozenset[str]]] = {}
        self._static: dict[int, frozenset[bytes]] = {}  # ``_static_scopes``, by function

    def innermost(self, path: str, line: int) -> Cursor | None:
        """``_innermost`` of the finder's functions."""
        key = (path, line)
        if key not in self._innermost:
            self._innermost[key] = _innermost(self.finder.functions, path, line)
        return self._innermost[key]

    def node_names(self, function: Cursor) -> frozenset[str]:
        """``owners.node_names`` of ``function`` (kept with it: its id stays its own)."""
        found = self._names.get(id(function))
        if found is None:
            found = self._names[id(function)] = (function, node_names(function))
        return found[1]

    def _static_scopes(self, function: Cursor, data: bytes, start: int) -> frozenset[bytes]:
        """The classes ``function``'s code (from ``start``) writes only as the scope of
        calls of their static methods that the parse read (``C::f(...)``, each at the
        lines of such a call): no statement an error hides constructs one there, and
        what the calls do is read with them (mpc_local_planner's test_mpc_optim_node
        calls its plugin class's static ``MpcLocalPlannerROS::
        getRobotFootprintFromParamServer(nh)`` in ``start()``, whose other statements
        have errors: the plugin's ``initialize`` ran in the executable)."""
        key = function.hash
        found = self._static.get(key)
        if found is not None:
            return found
        lines: dict[bytes, set[int]] = {}
        for node in function.walk_preorder():
            if node.kind != CursorKind.CALL_EXPR:
                continue
            target = node.referenced
            if target is None or target.kind != CursorKind.CXX_METHOD or (
                    not target.is_static_method()):
                continue
            owner = target.semantic_parent
            if owner is None or owner.kind not in _CLASSES or not owner.spelling:
                continue
            lines.setdefault(owner.spelling.encode(), set()).update(
                range(node.extent.start.line, node.extent.end.line + 1))
        end = function.extent.end.offset
        scopes: set[bytes] = set()
        for word, at in lines.items():
            uses = list(re.compile(rb"\b" + re.escape(word) + rb"\b").finditer(data, start, end))
            if uses and all(_STATIC_CALL.match(data, use.end()) is not None and (
                    data.count(b"\n", 0, use.start()) + 1 in at) for use in uses):
                scopes.add(word)
        found = self._static[key] = frozenset(scopes)
        return found

    def logged(self, error: _Error) -> bool:
        """Whether ``error`` is inside the arguments of a logging macro (``RCLCPP_INFO``,
        ``ROS_WARN_STREAM``: ``recall.log_statements``) that holds no ROS call site of
        the API or the unit's wrappers: such a statement writes a message, and hides no
        call (mavros' ``RCLCPP_INFO(..., mavlink::version)`` with mavlink's generated
        headers absent left its router and UAS partial)."""
        data = self.source.get(error.path) if error.path is not None else None
        if data is None:
            return False
        span = next(((start, end) for start, end in recall.log_statements(data)
                     if start <= error.offset < end), None)
        if span is None:
            return False
        assert error.path is not None
        first = data.count(b"\n", 0, span[0]) + 1
        last = first + data.count(b"\n", span[0], span[1])
        return not any(first <= site.line <= last for site in self.sites(error.path) or ())

    def sites(self, name: str) -> list[recall.Site] | None:
        """The ROS call sites of file ``name`` (``recall.call_sites``), of the API and of
        the unit's wrappers; None when it cannot be read."""
        text = self.source.text(name)
        if text is None:
            return None
        wrappers = self.finder.wrappers
        return recall.call_sites(text, sorted(n for n in wrappers.site_names if n),
                                 wrappers.site_names_bare, self.finder.ros2,
                                 wrappers.site_qualifiers)

    def words(self, error: _Error) -> frozenset[bytes] | None:
        """The words of the code where ``error`` can hide a statement: the text of the
        function that holds it (a constructor's, with the types of its class's
        members, which its initialisers construct unnamed), else the error's line;
        None when its file cannot be read."""
        assert error.path is not None
        key = (error.path, error.line)
        if key in self._words:
            return self._words[key]
        data = self.source.get(error.path)
        found: set[bytes] | None = None
        if data is not None:
            found = set()
            function = self.innermost(error.path, error.line)
            if function is None:
                lines = data.splitlines()
                if 0 < error.line <= len(lines):
                    found.update(WORDS.findall(lines[error.line - 1]))
            else:
                # from its member initialisers and body on: not the class that qualifies
                # a method's name (every error in a method of the class would name it)
                start = next((child.extent.start.offset for child in function.get_children()
                              if child.kind not in _DECLARATOR), function.extent.start.offset)
                found.update(WORDS.findall(data[start:function.extent.end.offset]))
                found -= self._static_scopes(function, data, start)
                owner = function.semantic_parent
                if owner is not None and owner.kind in _CLASSES:
                    # a method names its own class (``&Costmap2DROS::reconfigureCB``),
                    # which it does not construct
                    found.discard(owner.spelling.encode())
                    if function.kind == CursorKind.CONSTRUCTOR:
                        for member in owner.get_children():
                            if member.kind == CursorKind.FIELD_DECL:
                                found.update(WORDS.findall(member.type.spelling.encode()))
        self._words[key] = words = frozenset(found) if found is not None else None
        return words


def _unseen(errors: list[_Error], places: _Places,
            owners: dict[bytes, set[str]] | None = None) -> set[bytes]:
    """The words of the code where ``errors`` can hide a statement (``_Places.words``);
    ``*`` when the file of one cannot be read. With ``owners``, each word found only in
    functions gets the owners of those functions there (what ``_reached`` counts only
    where one of them runs)."""
    words: set[bytes] = set()
    loose: set[bytes] = set()  # words of an error outside any function
    for error in errors:
        if error.path is None:
            continue
        found = places.words(error)
        if found is None:
            return {b"*"}
        function = places.innermost(error.path, error.line)
        if function is None:
            loose |= found
            continue
        words |= found
        if owners is not None:
            holder = owner_of(function)
            for word in found:
                owners.setdefault(word, set()).add(holder)
    if owners is not None:
        for word in loose:
            owners.pop(word, None)
    return words | loose


def _node_given(errors: list[_Error], places: _Places, workspace: Workspace
                ) -> list[Diagnostic]:
    """The errors on a name the parse does not know in a statement that passes the node
    to it (``recall.node_given``): ``CPP_NODE_TO_UNKNOWN``, once per line."""
    found: list[Diagnostic] = []
    said: set[tuple[str, int]] = set()
    for error in errors:
        match = recall.UNKNOWN_NAME.search(error.spelling)
        if match is None or error.path is None or (error.path, error.line) in said:
            continue
        function = places.innermost(error.path, error.line)
        lines = places.source.lines(error.path) if function is not None else None
        if function is None or lines is None:
            continue
        given = recall.node_given(lines, error.line, places.node_names(function))
        unknown = match.group("name") or match.group("scope")
        if given is not None and recall.assigns_to(lines, error.line, unknown):
            given = None  # the unknown name takes the result: nothing is given to it
        if given is not None:
            said.add((error.path, error.line))
            places.finder.handed.add(owner_of(function))
            # as written there: ``quadrotor_common::getParam``, not its namespace alone
            name = _written_name(error, unknown, lines)
            found.append(diag.make(
                "CPP_NODE_TO_UNKNOWN", workspace.location(error.path, error.line, error.column),
                given=given, name=name))
    return found


def _error_words(errors: list[_Error], places: _Places
                 ) -> list[tuple[set[str], tuple[str, int] | None]]:
    """The words of the code each error can hide a statement in (``_unseen``), with
    the error's place when it is outside the functions (its line's words: the
    declarations there are no calls, ``call_conditions.hidden_facts``)."""
    found: list[tuple[set[str], tuple[str, int] | None]] = []
    for error in errors:
        if error.path is None:
            continue
        words = {w.decode() for w in _unseen([error], places)}
        inside = places.innermost(error.path, error.line) is not None
        found.append((words, None if inside or "*" in words else (error.path, error.line)))
    return found


def _innermost(functions: list[Cursor], path: str, line: int) -> Cursor | None:
    """The function of ``functions`` defined in ``path`` whose lines hold ``line`` and
    that starts last (a lambda's or a local class's method inside another)."""
    best: Cursor | None = None
    best_start = -1
    for function in functions:
        extent = function.extent
        start, end = extent.start, extent.end
        if start.file is None or start.line > line or end.line < line or (
            start.line <= best_start
        ) or os.path.abspath(start.file.name) != path:
            continue
        best, best_start = function, start.line
    return best


def _parse(path: str, text: str, setup: IncludeSetup, workspace: Workspace,
           result: CppResult, source: SourceCache,
           owned: Callable[[str], bool], ros2: bool = False,
           wrappers: tuple[frozenset[str], frozenset[str]] | None = None,
           clients: Callable[..., str | None] | None = None
           ) -> TranslationUnit | None:
    """Parse ``path``; headers clang still misses are stood in for and parsed again, then
    names it does not know are declared (``synthesis``) and parsed again while that
    leaves fewer errors (``clients``: ``ros1_clients`` of a ROS 1 unit)."""
    unsaved = [(path, text)]
    args = setup.arguments(source=path)
    if not setup.system_headers:
        args = [*args, "-include", UNIT_ROS[2 if ros2 else 1]]
    tu: TranslationUnit | None = None
    for _attempt in range(2):
        tu = _parse_once(path, args, unsaved, workspace, result)
        if tu is None:
            return None
        missing = [
            (e.spelling, workspace.location(e.path, e.line, e.column))
            for e in _errors(tu) if e.path is not None and "file not found" in e.spelling]
        if not missing or not setup.repair(missing):
            break
    assert tu is not None
    setup.unit_missing = setup.stood_in(
        (os.path.abspath(inclusion.include.name), functools.partial(
            _included_at, workspace, inclusion.location))
        for inclusion in tu.get_includes() if inclusion.location.file is not None)
    wanted = _unincluded_messages(tu, setup, source)
    if wanted:
        more = [*args, *(word for header in wanted for word in ("-include", header))]
        again = _parse_once(path, more, unsaved, workspace, result)
        if again is not None and len(_errors(again)) < len(_errors(tu)):
            tu, args = again, more
    demanded = _demanded_macros(tu, source)
    if demanded:
        more = [*args, *(f"-D{name}" for name, _where in demanded)]
        again = _parse_once(path, more, unsaved, workspace, result)
        if again is not None:  # (the code the header now declares may show more errors)
            tu, args = again, more
            for name, (file, line) in demanded:
                result.diagnostics.append(diag.make(
                    "CPP_MACRO_DEMANDED", workspace.location(path), macro=name,
                    where=f"{workspace.relpath(file)}:{line}"))
    return _synthesise(path, tu, args, unsaved, setup, workspace, result, source, owned,
                       wrappers, clients)


MAX_DEMANDED = 8  # macros defined for one unit because an #error demands them
# an ``#error`` directive (the conditional directives around it: ``recall.DIRECTIVE``)
_ERROR_LINE = re.compile(r"\s*#\s*error\b")
_NOT_DEFINED = re.compile(r"!\s*defined\s*(?:\(\s*(\w+)\s*\)|(\w+))\s*$")
_DEFINED = re.compile(r"defined\s*(?:\(\s*(\w+)\s*\)|(\w+))\s*$")
MAX_DIRECTIVE_SCAN = 2000  # lines read back from an #error to its #if


def _demanded_macros(tu: TranslationUnit, source: SourceCache
                     ) -> list[tuple[str, tuple[str, int]]]:
    """The macros a workspace header's ``#error`` says a build defines: the error is the
    branch of ``#ifndef X`` (``#if !defined(X)``), or the ``#else`` of ``#ifdef X``
    (``#if defined(X)``), so every build that compiles the unit defines X (beluga's
    ndt_sensor_model.hpp, ``#ifndef BELUGA_HAS_HDF5 #error ...``, its macro an
    INTERFACE definition of another package's target under ``if(HDF5_FOUND)``: without
    it the header declares nothing and the node's class, built on it, is invalid). Each
    with the ``#error``'s file and line; none of our stand-ins'."""
    out: dict[str, tuple[str, int]] = {}
    for error in _errors(tu):
        if error.path is None or in_standin(error.path) or len(out) >= MAX_DEMANDED:
            continue
        lines = source.lines(error.path)
        if lines is None or not 0 < error.line <= len(lines) or not _ERROR_LINE.match(
                lines[error.line - 1]):
            continue
        name = _guard_of(lines, error.line - 1)
        if name is not None and name not in out:
            out[name] = (error.path, error.line)
    return list(out.items())


def _guard_of(lines: list[str], index: int) -> str | None:
    """The macro the conditional around line ``index`` needs defined for that line not
    to be reached: its ``#ifndef X`` / ``#if !defined(X)`` when the line is in its first
    branch, its ``#ifdef X`` / ``#if defined(X)`` when in its ``#else``; None for any
    other test, or an ``#elif`` between."""
    depth = 0
    in_else = False
    for line in reversed(lines[max(0, index - MAX_DIRECTIVE_SCAN):index]):
        found = recall.DIRECTIVE.match(line)
        if found is None:
            continue
        word, rest = found.group(1), code_only(found.group(2)).strip()
        if word == "endif":
            depth += 1
        elif word in ("if", "ifdef", "ifndef"):
            if depth:
                depth -= 1
                continue
            if word == "ifndef" and not in_else:
                return rest.split()[0] if rest.split() else None
            if word == "ifdef" and in_else:
                return rest.split()[0] if rest.split() else None
            test = (_DEFINED if in_else else _NOT_DEFINED).fullmatch(rest)
            if word == "if" and test is not None and (in_else or rest.startswith("!")):
                return test.group(1) or test.group(2)
            return None
        elif not depth:
            if word == "elif":
                return None
            in_else = True
    return None


def _included_at(workspace: Workspace, where: SourceLocation) -> Location:
    """Where an ``#include`` is, as a diagnostic says it (asked only of the few
    inclusions ``IncludeSetup.stood_in`` reports)."""
    return workspace.location(os.path.abspath(where.file.name), where.line, where.column)


# an error naming a namespace clang does not know, or a name missing from one (a ROS 2
# package's ``pkg::msg``: geometry_msgs::msg::TransformStamped where only twist.hpp is
# included, tf2_ros' headers bringing the rest in a real build)
_UNKNOWN_SPACE = re.compile(r"^use of undeclared identifier '(\w+)'$"
                            r"|^no (?:type|member|template) named '\w+' in namespace "
                            r"'(\w+)(?:::(?:msg|srv|action))?'$")
_QUALIFIED = re.compile(rb"\b([A-Za-z_]\w*)\s*::\s*([A-Za-z_]\w*)")
# a ROS 2 interface written in full: ``rcl_interfaces::srv::SetParameters``
_QUALIFIED_ROS2 = re.compile(
    rb"\b([A-Za-z_]\w*)\s*::\s*(msg|srv|action)\s*::\s*([A-Z]\w*)")
_POINTER_SUFFIXES = ("ConstPtr", "Ptr")


def _unincluded_messages(tu: TranslationUnit, setup: IncludeSetup,
                         source: SourceCache) -> list[str]:
    """The message headers a unit uses without including them: MoveIt's headers bring
    ``geometry_msgs/PoseStamped.h``, so kinova's pick_place names
    ``geometry_msgs::PoseStampedConstPtr`` with no include of its own; with MoveIt's
    headers missing the type was declared permissively and ``subscribe<geometry_msgs::
    PoseStamped>(topic, 1, &PickPlace::get_current_pose, this)`` an error. A name
    ``pkg::Name`` (or ``NameConstPtr`` / ``NamePtr``) in a file with such an error, where
    ``pkg`` is a namespace an error says is unknown and the workspace or the catalogue
    defines the message ``pkg/Name``: its ``pkg/Name.h``."""
    errors = [e for e in _errors(tu) if e.name is not None]
    spaces: set[str] = set()
    files: set[str] = set()
    for error in errors:
        found = _UNKNOWN_SPACE.match(error.spelling)
        if found is not None:
            spaces.add(found.group(1) or found.group(2))
            files.add(error.name or "")
    if not spaces:
        return []
    wanted = {space.encode() for space in spaces}  # most names are in no such space
    headers: list[str] = []
    for name in sorted(files):
        text = source.get(name)
        for outer, inner in _qualified_in(text or b""):
            if outer not in wanted:
                continue
            space = outer.decode()
            written = inner.decode()
            base = next((written[: -len(s)] for s in _POINTER_SUFFIXES
                         if written.endswith(s) and len(written) > len(s)), written)
            header = f"{space}/{base}.h"
            if header not in headers and setup.message_header(header):
                headers.append(header)
        # ROS 2: rclcpp's headers bring rcl_interfaces' parameter services, so webots'
        # WebotsNode.hpp holds an ``rclcpp::Client<rcl_interfaces::srv::SetParameters>``
        # with no include of its own; the member's type was an error and the node class
        # invalid (``no member named 'srv' in namespace 'rcl_interfaces'``)
        for outer, kind, written_name in _qualified_ros2_in(text or b""):
            if outer not in wanted:
                continue
            space = outer.decode()
            header = ros2_interfaces.header(space, kind.decode(), written_name.decode())
            if header not in headers and setup.message_header(header):
                headers.append(header)
    return headers


@functools.lru_cache(maxsize=256)
def _qualified_in(text: bytes) -> list[tuple[bytes, bytes]]:
    """Every ``a::b`` of ``text`` (``_QUALIFIED``), in order: each header with errors is
    read by every unit that includes it."""
    return _QUALIFIED.findall(text)


@functools.lru_cache(maxsize=256)
def _qualified_ros2_in(text: bytes) -> list[tuple[bytes, bytes, bytes]]:
    """Every ``pkg::msg::Name`` of ``text`` (``_QUALIFIED_ROS2``), in order."""
    return _QUALIFIED_ROS2.findall(text)


def _parse_once(path: str, args: list[str], unsaved: list[tuple[str, str]],
                workspace: Workspace, result: CppResult,
                options: int = PARSE_OPTIONS) -> TranslationUnit | None:
    try:
        return toolchain.index().parse(path, args=args, unsaved_files=unsaved,
                                       options=options)
    except TranslationUnitLoadError as err:
        failed = err
    # a precompiled prelude libclang cannot read fails every parse that names it, the
    # unit's own code aside: once more with the prelude's header
    plain = without_pch(args)
    if plain is not None:
        try:
            return toolchain.index().parse(path, args=plain, unsaved_files=unsaved,
                                           options=options)
        except TranslationUnitLoadError as err:
            failed = err
    result.diagnostics.append(diag.make(
        "CPP_PARSE_FAILED", workspace.location(path), detail=str(failed) or "libclang"))
    return None


def _synthesise(path: str, tu: TranslationUnit, args: list[str],
                unsaved: list[tuple[str, str]], setup: IncludeSetup, workspace: Workspace,
                result: CppResult, source: SourceCache,
                owned: Callable[[str], bool],
                wrappers: tuple[frozenset[str], frozenset[str]] | None = None,
                clients: Callable[..., str | None] | None = None
                ) -> TranslationUnit:
    """The parse with the fewest errors once the unknown names are declared;
    ``wrappers``: the names of the unit's own wrappers of the API, whose calls count as
    the API's where an error may cost one (known once the unit was walked); ``clients``:
    which classes known only by name may make ROS calls of their own (``_hiding``)."""

    def mine(unit: TranslationUnit) -> list[_Error]:
        return [e for e in _errors(unit) if e.name is not None and owned(e.name)]

    if clients is not None:
        clients = _by_header(clients, _missing_headers(tu, setup))
    first = mine(tu)
    before = len(first)
    facts = _header_facts(setup)
    fieldless = facts.fieldless(setup)
    names = synthesis.Names(fieldless, _declared_in(tu), facts.libraries(setup),
                            qt=_reads(tu, os.path.join(STANDIN, QT)))
    header = os.path.join(setup.generated, synthesis.HEADER_NAME)
    # the functions of each file, by line, and its API call sites (the same text in
    # every parse of the unit: each file is read once, not once per parse)
    functions: dict[str, list[recall.Function]] = {}
    sites = _Sites(wrappers)
    if synthesis.MAX_ROUNDS < 1 or not _hiding(tu, first, source, fieldless, functions, sites,
                                               clients):
        return tu  # no error where it could cost a call
    names.in_free = _in_free(first, functions, source)
    names.in_read = _in_free(first, functions, source, recall.BASES_READ)
    if not names.learn(_located(first, source, tu)):
        return tu  # nothing to declare
    # Errors come in waves: a class made valid shows its other members. With more than
    # one round, the next waves are looked for without function bodies (the names that
    # make a class invalid are in declarations); then the unit is parsed in full with
    # all the names, and once more when that shows more (a wave, or members of declared
    # classes used in function bodies); the parse with the fewest errors is kept.
    args = _with_names(args, header)
    for _round in range(synthesis.MAX_ROUNDS - 1):
        probe = _parse_once(path, args,
                            [*unsaved, (header, names.header())], workspace, result,
                            PARSE_OPTIONS | SKIP_FUNCTION_BODIES)
        if probe is None or not names.learn(_located(mine(probe), source, probe)):
            break
    names.read_members(source.values())  # the files with errors: members come next
    best = tu
    for _full in range(synthesis.FULL_PARSES):  # more: again when one shows more names
        again = _parse_once(path, args, [*unsaved, (header, names.header())], workspace,
                            result)
        if again is None:
            break
        if _cost(again) < _cost(best):
            best = again
        # parsed again only when a name learnt here can matter: from an error that can
        # cost a call (the other errors' names are declared too, but never cost a parse)
        left = mine(again)
        hiding = _hiding(again, left, source, fieldless, functions, sites, clients)
        names.in_free = _in_free(left, functions, source)
        names.in_read = _in_free(left, functions, source, recall.BASES_READ)
        learnt = bool(hiding) and names.learn(_located(hiding, source, again))
        rest = names.learn(_located([e for e in left if e not in hiding], source, again))
        # or when this parse is not the best and the other errors name more (members
        # of declared classes read in code that makes no ROS call, which count against
        # it: stereo_image_proc's processor.h, whose unknown members kept its nodelet's
        # class invalid)
        if not learnt and not (rest and best is not again):
            break
    if best is tu:
        return tu  # declaring them made it no better: the parse as it was
    again = best
    included = names.included()
    result.diagnostics.append(diag.make(
        "CPP_NAMES_DECLARED", workspace.location(path), count=names.declared_count(),
        names=", ".join(names.first()) or "none", before=before, after=len(mine(again)),
        included=f"; {', '.join(included)} from the stand-ins' headers" if included else ""))
    return again


def _with_names(args: list[str], header: str) -> list[str]:
    """``args`` with the synthesised names' header included before the messages a unit
    uses without including them (``_unincluded_messages``, given as ``-include`` after
    the unit's ROS stand-in): its definitions must come first, as they do for headers
    the unit's own file includes. A message known only by name takes the members it is
    asked for through a macro its struct expands (``interfaces.fields_macro``), which a
    struct read before the macro is defined never sees: Autoware's multi_object_tracker
    (autoware_auto_perception_msgs missing) kept ``Label::CAR`` an error, and the seven
    ``declare_parameter`` calls beside it were lost."""
    for at in range(len(args) - 1):
        if args[at] == "-include" and args[at + 1] in UNIT_ROS.values():
            return [*args[:at + 2], "-include", header, *args[at + 2:]]
    return [*args, "-include", header]


@functools.lru_cache(maxsize=1)
def _api_names() -> frozenset[str]:
    """The names of the API's functions (``api.ALL``'s rows)."""
    return frozenset(name for _owner, name in api.ALL)


def _cost(tu: TranslationUnit) -> int:
    """How bad a parse is, to choose between parses of a unit: its errors, but for
    clang's "call to ... 'X' is ambiguous" of an API function ``X``, a call the walk
    keeps by its name (``_of_kept_call``): laser_scan_matcher's ``getParam("epsilon_xy",
    input_.epsilon_xy)`` into a field of a struct of csm (not in the workspace) is such a
    call once ``sm_params`` is declared, where without it the statement, and the call,
    is lost. Nor a reinterpret_cast of a value the parse does not know
    (``_PERMISSIVE_CAST``): with the name declared all but that value reads
    (``reinterpret_cast<Map*>(vendor::current())``), without it the name is undeclared."""
    return sum(1 for e in _errors(tu) if not (
        "is ambiguous" in e.spelling and (found := _CALL_ERROR.search(e.spelling)) is not None
        and found.group(1) in _api_names()) and not _PERMISSIVE_CAST.match(e.spelling))


def _reads(tu: TranslationUnit, path: str) -> bool:
    """Whether the parse ``tu`` read the file ``path``."""
    return bool(conf.lib.clang_getFile(tu, path))


def _declared_in(tu: TranslationUnit) -> Callable[[str], frozenset[str]]:
    """The names ``tu`` declares directly in a top-level namespace, by its name (every
    block that opens it), or at global scope (``""``: the unit's top-level declarations,
    read only when asked), each namespace read once per parse: the names are kept with
    ``tu`` (the synthesis and ``_hidden`` ask the same parse when declaring names made
    it no better), not its cursors, which refer to it."""
    kept: dict[str, frozenset[str]] | None = getattr(tu, "_haros_declared", None)
    found: dict[str, frozenset[str]] = {} if kept is None else kept
    tu._haros_declared = found
    blocks: dict[str | None, list[Cursor]] = {}

    def declared(scope: str) -> frozenset[str]:
        if scope in found:
            return found[scope]
        if scope == "":
            found[scope] = frozenset(name for name in child_spellings(tu.cursor)
                                     if name is not None)
            return found[scope]
        if not blocks:  # the unit's top-level namespaces, one visit
            blocks[""] = []
            blocks.update(namespace_blocks(tu.cursor))
        found[scope] = frozenset(name for block in blocks.get(scope, ())
                                 for name in child_spellings(block) if name is not None)
        return found[scope]

    return declared


def _missing_headers(tu: TranslationUnit, setup: IncludeSetup) -> list[str]:
    """The headers ``tu`` includes that are empty stand-ins, as included."""
    return [h for h in dict.fromkeys(setup.empty_stand_in(os.path.abspath(i.include.name))
                                     for i in tu.get_includes()) if h is not None]


def _by_header(clients: Callable[..., str | None], headers: list[str]
               ) -> Callable[..., str | None]:
    """``clients``, and for a class it takes for no package's, the dependency a missing
    header the class is declared in names by its first folder (``header_folder``)."""
    if not headers:
        return clients

    def client(name: str, cls: str, unread: bool = False) -> str | None:
        found = clients(name, cls, unread)
        if found is not None or unread:
            return found
        top = header_folder(cls, headers)
        found = None if top is None else clients(top, cls, header=True)
        named = named_header_folder(cls, headers) if found is None else None
        return found if named is None else clients(named, cls)
    return client


def _hiding(tu: TranslationUnit, errors: list[_Error],
            source: SourceCache, fieldless: set[str],
            functions: dict[str, list[recall.Function]],
            sites: dict[str, list[recall.Site]],
            clients: Callable[..., str | None] | None = None) -> list[_Error]:
    """Those of ``errors`` that can cost a call (``recall``): one outside every function
    the unit defines (a declaration: it may make a class invalid, and every call in its
    methods with it), one inside a function whose text calls the ROS API, or, with
    ``clients``, one on a qualified name the parse does not know that ``clients`` takes
    for a class of a ROS package that may make ROS calls of its own (vizzy's
    ``moveit::planning_interface::MoveGroupInterface group("right_arm");``, MoveIt's
    headers missing, in a function calling no API: declared, the class is one
    ``CallFinder._unseen_class`` says is built without its code). Errors
    only inside functions that make no ROS call, and those on fields of messages known
    only by name (clang reads on past them) but in a ROS call's arguments
    (``_in_ros_call``), are left as they are: declaring the names they miss would cost
    a parse and change no call. ``functions`` and ``sites`` hold
    the functions and the call sites of the files already read (the same in every
    parse of the unit)."""
    files = {e.path for e in errors if e.path is not None} - functions.keys()
    if files:
        found = recall.definitions(tu, files)
        functions.update({name: found.get(name, []) for name in files})
    kept = []
    for error in errors:
        name, line = error.path, error.line
        if name is None:
            continue
        if _names_fieldless_type(error.spelling, fieldless):
            if _in_ros_call(error, source, sites):
                kept.append(error)
            continue
        around = [f for f in functions.get(name, ()) if f[0] <= line <= f[1]]
        if not around:
            kept.append(error)
            continue
        if recall.holding(line, around, _sites(name, source, sites)) is not None or (
                clients is not None and _names_client_class(error, source, clients)):
            kept.append(error)
    return kept


def _written_name(error: _Error, name: str, lines: list[str]) -> str:
    """``name`` of ``error`` with the scopes written after it there (``quadrotor_common``
    of ``quadrotor_common::getParam``: the whole), without spaces; ``name`` when the
    error's place does not start with it."""
    text = lines[error.line - 1] if 0 < error.line <= len(lines) else ""
    written = re.match(re.escape(name) + r"(?:\s*::\s*\w+)+", text[max(error.column - 1, 0):])
    return re.sub(r"\s+", "", written.group(0)) if written is not None else name


def _names_client_class(error: _Error, source: SourceCache,
                        clients: Callable[..., str | None]) -> bool:
    """Whether ``error`` is on a name the parse does not know, written qualified
    (``pkg::ns::Class``), that ``clients`` takes for a class of a ROS package whose code
    may make ROS calls (``ros1_clients``)."""
    match = recall.UNKNOWN_NAME.search(error.spelling)
    lines = source.lines(error.path) if error.path is not None else None
    if match is None or lines is None:
        return False
    qualified = _written_name(error, match.group("name") or match.group("scope"), lines)
    return "::" in qualified and clients(qualified.split("::", 1)[0], qualified) is not None


_UNDECLARED = re.compile(r"^use of undeclared identifier '(\w+)'$")


# clang's errors about a declaration's default arguments, which GCC builds without a
# word (clearpath_platform's constructor defined ``(std::string node_name = "...")``
# after a declaration without one): the function and its body are read as written, so
# they hide no call
_DECLARATION_ONLY = re.compile(
    r"^(?:addition of default argument on redeclaration makes this \w+ a"
    r"|redefinition of default argument$)")

# clang's error about a reinterpret_cast of a value whose type the parse has wrong: code
# that builds casts only pointers and integers this way, so the value is one of code
# the parse does not read, a permissive value or a class declared by name (mapviz's
# ``reinterpret_cast<QGLMap*>(centralWidget())``, Qt's QMainWindow a stand-in without
# it; ``reinterpret_cast<Map*>(vendor::current())``, the vendor's header missing). The
# error spoils the cast's value alone, which nobody knows anyway; it hides a call only
# in the statement of one (``_in_ros_call``, asked by the caller), and a call lost with
# a variable it initialises is still found by its line (CPP_CALL_MISSED)
_PERMISSIVE_CAST = re.compile(r"^reinterpret_cast from '[^']+' to '[^']+' is not allowed$")


def _std_by_adl(error: _Error, source: SourceCache,
                declared: Callable[[str], frozenset[str]]) -> bool:
    """Whether ``error`` is an unqualified call of a function the unit's namespace std
    declares, which clang could not find: C++ finds it through its arguments' types
    (``make_pair(laser->getName(), laser)``), and those come from a header the parse
    lacks. A standard function makes no ROS call; the error hides one only in the
    statement of a ROS call (``_in_ros_call``, asked by the caller)."""
    match = _UNDECLARED.match(error.spelling)
    if match is None or match.group(1) not in declared("std") or error.path is None:
        return False
    lines = source.lines(error.path)
    if lines is None or not 0 < error.line <= len(lines):
        return False
    rest = lines[error.line - 1][error.column - 1:]
    return re.match(re.escape(match.group(1)) + r"\s*(?:<[^;()]*>\s*)?\(", rest) is not None


def _in_ros_call(error: _Error, source: SourceCache,
                 sites: dict[str, list[recall.Site]]) -> bool:
    """Whether ``error`` is inside the statement of a ROS API call site of its file
    (``recall.in_call``; ``sites`` holds each file's, found once). clang reads on past a
    field of a message known only by name, but not in a call's arguments: the call is
    lost with it (``declare_parameter(bond::msg::Constants::X, true)``)."""
    name = error.path
    lines = source.lines(name) if name is not None else None
    if name is None or lines is None:
        return False
    return recall.in_call(lines, _sites(name, source, sites), error.line)


class _Sites(dict[str, list[recall.Site]]):
    """The ROS API call sites of each file read (``recall.call_sites``), found once; with
    ``wrappers`` (names, and those called with no argument), the calls of the unit's
    own wrappers too (``_translation_unit``'s second synthesis)."""

    def __init__(self, wrappers: tuple[frozenset[str], frozenset[str]] | None = None
                 ) -> None:
        super().__init__()
        self.wrappers = wrappers or (frozenset(), frozenset())


def _sites(name: str, source: SourceCache, sites: dict[str, list[recall.Site]]
           ) -> list[recall.Site]:
    """The ROS API call sites of file ``name`` (``recall.call_sites``), found once: kept
    in ``sites`` (with the wrappers' calls when it is a ``_Sites`` that names them)."""
    if name not in sites:
        text = source.text(name)
        extra, bare = sites.wrappers if isinstance(sites, _Sites) else ((), ())
        sites[name] = recall.call_sites(text, extra, bare) if text else []
    return sites[name]


def _in_free(errors: list[_Error], functions: dict[str, list[recall.Function]],
             source: SourceCache, kind: int = recall.FREE) -> set[tuple[int, int]]:
    """The errors in a free function (``main``, a helper: a function, no class's
    method; ``synthesis.Names.in_free``), by their file's bytes and offset;
    ``functions``: the files' functions ``_hiding`` read. With ``kind``
    ``recall.BASES_READ``: those in a method of a class whose bases the parse reads
    whole (``synthesis.Names.in_read``)."""
    found = set()
    for error in errors:
        if error.name is None or error.path is None:
            continue
        around = [f for f in functions.get(error.path, ()) if f[0] <= error.line <= f[1]]
        if around and min(around, key=lambda f: f[1] - f[0])[3] == kind:
            found.add((id(source.get(error.name)), error.offset))
    return found


def _located(errors: list[_Error], source: SourceCache,
             tu: TranslationUnit | None = None) -> list[tuple[str, bytes | None, int]]:
    """Errors as ``synthesis.Names.learn`` reads them: message, file bytes, offset. An
    error about a name that a macro's definition writes, not its call (ateam_common's
    ``SET_ROS_PROTOBUF_LOG_HANDLER(name)``, whose ``google::protobuf::SetLogHandler``
    is unknown with protobuf's headers missing, is reported at the call), is placed
    where the definition writes it, in the header of ``tu`` that defines the macro:
    read at the call, the macro's own name was declared, and the error stayed."""
    found: list[tuple[str, bytes | None, int]] = []
    for e in errors:
        if e.name is None:
            continue
        text = source.get(e.name)
        for message in (e.spelling, *e.notes):
            at = _in_macro_definition(message, text, e.offset, tu, source)
            found.append(at if at is not None else (message, text, e.offset))
    return found


_MACRO_CALLED = re.compile(rb"([A-Za-z_]\w*)\s*\(")


def _in_macro_definition(message: str, text: bytes | None, offset: int,
                         tu: TranslationUnit | None, source: SourceCache
                         ) -> tuple[str, bytes, int] | None:
    """``(message, header bytes, offset)`` of the unknown name ``message`` is about,
    where the definition of the macro called at ``offset`` writes it; None when the
    name is written in the call (``_spelled_at`` finds it there) or the definition is
    in no header of ``tu`` the workspace holds."""
    unknown = recall.UNKNOWN_NAME.search(message)
    called = _MACRO_CALLED.match(text, offset) if text is not None and tu is not None \
        else None
    if unknown is None or called is None or text is None or tu is None:
        return None
    name = (unknown.group("name") or unknown.group("scope") or "").split("::")[0]
    macro = called.group(1).decode()
    if not name or name == macro or not synthesis.is_macro_name(macro):
        return None
    close = closing(text, called.end() - 1)
    word = re.compile(rb"(?<![\w.:>])" + re.escape(name.encode()) + rb"\b")
    if close is None or word.search(text, offset, close) is not None:
        return None
    defined = re.compile(rb"^[ \t]*#[ \t]*define[ \t]+" + re.escape(called.group(1))
                         + rb"\b(?:[^\n]*\\\r?\n)*[^\n]*", re.M)
    for header in _unit_headers(tu):
        data = source.get(header)
        definition = defined.search(data) if data is not None else None
        if data is None or definition is None:
            continue
        written = word.search(data, definition.start(), definition.end())
        return (message, data, written.start()) if written is not None else None
    return None


def _unit_headers(tu: TranslationUnit) -> list[str]:
    """The files ``tu`` includes (absolute paths, in order), read once per parse."""
    kept: list[str] | None = getattr(tu, "_haros_headers", None)
    if kept is None:
        kept = list(dict.fromkeys(os.path.abspath(i.include.name) for i in tu.get_includes()))
        tu._haros_headers = kept
    return kept


class SourceCache(dict[str, bytes]):
    """The bytes of the workspace files clang positions point into, read on demand."""

    def __init__(self, readable: Callable[[str], bool], initial: dict[str, bytes]) -> None:
        super().__init__(initial)
        self.readable = readable  # an absolute path of the workspace's folders
        self._texts: dict[str, str | None] = {}
        self._lines: dict[str, list[str] | None] = {}

    def text(self, name: str) -> str | None:
        """The file's text (decoded once: each error of a file asks for it)."""
        if name not in self._texts:
            data = self.get(name)
            self._texts[name] = data.decode("utf-8", "replace") if data is not None else None
        return self._texts[name]

    def lines(self, name: str) -> list[str] | None:
        """The file's lines (split once)."""
        if name not in self._lines:
            text = self.text(name)
            self._lines[name] = text.split("\n") if text is not None else None
        return self._lines[name]

    def get(self, name: str, default: bytes | None = None) -> bytes | None:  # type: ignore[override]
        name = os.path.abspath(name)
        if name in self:
            return self[name]
        if not self.readable(name):
            return default
        try:
            with open(name, "rb") as handle:
                data = handle.read(MAX_FILE_BYTES)
        except OSError:
            return default
        self[name] = data
        return data
