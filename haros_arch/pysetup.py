"""ament_python packages: ``console_scripts`` entry points of setup.py / setup.cfg.

setup.py is read with ``ast`` and never run: module-level assignments of literals
(``package_name = 'demo'``) are followed, and strings built with ``+``, ``%``,
f-strings and plain ``str.format`` are computed by our own evaluator; anything else
is unknown and reported. Each entry point ``name = pkg.module:main`` becomes
``Node(executable=name, kind="script", language="python", sources=[pkg/module.py])``.
"""

from __future__ import annotations

import ast
import configparser
import os
import re
from dataclasses import dataclass

from . import diagnostics as diag
from .diagnostics import Diagnostic
from .evaluate import budget, syntax
from .files import read_text
from .model.location import Location
from .model.source import Node, Package
from .workspace import Workspace

_ENTRY = re.compile(r"^\s*([\w.\-]+)\s*=\s*([\w.]+)\s*(?::\s*([\w.]+))?\s*(\[.*\])?\s*$")


class _Unknown:
    pass


UNKNOWN = _Unknown()


@dataclass
class EntryPoint:
    name: str
    module: str
    location: Location


def parse_package(package: Package, workspace: Workspace) -> tuple[list[Node], list[Diagnostic]]:
    """The runnable Python nodes of an ament_python package, with their module files."""
    found: list[Diagnostic] = []
    entries: list[EntryPoint] = []
    package_dir: dict[str, str] = {}
    setup_py = os.path.join(package.root, "setup.py")
    if os.path.isfile(setup_py):
        more, package_dir = _from_setup_py(setup_py, workspace, found)
        entries.extend(more)
    setup_cfg = os.path.join(package.root, "setup.cfg")
    if os.path.isfile(setup_cfg):
        more, cfg_dirs = _from_setup_cfg(setup_cfg, workspace, found)
        entries.extend(e for e in more if e.name not in {x.name for x in entries})
        package_dir = package_dir or cfg_dirs
    nodes = []
    for entry in entries:
        module = module_file(package.root, entry.module, package_dir)
        if module is None:
            found.append(diag.make("PYSETUP_MODULE_MISSING", entry.location,
                                   module=entry.module, name=entry.name))
        nodes.append(Node(package.name, entry.name, "script", "python",
                          [workspace.relpath(module)] if module else [],
                          location=entry.location))
    return nodes, found


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


def parse_entry(text: str) -> tuple[str, str] | None:
    """``name = pkg.module:main [extra]`` → (name, module)."""
    match = _ENTRY.match(text)
    return (match.group(1), match.group(2)) if match else None


# -- setup.py ----------------------------------------------------------------------
def _from_setup_py(path: str, workspace: Workspace,
                   found: list[Diagnostic]) -> tuple[list[EntryPoint], dict[str, str]]:
    text, problems = read_text(path, workspace.location(path))
    found.extend(problems)
    if text is None:
        return [], {}
    try:
        tree = syntax.parse(text, path)
    except (SyntaxError, ValueError, RecursionError) as err:
        line = getattr(err, "lineno", 0) or 0
        column = getattr(err, "offset", 0) or 0
        found.append(diag.make("PYSETUP_SYNTAX", workspace.location(path, line, column),
                               detail=getattr(err, "msg", str(err))))
        return [], {}
    names: dict[str, object] = {}
    assigned: dict[str, ast.expr] = {}  # module-level name -> its expression
    call: ast.Call | None = None
    for statement in tree.body:
        if isinstance(statement, ast.Assign) and len(statement.targets) == 1 and isinstance(
                statement.targets[0], ast.Name):
            names[statement.targets[0].id] = _value(statement.value, names)
            assigned[statement.targets[0].id] = statement.value
        for node in ast.walk(statement):
            if isinstance(node, ast.Call) and _callee(node) == "setup":
                call = node
    if call is None:
        return [], {}
    entries: list[EntryPoint] = []
    package_dir: dict[str, str] = {}
    for keyword in call.keywords:
        if keyword.arg == "package_dir":
            value = _value(keyword.value, names)
            if isinstance(value, dict):
                package_dir = {k: v for k, v in value.items()
                               if isinstance(k, str) and isinstance(v, str)}
        if keyword.arg != "entry_points":
            continue
        node = keyword.value
        if isinstance(node, ast.Name) and node.id in assigned:
            node = assigned[node.id]  # entry_points=ENTRY_POINTS defined above
        entries.extend(_console_scripts(node, names, path, workspace, found))
    return entries, package_dir


