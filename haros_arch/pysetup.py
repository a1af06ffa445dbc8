"""ament_python packages: ``console_scripts`` entry points of setup.py / setup.cfg.

setup.py is read with ``ast`` and never run: its module-level statements go through the
one safe evaluator (``evaluate.module.run_module``) with setup.py's table of functions
(``setup_functions``: builtins, ``os.path`` on text, ``glob`` inside the package), so
``package_name = 'demo'``, ``+``, ``%``, f-strings, ``str.format`` and
``data_files.append(...)`` are followed; anything else is unknown and reported. Each
entry point ``name = pkg.module:main`` becomes
``Node(executable=name, kind="script", language="python", sources=[pkg/module.py])``.
"""

from __future__ import annotations

import ast
import configparser
import functools
import glob
import os
import posixpath
import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from . import diagnostics as diag
from .diagnostics import Diagnostic
from .evaluate import syntax
from .evaluate.module import Module, run_module
from .evaluate.python import BUILTINS
from .files import read_text
from .model.location import Location
from .model.source import Node, Package
from .workspace import Workspace

_ENTRY = re.compile(r"^\s*([\w.\-]+)\s*=\s*([\w.]+)\s*(?::\s*([\w.]+))?\s*(\[.*\])?\s*$")


@dataclass
class EntryPoint:
    name: str
    module: str
    location: Location
    function: str | None = None  # ``main`` of ``pkg.module:main``; None: the module


def parse_package(package: Package, workspace: Workspace,
                  environment: Mapping[str, str] | None = None
                  ) -> tuple[list[Node], list[Diagnostic]]:
    """The runnable Python nodes of an ament_python package, with their module files;
    setup.py read in ``environment`` (default: the workspace's)."""
    found: list[Diagnostic] = []
    entries: list[EntryPoint] = []
    package_dir: dict[str, str] = {}
    setup_py = os.path.join(package.root, "setup.py")
    if os.path.isfile(setup_py):
        more, package_dir = _from_setup_py(
            setup_py, workspace, found,
            workspace.environment if environment is None else environment)
        entries.extend(more)
    setup_cfg = os.path.join(package.root, "setup.cfg")
    if os.path.isfile(setup_cfg):
        more, cfg_dirs = _from_setup_cfg(setup_cfg, workspace, found)
        entries.extend(e for e in more if e.name not in {x.name for x in entries})
        package_dir = package_dir or cfg_dirs
    return _entry_nodes(package, workspace, entries, package_dir, found), found


def setup_cfg_nodes(package: Package, workspace: Workspace
                    ) -> tuple[list[Node], list[Diagnostic]]:
    """The entry points of a CMake-built package's setup.cfg, which ament_cmake_python's
    ``ament_python_install_package(pkg SCRIPTS_DESTINATION lib/pkg)`` installs as
    executables (controller_manager's ``spawner``)."""
    found: list[Diagnostic] = []
    setup_cfg = os.path.join(package.root, "setup.cfg")
    if not os.path.isfile(setup_cfg):
        return [], found
    entries, package_dir = _from_setup_cfg(setup_cfg, workspace, found)
    return _entry_nodes(package, workspace, entries, package_dir, found), found


def _entry_nodes(package: Package, workspace: Workspace, entries: list[EntryPoint],
                 package_dir: dict[str, str], found: list[Diagnostic]) -> list[Node]:
    nodes = []
    for entry in entries:
        module = module_file(package.root, entry.module, package_dir)
        if module is None:
            found.append(diag.make("PYSETUP_MODULE_MISSING", entry.location,
                                   module=entry.module, name=entry.name))
        nodes.append(Node(package.name, entry.name, "script", "python",
                          [workspace.relpath(module)] if module else [],
                          location=entry.location,
                          entry=entry.function if entry.function is not None else ""))
    return nodes


def module_file(root: str, module: str, package_dir: dict[str, str]) -> str | None:
    """``pkg.sub.mod`` → the file that defines it, honouring ``package_dir``."""
    parts = module.split(".")
    for cut in range(len(parts), -1, -1):
        prefix = ".".join(parts[:cut])
        if prefix in package_dir:
            base = os.path.join(root, package_dir[prefix], *parts[cut:])
            break
    else:
        base = os.path.join(root, *parts)
    for candidate in (base + ".py", os.path.join(base, "__init__.py")):
        if os.path.isfile(candidate):
            return candidate
    return None


def parse_entry(text: str) -> tuple[str, str, str | None] | None:
    """``name = pkg.module:main [extra]`` → (name, module, function)."""
    match = _ENTRY.match(text)
    return (match.group(1), match.group(2), match.group(3)) if match else None


