"""ROS calls the parse cannot see because the build defines a macro that chooses them.

A package built for ROS 1 and ROS 2 from one source tree picks its code with a macro its
CMakeLists.txt defines (livox_ros_driver2: ``add_definitions(-DBUILDING_ROS2)``, then
``#elif defined BUILDING_ROS2`` around every declaration and publisher). The extraction
applies the macros of a ``compile_commands.json`` only, not those of CMake commands, so a
block under such a macro is code this parse leaves out: when it holds a ROS API call, the
node says so (``CPP_BUILD_MACRO``), and is partial, rather than silently empty.
"""

from __future__ import annotations

import os
import re

from ... import diagnostics as diag
from ...diagnostics import Diagnostic
from ...files import read_text
from ...workspace import Workspace
from . import recall

# the CMake commands that define macros for the compiler, and what they define
_COMMAND = re.compile(r"\b(add_definitions|add_compile_definitions|target_compile_definitions)"
                      r"\s*\(([^)]*)\)", re.IGNORECASE)
_DEFINED = re.compile(r"(?:-D)?([A-Za-z_]\w*)(?:=[^\s)]*)?")
_WORD = re.compile(r"[A-Za-z_]\w*")
_KEYWORDS = frozenset({"PRIVATE", "PUBLIC", "INTERFACE", "defined"})
MAX_CMAKE_FILES = 40


def cmake_files(root: str) -> list[str]:
    """A package's CMake files (``CMakeLists.txt``, ``*.cmake``) under ``root``, in a
    stable order, not in hidden, build or install folders; at most ``MAX_CMAKE_FILES``."""
    files: list[str] = []
    for folder, dirs, names in os.walk(root):
        dirs[:] = sorted(d for d in dirs if not d.startswith((".", "build", "install")))
        files.extend(os.path.join(folder, n) for n in sorted(names)
                     if n == "CMakeLists.txt" or n.endswith(".cmake"))
        if len(files) >= MAX_CMAKE_FILES:
            break
    return files[:MAX_CMAKE_FILES]


def cmake_macros(root: str, workspace: Workspace) -> dict[str, tuple[str, int]]:
    """The macros a package's CMake files define, each with where (file, line)."""
    found: dict[str, tuple[str, int]] = {}
    for path in cmake_files(root):
        text, _ = read_text(path, workspace.location(path))
        for match in _COMMAND.finditer(text or ""):
            line = text.count("\n", 0, match.start()) + 1 if text else 0
            words = match.group(2).split()
            if match.group(1).lower() == "target_compile_definitions":
                words = words[1:]  # the target
            for word in words:
                if word.upper() in _KEYWORDS or "$" in word:
                    continue
                if match.group(1).lower() == "add_definitions" and not word.startswith("-D"):
                    continue
                named = _DEFINED.fullmatch(word)
                if named is not None:
                    found.setdefault(named.group(1), (path, line))
    return found


def skipped_calls(text: str, macros: dict[str, tuple[str, int]]
                  ) -> list[tuple[int, str, str]]:
    """(line, macro, call text) of the first ROS API call of each conditional block of
    ``text`` whose condition names one of ``macros``."""
    sites = recall.call_sites(text)
    if not sites:
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
        current = named[0] if named and kind in ("if", "ifdef", "elif") else None
        start = number
    for first, last, macro in blocks:
        site = recall.first_site(sites, first, last)
        if site is not None:
            found.append((site.line, macro, site.text))
    return found


def build_macro_calls(sources: list[str], macros: dict[str, tuple[str, int]],
                      workspace: Workspace) -> list[Diagnostic]:
    """``CPP_BUILD_MACRO`` at the first ROS call of each block of the node's sources that
    only one of ``macros`` (its package's CMake files', ``cmake_macros``) turns on."""
    if not macros:
        return []
    found: list[Diagnostic] = []
    for source in sources:
        text, _ = read_text(source, workspace.location(source))
        if not text:
            continue
        for line, macro, call in skipped_calls(text, macros):
            where, at = macros[macro]
            found.append(diag.make(
                "CPP_BUILD_MACRO", workspace.location(source, line), macro=macro,
                text=call.strip()[:80], cmake=f"{workspace.relpath(where)}:{at}"))
    return found