def _console_scripts(node: ast.expr, names: dict[str, object], path: str,
                     workspace: Workspace, found: list[Diagnostic]) -> list[EntryPoint]:
    where = workspace.location(path, node.lineno, node.col_offset + 1)
    items: list[ast.expr] = []
    if isinstance(node, ast.Dict):
        for key, value in zip(node.keys, node.values, strict=False):
            if key is not None and _value(key, names) == "console_scripts":
                items = list(value.elts) if isinstance(value, (ast.List, ast.Tuple)) else [value]
    else:
        computed = _value(node, names)
        if isinstance(computed, dict):
            strings = computed.get("console_scripts", [])
            return [EntryPoint(*parsed, where) for s in strings
                    if isinstance(s, str) and (parsed := parse_entry(s))]
        found.append(diag.make("PYSETUP_DYNAMIC", where, detail="entry_points"))
        return []
    entries = []
    for item in items:
        text = _value(item, names)
        item_where = workspace.location(path, item.lineno, item.col_offset + 1)
        parsed = parse_entry(text) if isinstance(text, str) else None
        if parsed is None:
            found.append(diag.make("PYSETUP_DYNAMIC", item_where, detail="a console script"))
            continue
        entries.append(EntryPoint(parsed[0], parsed[1], item_where))
    return entries


def _callee(call: ast.Call) -> str | None:
    if isinstance(call.func, ast.Name):
        return call.func.id
    if isinstance(call.func, ast.Attribute):
        return call.func.attr
    return None


def _value(node: ast.expr, names: dict[str, object]) -> object:
    """A literal value computed without running anything, or UNKNOWN."""
    if isinstance(node, ast.Constant):
        return node.value
    if isinstance(node, ast.Name):
        return names.get(node.id, UNKNOWN)
    if isinstance(node, (ast.List, ast.Tuple)):
        return [_value(e, names) for e in node.elts]
    if isinstance(node, ast.Dict):
        out = {}
        for key, value in zip(node.keys, node.values, strict=False):
            k = _value(key, names) if key is not None else UNKNOWN
            if not isinstance(k, str):
                return UNKNOWN
            out[k] = _value(value, names)
        return out
    if isinstance(node, ast.JoinedStr):
        parts = []
        for part in node.values:
            piece = _value(part.value, names) if isinstance(part, ast.FormattedValue) and (
                part.format_spec is None and part.conversion == -1) else _value(part, names)
            if not isinstance(piece, str):
                return UNKNOWN
            parts.append(piece)
        return "".join(parts)
    if isinstance(node, ast.BinOp):
        left, right = _value(node.left, names), _value(node.right, names)
        if isinstance(node.op, ast.Add) and isinstance(left, str) and isinstance(right, str):
            if len(left) + len(right) > budget.MAX_LENGTH:  # a = a + a, line after line
                return UNKNOWN
            return left + right
        if isinstance(node.op, ast.Mod) and isinstance(left, str) and re.fullmatch(
                r"(?:[^%]|%%|%s)*", left):
            operands = tuple(right) if isinstance(right, list) else (right,)
            if all(isinstance(a, str) for a in operands) and left.count("%s") == len(operands):
                return left % operands
    if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
            and node.func.attr == "format" and not node.keywords):
        template = _value(node.func.value, names)
        args = [_value(a, names) for a in node.args]
        if isinstance(template, str):
            formatted = format_positional(template, args)
            return UNKNOWN if formatted is None else formatted
    return UNKNOWN


def format_positional(template: str, args: list[object]) -> str | None:
    """``template.format(*args)`` when every field is positional (``{}``, ``{0}``) and
    every argument a known string; None otherwise (never a format spec or attribute,
    so nothing but string building happens)."""
    if not all(isinstance(a, str) for a in args) or not all(
            re.fullmatch(r"\d*", field) for field in re.findall(r"\{([^{}]*)\}", template)):
        return None
    try:
        return template.format(*args)
    except (IndexError, ValueError):
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
            entries.append(EntryPoint(parsed[0], parsed[1], workspace.location(path, line, 1)))
    package_dir: dict[str, str] = {}
    if parser.has_option("options", "package_dir"):
        for raw in parser.get("options", "package_dir").splitlines():
            key, sep, value = raw.partition("=")
            if sep:
                package_dir[key.strip()] = value.strip()
    return entries, package_dir
