"""The macros a package's CMake files define, applied to the parse where they are known,
and the ROS calls the parse cannot see where they are not.

A package built for ROS 1 and ROS 2 from one source tree picks its code with a macro its
CMakeLists.txt defines (livox_ros_driver2: ``add_definitions(-DBUILDING_ROS2)``, then
``#elif defined BUILDING_ROS2`` around every declaration and publisher); depthai_examples
names a file with ``target_compile_definitions(mobilenet_node PRIVATE
BLOB_NAME="${mobilenet_blob_name}")``. Where no ``compile_commands.json`` gives a source's
flags (they win: they are the build's own), ``cmake_flags`` gives the ``-D`` flags of the
targets that compile it (``cmake.source_definitions``), each once every such target
defines it alike and no undecided ``if()`` guards it. A value that reads something the
CMake reading does not know is defined as ``UNKNOWN_VALUE``: an identifier nothing
declares, so that what it gives is unknown, not empty (``#ifdef`` still holds), and the
parse error it makes names the macro.

A macro the CMake files define that the reading does not decide for a source (under an
undecided condition, given two values, or defined in code the reading does not run or
through a command it does not read) leaves a block this parse may not see: when it
holds a ROS API call, the node says so (``CPP_BUILD_MACRO``), and is partial, rather
than silently empty.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Container

from ... import diagnostics as diag
from ...compile_commands import valid_macro
from ...diagnostics import Diagnostic
from ...files import package_files, read_text
from ...workspace import Workspace
from . import recall

# the CMake commands that define macros for the compiler, and what they define
_COMMAND = re.compile(r"\b(add_definitions|add_compile_definitions|target_compile_definitions"
                      r"|add_compile_options|target_compile_options)"
                      r"\s*\(([^)]*)\)", re.IGNORECASE)
_DEFINED = re.compile(r"(?:-D)?([A-Za-z_]\w*)(?:=[^\s)]*)?")
_WORD = re.compile(r"[A-Za-z_]\w*")
_KEYWORDS = frozenset({"PRIVATE", "PUBLIC", "INTERFACE", "defined"})
MAX_CMAKE_FILES = 40
# what a macro whose value is not known holds: an identifier nothing declares, in
# parentheses (``std::string s(NAME)`` stays an expression, not a function declaration)
UNKNOWN_VALUE = "(haros_cmake_value_unknown_{})"


def cmake_flags(source: str, workspace: Workspace) -> list[str]:
    """The ``-D`` flags of the macros the CMake targets that compile ``source`` (an
    absolute path) define, each where every one of them defines it alike and no
    undecided condition guards it; none for a source no target of its package lists."""
    return _cmake_macros(source, workspace)[0]


def cmake_standard(source: str, workspace: Workspace) -> str | None:
    """The ``-std`` value (``c++20``) the CMake targets that compile ``source`` (an
    absolute path) ask when newer than the parse's default (``cmake.source_standards``);
    None for the default."""
    from ...cmake import source_standards

    package = workspace.package_of(source)
    if package is None:
        return None
    return source_standards(package, workspace).get(workspace.relpath(source))


def _cmake_macros(source: str, workspace: Workspace
                  ) -> tuple[list[str], set[str], dict[str, tuple[str, int]]]:
    """``cmake_flags``; the names of the macros whose presence the CMake reading decides
    for ``source``: those flags', and those it records for other targets of the package
    only (not defined here); and those of the flags whose value is not known, each with
    where (file, line) it is defined."""
    from ...cmake import CONFLICT, absent_definitions, source_definitions

    package = workspace.package_of(source)
    if package is None:
        return [], set(), {}
    found = source_definitions(package, workspace)
    per_target = found.get(workspace.relpath(source))
    if not per_target:
        return [], set(), {}
    flags: list[str] = []
    valued: dict[str, tuple[str, int]] = {}
    own = {name for defined in per_target for name in defined}
    # known absent: defined only for other targets, or only in branches not taken
    settled = ({name for targets in found.values() for defined in targets for name in defined}
               | absent_definitions(package, workspace)) - own
    first, *others = per_target
    for name, each in first.items():
        if each is CONFLICT or each.conditions or any(o.get(name) != each for o in others):
            continue
        value = each.value if each.known else UNKNOWN_VALUE.format(name)
        flag = name if value is None else f"{name}={value}"
        if valid_macro(flag):
            flags.append("-D" + flag)
            settled.add(name)
            if not each.known:
                valued[name] = (each.file, each.line)
    return flags, settled, valued


def cmake_files(root: str) -> list[str]:
    """A package's CMake files (``CMakeLists.txt``, ``*.cmake``) under ``root``, in a
    stable order, not in hidden, build or install folders; at most ``MAX_CMAKE_FILES``."""
    files: list[str] = []
    for path in package_files(root):
        name = os.path.basename(path)
        if name == "CMakeLists.txt" or name.endswith(".cmake"):
            files.append(path)
            if len(files) >= MAX_CMAKE_FILES:
                break
    return files


# a target's COMPILE_DEFINITIONS property (``set_property(TARGET t PROPERTY
# COMPILE_DEFINITIONS X Y)``, ``set_target_properties(t PROPERTIES COMPILE_DEFINITIONS
# "X;Y=1" ...)``): the values after the property's name (of set_target_properties the
# one argument)
_PROPERTY = re.compile(r"\b(set_property|set_target_properties)\s*\(([^)]*)\)", re.IGNORECASE)
_PROPERTY_VALUES = re.compile(r"\bCOMPILE_DEFINITIONS\s+(\"[^\"]*\"|\S+)((?:\s+\S+)*)")


def cmake_macros(root: str, workspace: Workspace) -> dict[str, tuple[str, int]]:
    """The macros a package's CMake files define, each with where (file, line)."""
    found: dict[str, tuple[str, int]] = {}
    for path in cmake_files(root):
        text, _ = read_text(path, workspace.location(path))
        for match in _PROPERTY.finditer(text or ""):
            values = _PROPERTY_VALUES.search(match.group(2))
            if values is None:
                continue
            line = text.count("\n", 0, match.start()) + 1 if text else 0
            words = values.group(1).strip('"').split(";")
            if match.group(1).lower() == "set_property":
                words += values.group(2).split()
            for word in words:
                named = _DEFINED.fullmatch(word.strip())
                if named is not None and "$" not in word:
                    found.setdefault(named.group(1), (path, line))
        for match in _COMMAND.finditer(text or ""):
            line = text.count("\n", 0, match.start()) + 1 if text else 0
            words = match.group(2).split()
            command = match.group(1).lower()
            if command.startswith("target_"):
                words = words[1:]  # the target
            for word in words:
                if word.upper() in _KEYWORDS or "$" in word:
                    continue
                if (command in ("add_definitions", "add_compile_options", "target_compile_options")
                        and not word.startswith("-D")):
                    continue
                named = _DEFINED.fullmatch(word)
                if named is not None:
                    found.setdefault(named.group(1), (path, line))
    return found