# -- setup.py ----------------------------------------------------------------------
SETUP_CALLS = ("setup", "setuptools.setup", "distutils.core.setup")


def _text_args(*args: Any) -> list[str]:
    if not all(isinstance(a, str) for a in args):
        raise TypeError("a path of values not known statically")
    return list(args)


def setup_functions(root: str, environment: Mapping[str, str] | None = None
                    ) -> dict[str, Any]:
    """What setup.py may call for us: safe builtins, ``os.path`` on text, ``glob`` from the
    package folder and inside it (nothing else is called, nothing is run); and, given the
    run's ``environment``, ``os.environ`` / ``os.getenv`` over it (the distribution's
    ROS_VERSION: ros-bridge's ``if int(os.environ['ROS_VERSION']) == 2:`` around the ROS 2
    ``setup()`` and the names it uses)."""

    def exists(test: Any) -> Any:
        def call(path: Any) -> bool:
            (text,) = _text_args(path)
            if os.path.isabs(text) or ".." in text.split("/"):
                raise ValueError("only paths inside the package are looked at")
            return bool(test(os.path.join(root, text)))
        return call

    def globbed(pattern: Any, recursive: bool = False) -> list[str]:
        (text,) = _text_args(pattern)
        if os.path.isabs(text) or ".." in text.split("/"):
            raise ValueError("glob outside the package is not run")
        out: list[str] = []
        for match in glob.iglob(text, root_dir=root, recursive=recursive is True):
            out.append(match.replace(os.sep, "/"))
            if len(out) > MAX_GLOB:
                raise OverflowError(f"glob gives more than {MAX_GLOB} files")
        return sorted(out)

    join = lambda *a: posixpath.join(*_text_args(*a))  # noqa: E731
    table: dict[str, Any] = {
        **BUILTINS, "os.path.join": join, "posixpath.join": join,
        "os.path.dirname": lambda p: posixpath.dirname(*_text_args(p)),
        "os.path.basename": lambda p: posixpath.basename(*_text_args(p)),
        "os.path.isfile": exists(os.path.isfile), "os.path.isdir": exists(os.path.isdir),
        "glob.glob": globbed,
    }
    if environment is not None:
        table.update(environment_functions(environment))
    return table


def environment_functions(environment: Mapping[str, str]) -> dict[str, Any]:
    """``os.environ`` and ``os.getenv`` over the distribution's variables of
    ``environment`` (``DISTRO_VARIABLES``); any other variable is not known."""
    known = _Environment({k: v for k, v in environment.items() if k in DISTRO_VARIABLES})
    return {"os.environ": known,
            "os.getenv": lambda name, default=None: known.get(name, default)}


# the variables a ROS distribution's setup script sets, which a build has as the run
# gives them; any other is the builder's shell's, not known here
DISTRO_VARIABLES = frozenset({"ROS_VERSION", "ROS_DISTRO", "ROS_PYTHON_VERSION"})


class _Environment(dict[str, str]):
    """``os.environ`` of setup.py: the distribution's variables (``DISTRO_VARIABLES``);
    any other is not known (neither its value nor whether it is set), not absent."""

    def get(self, key: Any, default: Any = None) -> Any:
        if key in self.keys():
            return self[key]
        raise LookupError(f"environment variable {key} is not known here")

    def __contains__(self, key: object) -> bool:
        if key in self.keys():
            return True
        raise LookupError(f"environment variable {key} is not known here")


MAX_GLOB = 2_000


def setup_module(tree: ast.Module, root: str,
                 environment: Mapping[str, str] | None = None) -> Module:
    """setup.py's module-level names, run over known values only (an ``if`` of a test
    known there, over ``environment`` too, runs its branch), and its ``setup()`` calls
    (collected, never run)."""
    return run_module(tree, setup_functions(root, environment), calls=SETUP_CALLS)


def _from_setup_py(path: str, workspace: Workspace,
                   found: list[Diagnostic], environment: Mapping[str, str]
                   ) -> tuple[list[EntryPoint], dict[str, str]]:
    text, problems = read_text(path, workspace.location(path))
    found.extend(problems)
    if text is None:
        return [], {}
    try:
        tree = syntax.parse(text, path)
    except (SyntaxError, ValueError, RecursionError, MemoryError) as err:
        line = getattr(err, "lineno", 0) or 0
        column = getattr(err, "offset", 0) or 0
        found.append(diag.make("PYSETUP_SYNTAX", workspace.location(path, line, column),
                               detail=getattr(err, "msg", str(err))))
        return [], {}
    module = setup_module(tree, os.path.dirname(path), environment)
    entries, package_dir = _from_setup_call(module, tree, path, workspace, found)
    if module.limited is not None:  # what came after the bound is unknown: said once
        unknown, node = module.limited
        found.append(diag.make("PYSETUP_DYNAMIC", workspace.location(
            path, getattr(node, "lineno", 0), getattr(node, "col_offset", -1) + 1),
            detail=f"setup.py ({unknown.reason})"))
    return entries, package_dir


