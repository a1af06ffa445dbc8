"""Per-translation-unit flags from a ``compile_commands.json`` (CMake's
``CMAKE_EXPORT_COMPILE_COMMANDS``, catkin and colcon build folders).

The file is read as untrusted data, never run: it is bounded in size and entries, and
only the flags we understand are kept — include folders (``-I``, ``-isystem``,
``-iquote``) that lie inside the workspace or the build folder (system and ROS install
folders are left to our stand-ins, so results do not depend on what is installed),
macro definitions (``-D``, ``-U``) with plain names, and a C++ ``-std``. Everything else
(optimisation, warnings, ``-include``, plugins, response files) is ignored.

Where it is looked for (``find``): a path the project file names (``compile_commands``:
the file or its folder), else each workspace folder, its ``build/`` folder, the ``build/``
folder beside it (a ``src/`` workspace), and their per-package ``build/<pkg>/`` folders.
"""

from __future__ import annotations

import json
import os
import re
import shlex
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from . import diagnostics as diag
from .diagnostics import Diagnostic
from .workspace import Workspace

NAME = "compile_commands.json"
MAX_BYTES = 64 * 1024 * 1024
MAX_ENTRIES = 100_000
MAX_FLAGS = 2_000  # per entry
MAX_FILES = 256  # per-package files under build/
STANDARDS = frozenset(f"{lang}++{v}" for lang in ("c", "gnu")
                      for v in ("98", "03", "0x", "11", "1y", "14", "1z", "17", "2a", "20",
                                "2b", "23"))
_MACRO = re.compile(r"[A-Za-z_]\w{0,127}(=[^\n\r\0]{0,1024})?")
_INCLUDE_FLAGS = ("-I", "-isystem", "-iquote")


@dataclass(frozen=True)
class UnitFlags:
    """What one translation unit's compile command says that we use."""

    include_dirs: tuple[str, ...] = ()
    macros: tuple[str, ...] = ()  # "-DNAME=value" / "-UNAME", in order
    std: str | None = None  # "c++14", "gnu++17", ...

    def arguments(self) -> list[str]:
        args = [arg for folder in self.include_dirs for arg in ("-I", folder)]
        return [*args, *self.macros]


def find(workspace: Workspace, named: str | None = None) -> list[str]:
    """The compile_commands.json files to read, first wins for a source."""
    if named is not None:
        path = os.path.join(named, NAME) if os.path.isdir(named) else named
        return [path]
    found: list[str] = []
    for root in workspace.roots or [workspace.root]:
        for folder in dict.fromkeys([root, os.path.join(root, "build"),
                                     os.path.join(os.path.dirname(root), "build")]):
            candidates = [os.path.join(folder, NAME)]
            if os.path.basename(folder) == "build" and os.path.isdir(folder):
                try:
                    packages = sorted(os.listdir(folder))[:MAX_FILES]
                except OSError:
                    packages = []
                candidates += [os.path.join(folder, p, NAME) for p in packages]
            found += [c for c in candidates if os.path.isfile(c) and c not in found]
    return found


def load(paths: Sequence[str], workspace: Workspace) -> tuple[dict[str, UnitFlags],
                                                                 list[Diagnostic]]:
    """Each source file's flags (by real path), and what was wrong with the files;
    ``paths`` are files or the folders that hold them."""
    flags: dict[str, UnitFlags] = {}
    found: list[Diagnostic] = []
    for path in paths:
        if os.path.isdir(path):
            path = os.path.join(path, NAME)
        entries, problem = _read(path)
        if problem is not None:
            found.append(diag.make("CPP_COMPILE_COMMANDS", workspace.location(path),
                                   path=workspace.relpath(path), detail=problem))
            continue
        allowed = [*(workspace.roots or [workspace.root]), os.path.dirname(os.path.abspath(path))]
        for entry in entries:
            parsed = _entry(entry, allowed)
            if parsed is not None and parsed[0] not in flags:
                flags[parsed[0]] = parsed[1]
    return flags, found


def _read(path: str) -> tuple[list[object], str | None]:
    try:
        if os.path.getsize(path) > MAX_BYTES:
            return [], f"larger than {MAX_BYTES // (1024 * 1024)} MB"
        with open(path, encoding="utf-8") as handle:
            data = json.load(handle)
    except OSError as err:
        return [], err.strerror or str(err)
    except (ValueError, RecursionError) as err:
        return [], f"not valid JSON ({err})"[:200]
    if not isinstance(data, list):
        return [], "not a list of compile commands"
    return data[:MAX_ENTRIES], None


def _entry(entry: object, allowed: Sequence[str]) -> tuple[str, UnitFlags] | None:
    if not isinstance(entry, dict):
        return None
    folder, source = entry.get("directory"), entry.get("file")
    if not isinstance(folder, str) or not isinstance(source, str) or not os.path.isabs(folder):
        return None
    args = entry.get("arguments")
    if args is None and isinstance(entry.get("command"), str):
        try:
            args = shlex.split(entry["command"][:1_000_000])
        except ValueError:
            return None
    if not isinstance(args, list) or not all(isinstance(a, str) for a in args):
        return None
    return (os.path.realpath(os.path.join(folder, source)),
            _flags(args[1:MAX_FLAGS + 1], folder, allowed))


def _flags(args: Sequence[str], folder: str, allowed: Sequence[str]) -> UnitFlags:
    includes: list[str] = []
    macros: list[str] = []
    std: str | None = None
    items = iter(args)
    for arg in items:
        value: str | None = None
        for flag in (*_INCLUDE_FLAGS, "-D", "-U"):
            if arg == flag:
                value = next(items, None)
            elif arg.startswith(flag) and flag in ("-I", "-D", "-U"):
                value = arg[len(flag):]
            else:
                continue
            if value is None:
                break
            if flag in _INCLUDE_FLAGS:
                where = os.path.normpath(os.path.join(folder, value))
                if _inside(where, allowed) and os.path.isdir(where) and where not in includes:
                    includes.append(where)
            elif _MACRO.fullmatch(value) and (flag == "-D" or "=" not in value):
                macros.append(flag + value)
            break
        if arg.startswith("-std=") and arg[5:] in STANDARDS:
            std = arg[5:]
    return UnitFlags(tuple(includes), tuple(macros), std)


def valid_macro(text: str) -> bool:
    """A macro definition (``NAME`` or ``NAME=value``) kept as a ``-D`` flag."""
    return _MACRO.fullmatch(text) is not None


def _inside(path: str, folders: Iterable[str]) -> bool:
    return any(path == f or path.startswith(f.rstrip(os.sep) + os.sep) for f in folders)