_DEFINED_TEST = re.compile(r"\bdefined\s*(?:\(\s*\w+\s*\)|\w+)")


def skipped_calls(text: str, macros: Container[str],
                  valued: frozenset[str] = frozenset(),
                  included: Callable[[str], str | None] | None = None
                  ) -> list[tuple[int, str, str]]:
    """(line, macro, call text) of the first ROS API call of each conditional block of
    ``text`` whose condition names one of ``macros``, or tests the value of one of
    ``valued`` (``#if X >= 2``; not ``#ifdef X`` nor ``defined(X)``). ``included``: the
    first ROS API call of a header an ``#include`` of the block names (None where it
    has none or is not found), which counts as the block's where the block has none of
    its own (ethzasl_sensor_fusion's ``#ifdef POSE_MEAS`` / ``#include
    "pose_measurements.h"``, whose class reads the filter's parameters)."""
    sites = recall.call_sites(text)
    if not sites and included is None:
        return []
    lines = text.splitlines()
    found: list[tuple[int, str, str]] = []
    current: str | None = None  # the build macro the open branch's condition names
    start = 0
    blocks: list[tuple[int, int, str]] = []
    for number, line in enumerate(lines, 1):
        match = recall.DIRECTIVE.match(line)
        if match is None:
            continue
        kind, rest = match.group(1), match.group(2)
        if current is not None:  # every directive ends the open branch
            blocks.append((start, number, current))
        if kind == "endif":
            current = None
            continue
        named = [w for w in _WORD.findall(rest) if w in macros] if kind != "else" else []
        if kind in ("if", "elif") and valued:
            named += [w for w in _WORD.findall(_DEFINED_TEST.sub(" ", rest)) if w in valued]
        current = named[0] if named and kind in ("if", "ifdef", "elif") else None
        start = number
    for first, last, macro in blocks:
        site = recall.first_site(sites, first, last)
        if site is not None:
            found.append((site.line, macro, site.text))
            continue
        for number in range(first + 1, last) if included is not None else ():
            written = _INCLUDE.match(lines[number - 1])
            call = included(written.group(1)) if written is not None and (
                included is not None) else None
            if call is not None:
                found.append((number, macro, f"{lines[number - 1].strip()} ({call})"))
                break
    return found


_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')