def _from_setup_call(module: Module, tree: ast.Module, path: str, workspace: Workspace,
                     found: list[Diagnostic]) -> tuple[list[EntryPoint], dict[str, str]]:
    if not module.calls:
        return [], {}
    call = module.calls[-1]
    assigned = {s.targets[0].id: s.value for s in tree.body if isinstance(s, ast.Assign)
                and len(s.targets) == 1 and isinstance(s.targets[0], ast.Name)}
    entries: list[EntryPoint] = []
    package_dir: dict[str, str] = {}
    for keyword in _keywords(call, module, assigned, _items_set(tree)):
        if keyword.arg == "package_dir":
            value = module.value(keyword.value)
            if isinstance(value, dict):
                package_dir = {k: v for k, v in value.items()
                               if isinstance(k, str) and isinstance(v, str)}
        if keyword.arg != "entry_points":
            continue
        node = keyword.value
        if isinstance(node, ast.Name) and node.id in assigned:
            node = assigned[node.id]  # entry_points=ENTRY_POINTS defined above
        entries.extend(_console_scripts(node, module, path, workspace, found))
    return entries, package_dir


# catkin_pkg's helper whose result ROS 1 packages pass to setup(): its keyword arguments,
# with what package.xml says added (``setup(**generate_distutils_setup(packages=[..],
# package_dir={'': 'src'}))``)
CATKIN_SETUP = "catkin_pkg.python_setup.generate_distutils_setup"


def _keywords(call: ast.Call, module: Module, assigned: dict[str, ast.expr],
              items: dict[str, dict[str, ast.expr]] | None = None) -> list[ast.keyword]:
    """The keyword arguments of a setup() call, with those of a ``**`` argument that is
    catkin's ``generate_distutils_setup(...)`` (or a name assigned one) in its place,
    and the items the module's own code then sets on that name (``d['package_dir'] =
    {'': 'python'}``, ``items``: object_recognition_ros' setup.py), which replace the
    call's keywords of those names, as setup() gets the dict."""
    found: list[ast.keyword] = []
    for keyword in call.keywords:
        node = keyword.value
        if keyword.arg is not None:
            found.append(keyword)
            continue
        named = node.id if isinstance(node, ast.Name) else None
        if named is not None and named in assigned:
            node = assigned[named]
        if isinstance(node, ast.Call) and module.qualified(node.func) == CATKIN_SETUP:
            later = (items or {}).get(named or "", {})
            found.extend(k for k in node.keywords if k.arg is not None and k.arg not in later)
            found.extend(ast.keyword(arg=key, value=value) for key, value in later.items())
    return found


def _items_set(tree: ast.Module) -> dict[str, dict[str, ast.expr]]:
    """The items the module's top-level code sets on a name by a text key (``d['packages']
    = [...]``), by name, the last value of each key."""
    found: dict[str, dict[str, ast.expr]] = {}
    for statement in tree.body:
        if not (isinstance(statement, ast.Assign) and len(statement.targets) == 1):
            continue
        target = statement.targets[0]
        if isinstance(target, ast.Subscript) and isinstance(target.value, ast.Name) \
                and isinstance(target.slice, ast.Constant) \
                and isinstance(target.slice.value, str):
            found.setdefault(target.value.id, {})[target.slice.value] = statement.value
    return found


def python_folders(root: str) -> tuple[str, ...]:
    """The folders (absolute) in which the package at ``root`` keeps the Python packages
    its setup.py installs, as ``package_dir`` places them: its ``''`` entry (duckietown's
    ``package_dir={'': 'include'}``), and the parent of a named package's folder that
    has the package's name (``{'pkg': 'lib/pkg'}``). Nothing for a package without a
    setup.py or one that gives no ``package_dir`` (the caller looks in ``src/`` and the
    package folder, the common layouts); setup.py's problems are said where it is
    read as a build file (``parse_package``), not here."""
    path = os.path.join(root, "setup.py")
    try:
        stat = os.stat(path)
    except OSError:
        return ()
    return _python_folders(path, stat.st_mtime_ns, stat.st_size)