def _header_call(source: str, workspace: Workspace) -> Callable[[str], str | None]:
    """The first ROS API call of the workspace header an ``#include`` of ``source``
    names: beside the source, or in the ``include`` folder of its package or of another
    workspace package; None where there is none or the header is not found."""
    package = workspace.package_of(source)
    folders = [os.path.dirname(source)]
    if package is not None:
        folders.append(os.path.join(package.root, "include"))
    folders += [os.path.join(p.root, "include") for p in workspace.packages.values()
                if package is None or p.root != package.root]

    def first_call(name: str) -> str | None:
        for folder in folders:
            path = os.path.normpath(os.path.join(folder, name))
            if os.path.isfile(path):
                text, _ = read_text(path, workspace.location(path))
                sites = recall.call_sites(text or "")
                return sites[0].text.strip() if sites else None
        return None
    return first_call


_SKIPPED: dict[tuple[str, str, frozenset[str], frozenset[str]],
               tuple[tuple[int, str, str], ...]] = {}


def _skipped(source: str, text: str, macros: frozenset[str], valued: frozenset[str],
             workspace: Workspace) -> tuple[tuple[int, str, str], ...]:
    """``skipped_calls`` of a source, asked once per text and macros: the plugin classes
    of one library are nodes with the same sources."""
    key = (source, text, macros, valued)
    if key not in _SKIPPED:
        if len(_SKIPPED) > 512:
            _SKIPPED.clear()
        _SKIPPED[key] = tuple(skipped_calls(text, macros, valued,
                                            _header_call(source, workspace)))
    return _SKIPPED[key]


def build_macro_calls(sources: list[str], macros: dict[str, tuple[str, int]],
                      workspace: Workspace) -> list[Diagnostic]:
    """``CPP_BUILD_MACRO`` at the first ROS call of each block of the node's sources, and
    of the headers of their package they include (``package_headers``), that only one of
    ``macros`` (its package's CMake files', ``cmake_macros``) turns on, unless the CMake
    reading decides that macro for the source (given to its parse, or defined for other
    targets only: ``_cmake_macros``), and of each block whose condition tests the value
    of a macro given with its value unknown. A header's block is said once for the
    node."""
    found: list[Diagnostic] = []
    done: set[tuple[str, int]] = set()
    for source in sources:
        _, settled, valued = _cmake_macros(source, workspace)
        left = {name: where for name, where in macros.items() if name not in settled}
        if not left and not valued:
            continue
        for path in [source, *package_headers(source, workspace)]:
            text, _ = read_text(path, workspace.location(path))
            if not text:
                continue
            for line, macro, call in _skipped(path, text, frozenset(left),
                                              frozenset(valued), workspace):
                if (path, line) in done:
                    continue
                done.add((path, line))
                where, at = left.get(macro) or valued[macro]
                named = macro if macro in left else f"{macro} (its value not known)"
                found.append(diag.make(
                    "CPP_BUILD_MACRO", workspace.location(path, line), macro=named,
                    text=call.strip()[:80], cmake=f"{workspace.relpath(where)}:{at}"))
    return found


MAX_HEADERS = 64  # the headers of its package one source includes, followed


def package_headers(source: str, workspace: Workspace) -> list[str]:
    """The headers of ``source``'s package that it includes, directly or through one
    another (at most ``MAX_HEADERS``): each ``#include`` found beside the file that
    writes it or in the package's ``include`` folder. ros_deep_learning's nodes choose
    their ROS calls in ros_compat.h (``#ifdef ROS1`` / ``#elif ROS2`` around the macros
    they call, ``ROS_DECLARE_PARAMETER``, ``ROS_CREATE_PUBLISHER``), where the CMake
    defines ROS1 or ROS2 under ``if(catkin_FOUND)``, not decided: the nodes were read
    with no call and complete (34 "set but never read" and 7 "remap that changes no
    name" warnings)."""
    package = workspace.package_of(source)
    if package is None or not package.root:
        return []
    key = (source, package.root)
    if key not in _HEADERS:
        if len(_HEADERS) > 512:
            _HEADERS.clear()
        _HEADERS[key] = tuple(_follow(source, package.root, workspace))
    return list(_HEADERS[key])


_HEADERS: dict[tuple[str, str], tuple[str, ...]] = {}


def _follow(source: str, root: str, workspace: Workspace) -> list[str]:
    inside = os.path.join(os.path.abspath(root), "")
    found: list[str] = []
    seen = {os.path.abspath(source)}
    queue = [os.path.abspath(source)]
    while queue and len(found) < MAX_HEADERS:
        current = queue.pop(0)
        text, _ = read_text(current, workspace.location(current))
        for line in (text or "").splitlines():
            written = _INCLUDE.match(line)
            if written is None:
                continue
            for folder in (os.path.dirname(current), os.path.join(root, "include")):
                path = os.path.normpath(os.path.join(folder, written.group(1)))
                if path.startswith(inside) and path not in seen and os.path.isfile(path):
                    seen.add(path)
                    found.append(path)
                    queue.append(path)
                    break
            if len(found) >= MAX_HEADERS:
                break
    return found