@functools.lru_cache(maxsize=256)
def _python_folders(path: str, _mtime: int, _size: int) -> tuple[str, ...]:
    workspace = Workspace(os.path.dirname(path))
    _, package_dir = _from_setup_py(path, workspace, [], workspace.environment)
    root = os.path.dirname(path)
    folders = []
    for name, folder in package_dir.items():
        if os.path.isabs(folder) or ".." in folder.replace("\\", "/").split("/"):
            continue  # only folders inside the package
        place = os.path.normpath(os.path.join(root, folder))
        if name == "":
            folders.append(place)
        elif "." not in name and os.path.basename(place) == name:
            folders.append(os.path.dirname(place))
    return tuple(dict.fromkeys(f for f in folders if os.path.isdir(f)))


def _console_scripts(node: ast.expr, module: Module, path: str,
                     workspace: Workspace, found: list[Diagnostic]) -> list[EntryPoint]:
    where = workspace.location(path, node.lineno, node.col_offset + 1)
    items: list[ast.expr] = []
    if isinstance(node, ast.Dict):
        for key, value in zip(node.keys, node.values, strict=False):
            if key is not None and module.value(key) == "console_scripts":
                items = list(value.elts) if isinstance(value, (ast.List, ast.Tuple)) else [value]
    else:
        computed = module.value(node)
        if isinstance(computed, dict):
            lines = _entry_lines(computed.get("console_scripts", []))
            if lines is None:
                found.append(diag.make("PYSETUP_DYNAMIC", where, detail="a console script"))
            return [EntryPoint(*parsed[:2], where, parsed[2]) for s in lines or []
                    if (parsed := parse_entry(s))]
        found.append(diag.make("PYSETUP_DYNAMIC", where, detail="entry_points"))
        return []
    entries: list[EntryPoint] = []
    while items:
        item = items.pop(0)
        if isinstance(item, (ast.List, ast.Tuple)):  # setuptools flattens nested lists
            items[:0] = item.elts
            continue
        item_where = workspace.location(path, item.lineno, item.col_offset + 1)
        lines = _entry_lines(module.value(item))
        results = [parse_entry(s) for s in lines] if lines is not None else [None]
        if None in results:
            found.append(diag.make("PYSETUP_DYNAMIC", item_where, detail="a console script"))
        entries.extend(EntryPoint(r[0], r[1], item_where, r[2])
                       for r in results if r is not None)
    return entries


def _entry_lines(value: Any) -> list[str] | None:
    """The entry-point lines of a console_scripts value as setuptools reads them: a
    string is split into lines (blank and ``#`` lines dropped), a list or tuple is
    flattened, nested; None when some part is not a string."""
    if isinstance(value, str):
        return [t for line in value.splitlines()
                if (t := line.strip()) and not t.startswith("#")]
    if isinstance(value, (list, tuple)):
        out: list[str] = []
        for part in value:
            lines = _entry_lines(part)
            if lines is None:
                return None
            out.extend(lines)
        return out
    return None


# -- setup.cfg ---------------------------------------------------------------------
def _from_setup_cfg(path: str, workspace: Workspace,
                    found: list[Diagnostic]) -> tuple[list[EntryPoint], dict[str, str]]:
    text, problems = read_text(path, workspace.location(path))
    found.extend(problems)
    if text is None:
        return [], {}
    parser = configparser.RawConfigParser(strict=False)
    try:
        parser.read_string(text, source=path)
    except configparser.Error as err:
        line = getattr(err, "lineno", 0) or 0
        found.append(diag.make("PYSETUP_SYNTAX", workspace.location(path, line, 0),
                               detail=str(err).splitlines()[0]))
        return [], {}
    lines = text.splitlines()
    entries = []
    if parser.has_option("options.entry_points", "console_scripts"):
        for raw in parser.get("options.entry_points", "console_scripts").splitlines():
            parsed = parse_entry(raw) if raw.strip() else None
            if parsed is None:
                continue
            line = next((n for n, t in enumerate(lines, 1)
                         if t.strip().startswith(parsed[0]) and "=" in t), 0)
            entries.append(EntryPoint(parsed[0], parsed[1], workspace.location(path, line, 1),
                                      parsed[2]))
    package_dir: dict[str, str] = {}
    if parser.has_option("options", "package_dir"):
        for raw in parser.get("options", "package_dir").splitlines():
            key, sep, value = raw.partition("=")
            if sep:
                package_dir[key.strip()] = value.strip()
    return entries, package_dir
