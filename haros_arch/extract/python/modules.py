"""Python modules of one ROS package, parsed with ``ast`` (never imported or run).

``Loader.load(path)`` reads and parses a file once (size-bounded, syntax errors become
``PY_PARSE_ERROR``; Python 2 files get a line-preserving repair of the common
statements and ``PY_PYTHON2``) and indexes it as a ``Module``: its imports, module
constants, functions and classes. ``Loader.resolve_import`` finds modules of the same
package (relative imports, and ``from pkg.sub import X`` inside the package's folder),
and Python packages other packages of the workspace hold (``src/<name>/__init__.py``,
or in the folder their setup.py's ``package_dir`` names: ``pysetup.python_folders``).
"""

from __future__ import annotations

import ast
import functools
import os
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from ... import diagnostics as diag
from ...diagnostics import Diagnostic
from ...evaluate import syntax
from ...evaluate.python import BUILTINS, evaluate_node
from ...files import read_text
from ...model.location import Location
from ...pysetup import environment_functions, python_folders
from ...workspace import Workspace

MAX_PY_BYTES = 512 * 1024
MAX_AST_NODES = 200_000

FunctionNode = ast.FunctionDef | ast.AsyncFunctionDef


@dataclass(eq=False)
class FunctionInfo:
    node: FunctionNode
    module: Module
    cls: ClassInfo | None = None
    # the enclosing function's variables, for functions defined inside functions
    closure: dict[str, object] | None = None

    @property
    def qualname(self) -> str:
        return f"{self.cls.name}.{self.node.name}" if self.cls else self.node.name


@dataclass(eq=False)
class ClassInfo:
    node: ast.ClassDef
    module: Module
    methods: dict[str, FunctionInfo] = field(default_factory=dict)
    constants: dict[str, ast.expr] = field(default_factory=dict)
    # filled by the evaluator on first use
    attrs: dict[str, object] | None = None
    bases: list[object] | None = None

    @property
    def name(self) -> str:
        return self.node.name


@dataclass(eq=False)
class Module:
    path: str
    text: str
    tree: ast.Module
    # local name -> qualified name (``String`` -> ``std_msgs.msg.String``)
    imports: dict[str, str] = field(default_factory=dict)
    # local name -> (module file, name in it or None for the module itself)
    local_imports: dict[str, tuple[str, str | None]] = field(default_factory=dict)
    stars: list[str] = field(default_factory=list)       # qualified modules
    local_stars: list[str] = field(default_factory=list)  # module files
    constants: dict[str, ast.expr] = field(default_factory=dict)
    # the names a ROS import guard's body binds (``_ros_import_guard``): what running as
    # a ROS node makes them, not a switch of the code's own
    import_guarded: set[str] = field(default_factory=set)
    functions: dict[str, FunctionInfo] = field(default_factory=dict)
    classes: dict[str, ClassInfo] = field(default_factory=dict)
    values: dict[str, object] = field(default_factory=dict)
    _lines: list[str] | None = None
    # how many statements assign each ``self.<member>`` (visitor._member_writes)
    member_writes: dict[str, int] | None = None
    # the ``self.<member>`` some code uses as a dict (visitor._mapping_members)
    mapping_members: set[str] | None = None
    # the ``self.<member>`` some code walks element by element (visitor._iterated_members)
    iterated_members: set[str] | None = None
    # the ROS version of the node these modules make, for a module that imports neither
    # rospy nor rclpy (``extract_python`` sets it)
    node_version: int = 1
    # the classes and functions a module-level ``if`` / ``elif`` / ``else`` defines, by
    # name, each with the tests that choose its branch (the test, and whether it must
    # hold): ros_compatibility's ``if ROS_VERSION == 1: class CompatibleNode(object)
    # ... elif ROS_VERSION == 2: class CompatibleNode(Node)`` (``Scopes.lookup``)
    guarded: dict[str, list[tuple[tuple[tuple[ast.expr, bool], ...], ClassInfo | FunctionInfo]]] \
        = field(default_factory=dict)

    @property
    def lines(self) -> list[str]:
        if self._lines is None:
            self._lines = self.text.splitlines(keepends=True)
        return self._lines

    @property
    def version(self) -> int:
        """2 when the module uses rclpy, 1 when it uses rospy; else that of the node (a
        helper the node hands itself to: ``diagnostic_updater.Updater(node)``)."""
        return self.client_version or self.node_version

    @property
    def client_version(self) -> int | None:
        """2 when the module imports rclpy, 1 when it imports rospy, else None (and
        None when it imports both, each under its own test: a compatibility module of
        either version, which is the node's)."""
        qualified = (*self.imports.values(), *self.stars)
        ros2 = any(q == "rclpy" or q.startswith("rclpy.") for q in qualified)
        ros1 = any(q == "rospy" or q.startswith("rospy.") for q in qualified)
        if ros1 and ros2:
            return None
        return 2 if ros2 else 1 if ros1 else None


class Loader:
    """Parses and indexes the modules of one package, each once."""

    def __init__(self, workspace: Workspace, package_root: str | None) -> None:
        self.workspace = workspace
        self.package_root = package_root
        self.modules: dict[str, Module | None] = {}
        self.diagnostics: list[Diagnostic] = []
        self.node_version = 1  # each module's ``node_version``
        # the environment of the node's process as far as it is known here (the run's;
        # a ROS version's where its package builds the node for that one alone)
        self.environment: Mapping[str, str] = getattr(workspace, "environment", {})
        # top-level Python package name -> folder holding it, in other workspace packages

    def location(self, path: str, line: int = 0, column: int = 0) -> Location:
        return self.workspace.location(path, line, column)

    def load(self, path: str) -> Module | None:
        path = os.path.abspath(path)
        if path in self.modules:
            return self.modules[path]
        self.modules[path] = None
        text, found = read_text(path, self.location(path), MAX_PY_BYTES)
        self.diagnostics.extend(found)
        if text is None:
            return None
        tree = self._parse(path, text)
        if tree is None:
            return None
        module = Module(path, text, tree, node_version=self.node_version)
        _index(module, self)
        self.modules[path] = module
        return module

    def _parse(self, path: str, text: str) -> ast.Module | None:
        try:
            tree = _ast_parse(text, path)
        except SyntaxError as err:
            repaired, shifts = _expand_python2_tabs(_repair_python2(text))
            if repaired != text:
                try:
                    tree = _ast_parse(repaired, path)
                except (SyntaxError, ValueError, RecursionError, MemoryError):
                    pass
                else:
                    _shift_columns(tree, shifts)
                    self.diagnostics.append(diag.make(
                        "PY_PYTHON2", self.location(path, err.lineno or 0,
                                                    err.offset or 0)))
                    return self._bounded(path, tree)
            self.diagnostics.append(diag.make(
                "PY_PARSE_ERROR", self.location(path, err.lineno or 0, err.offset or 0),
                detail=err.msg))
            return None
        except (ValueError, RecursionError, MemoryError) as err:
            self.diagnostics.append(diag.make(
                "PY_PARSE_ERROR", self.location(path), detail=type(err).__name__))
            return None
        return self._bounded(path, tree)

    def _bounded(self, path: str, tree: ast.Module) -> ast.Module | None:
        for count, _ in enumerate(ast.walk(tree)):
            if count >= MAX_AST_NODES:
                self.diagnostics.append(diag.make(
                    "PY_TOO_COMPLEX", self.location(path), limit=f"{MAX_AST_NODES} AST nodes"))
                return None
        return tree

    # -- imports of the same package ----------------------------------------------------

    def resolve_import(self, module_path: str, level: int, dotted: str) -> str | None:
        """The file of module ``dotted`` imported from ``module_path``, if it is a module
        of this package (relative with ``level`` dots, or absolute inside its folder)."""
        parts = [p for p in dotted.split(".") if p]
        if level:
            base = os.path.dirname(module_path)
            for _ in range(level - 1):
                base = os.path.dirname(base)
            return module_file(base, parts)
        if not parts or self.package_root is None:
            return None
        for root in self._search_roots(module_path):
            found = module_file(root, parts)
            if found is not None:
                return found
        return self._other_package(parts)

    def _other_package(self, parts: list[str]) -> str | None:
        """A Python package another package of the workspace holds (``src/<name>`` or
        ``<name>`` with an ``__init__.py``, as catkin_python_setup / setup.py install
        it): rosserial_arduino's ``from rosserial_python import SerialClient``."""
        own = os.path.abspath(self.package_root) if self.package_root else None
        return workspace_module(self.workspace, parts, own)

    def _search_roots(self, module_path: str) -> list[str]:
        assert self.package_root is not None
        roots = [self.package_root, os.path.join(self.package_root, "src"),
                 os.path.join(self.package_root, "scripts"),
                 *python_folders(self.package_root)]
        folder = os.path.dirname(os.path.abspath(module_path))
        while folder.startswith(self.package_root + os.sep) and folder not in roots:
            roots.append(folder)
            folder = os.path.dirname(folder)
        return roots


def workspace_module(workspace: Any, parts: list[str], own: str | None = None
                     ) -> str | None:
    """The file of module ``parts`` (``["pkg", "sub", "mod"]``) of a Python package that
    a package of the workspace holds (``src/<name>`` or ``<name>`` with an
    ``__init__.py``, as catkin_python_setup and an ament_python setup.py install it),
    not one of the package at ``own``; None when no package holds it, or for a client
    library whose calls the API tables read (``rospy``, ``rclpy``: ros_comm holds rospy's
    sources)."""
    if not parts or parts[0] in api_modules():
        return None  # its API rows read it, not its own code (ros_comm holds rospy's)
    packages = getattr(workspace, "packages", {})
    roots = tuple(p.root for p in packages.values() if p.root)
    for root, base in _python_packages(roots).get(parts[0], ()):
        if own is None or os.path.abspath(root) != own:
            return module_file(base, parts)
    return None


@functools.lru_cache(maxsize=8)
def _python_packages(roots: tuple[str, ...]) -> dict[str, tuple[tuple[str, str], ...]]:
    """The Python packages the package folders ``roots`` hold, by name: each (package
    root, the folder that holds it), in the order of ``roots``."""
    found: dict[str, list[tuple[str, str]]] = {}
    for root in roots:
        for base in dict.fromkeys((*python_folders(root), os.path.join(root, "src"), root)):
            try:
                names = sorted(os.listdir(base))
            except OSError:
                continue
            for name in names:
                if name.isidentifier() and os.path.isfile(
                        os.path.join(base, name, "__init__.py")):
                    found.setdefault(name, []).append((root, base))
    return {name: tuple(places) for name, places in found.items()}


def submodule(package_init: str, name: str) -> str | None:
    """The file of module ``name`` inside the package whose ``__init__.py`` is given."""
    if os.path.basename(package_init) != "__init__.py" or not name.isidentifier():
        return None
    return module_file(os.path.dirname(package_init), [name])


def module_file(base: str, parts: list[str]) -> str | None:
    """The file of module ``parts`` under the folder ``base`` (a module or a package's
    ``__init__.py``), if there is one."""
    if not parts:
        init = os.path.join(base, "__init__.py")
        return init if os.path.isfile(init) else None
    path = os.path.join(base, *parts)
    if os.path.isfile(path + ".py"):
        return path + ".py"
    if os.path.isfile(os.path.join(path, "__init__.py")):
        return os.path.join(path, "__init__.py")
    return None


def last_name(expr: ast.expr | None) -> str:
    """The name an expression ends in (``rospy.Publisher`` -> ``Publisher``, ``f`` ->
    ``f``; "" for anything else): what a call or a base class names."""
    if isinstance(expr, ast.Attribute):
        return expr.attr
    return expr.id if isinstance(expr, ast.Name) else ""


def _ast_parse(text: str, path: str) -> ast.Module:
    return syntax.parse(text, path)


def _index(module: Module, loader: Loader) -> None:
    for statement in module.tree.body:
        _index_statement(module, loader, statement)


def _index_statement(module: Module, loader: Loader, statement: ast.stmt) -> None:
    if isinstance(statement, ast.Import | ast.ImportFrom):
        add_import(module, loader, statement, module.imports, module.local_imports)
    elif isinstance(statement, ast.FunctionDef | ast.AsyncFunctionDef):
        module.functions[statement.name] = FunctionInfo(statement, module)
    elif isinstance(statement, ast.ClassDef):
        module.classes[statement.name] = _class_info(statement, module)
    elif isinstance(statement, ast.Assign | ast.AnnAssign):
        _constant(statement, module.constants)
    elif isinstance(statement, ast.If | ast.Try):
        _index_guarded_imports(module, loader, statement)
        if isinstance(statement, ast.If):
            _index_guarded(module, statement, ())
        elif _ros_import_guard(statement):
            for child in statement.body:
                if isinstance(child, ast.Assign | ast.AnnAssign):
                    bound: dict[str, ast.expr] = {}
                    _constant(child, bound)
                    module.constants.update(bound)
                    module.import_guarded.update(bound)


# the exceptions a failed import raises
_IMPORT_ERRORS = frozenset({"ImportError", "ModuleNotFoundError"})


def _ros_import_guard(statement: ast.Try) -> bool:
    """Whether a module-level ``try`` imports the ROS client library and only ROS
    modules (the client library's, interface modules ``pkg.msg`` / ``.srv`` /
    ``.action``) and catches only a failed import: kyubic_ros' dashboard sets
    ``ROS_AVAILABLE = True`` after ``import rclpy`` and its messages, ``False`` in
    ``except ImportError`` (a UI-only mode), then makes its node only ``if
    ROS_AVAILABLE``. Run as a ROS node those imports succeed, so the names the body
    binds are the module's (the handler's are not), and the node's calls no longer
    hang on a test not known."""
    if statement.finalbody or not statement.handlers or not all(
            handler.type is not None and _names(handler.type) <= _IMPORT_ERRORS
            for handler in statement.handlers):
        return False
    modules = [alias.name for child in statement.body if isinstance(child, ast.Import)
               for alias in child.names]
    modules += [child.module for child in statement.body
                if isinstance(child, ast.ImportFrom) and child.module and not child.level]
    if any(isinstance(child, ast.ImportFrom) and child.level for child in statement.body):
        return False
    client = any(name.split(".")[0] in ("rclpy", "rospy") for name in modules)
    return client and all(name.split(".")[0] in ("rclpy", "rospy")
                          or (len(name.split(".")) > 1 and name.split(".")[1] in (
                              "msg", "srv", "action")) for name in modules)


def _names(expr: ast.expr) -> set[str]:
    """The exception class names an ``except`` clause gives (one, or a tuple's)."""
    items = expr.elts if isinstance(expr, ast.Tuple) else [expr]
    return {item.id if isinstance(item, ast.Name) else "?" for item in items}


def _index_guarded_imports(module: Module, loader: Loader, statement: ast.If | ast.Try) -> None:
    """Imports guarded by try/except ImportError or version checks, through the
    ``elif``s and nested ``if``s of a module-level ``if`` (ros_compatibility imports
    rospy under ``if ROS_VERSION == 1:`` and rclpy's ``Node`` under ``elif ROS_VERSION
    == 2:``; a module that so imports both is of the node's ROS version,
    ``Module.client_version``). A branch whose test, over the distribution's variables
    of the node's process (``Loader.environment``) and literals alone, does not hold
    imports nothing: rosboard imports rospy as ``rospy`` under ``os.environ.get(
    "ROS_VERSION") == "1"`` and its own rclpy shim as ``rospy`` under ``== "2"``, and
    the shim, last, was taken for ROS 1's rospy."""
    holds = _test_holds(statement.test, loader.environment) if isinstance(
        statement, ast.If) else None
    branches = (statement.body if holds else statement.orelse if holds is False
                else (*statement.body, *statement.orelse))
    for child in branches:
        if isinstance(child, ast.Import | ast.ImportFrom):
            add_import(module, loader, child, module.imports, module.local_imports)
        elif isinstance(child, ast.If) and isinstance(statement, ast.If):
            _index_guarded_imports(module, loader, child)


def _test_holds(test: ast.expr, environment: Mapping[str, str]) -> bool | None:
    """Whether a module-level ``if``'s test holds, when it reads nothing but literals
    and the distribution's variables (``os.environ``, ``os.getenv``); None when that is
    not known."""
    value = evaluate_node(test, None, {**BUILTINS, **environment_functions(environment)})
    return value if isinstance(value, bool) else None


def _index_guarded(module: Module, statement: ast.If,
                   tests: tuple[tuple[ast.expr, bool], ...]) -> None:
    """The classes and functions each branch of a module-level ``if`` defines
    (``Module.guarded``), under the tests that choose the branch, through ``elif``s and
    nested ``if``s."""
    for body, holds in ((statement.body, True), (statement.orelse, False)):
        under = (*tests, (statement.test, holds))
        for child in body:
            if isinstance(child, ast.If):
                _index_guarded(module, child, under)
            elif isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
                made = _definition(child, module)
                module.guarded.setdefault(child.name, []).append((under, made))


def _definition(statement: ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef,
                module: Module) -> ClassInfo | FunctionInfo:
    if not isinstance(statement, ast.ClassDef):
        return FunctionInfo(statement, module)
    return _class_info(statement, module)


def _class_info(statement: ast.ClassDef, module: Module) -> ClassInfo:
    info = ClassInfo(statement, module)
    for item in statement.body:
        if isinstance(item, ast.FunctionDef | ast.AsyncFunctionDef):
            info.methods[item.name] = FunctionInfo(item, module, info)
        elif isinstance(item, ast.Assign | ast.AnnAssign):
            _constant(item, info.constants)
    return info


def _constant(statement: ast.Assign | ast.AnnAssign, into: dict[str, ast.expr]) -> None:
    """The names an assignment of a module or class body binds, with the expression
    (``x = y = 1``, ``x: int = 1``; a bare annotation binds nothing)."""
    if isinstance(statement, ast.Assign):
        for target in statement.targets:
            if isinstance(target, ast.Name):
                into[target.id] = statement.value
    elif isinstance(statement.target, ast.Name) and statement.value is not None:
        into[statement.target.id] = statement.value


def add_import(module: Module, loader: Loader, statement: ast.Import | ast.ImportFrom,
               imports: dict[str, str],
               local_imports: dict[str, tuple[str, str | None]]) -> None:
    """Record what an import statement binds, in ``imports`` / ``local_imports``."""
    if isinstance(statement, ast.Import):
        for alias in statement.names:
            local = loader.resolve_import(module.path, 0, alias.name)
            if alias.asname:
                if local is not None:
                    local_imports[alias.asname] = (local, None)
                else:
                    imports[alias.asname] = alias.name
            else:  # ``import pkg.sub`` binds ``pkg``: the package's own, when it is
                top = alias.name.split(".")[0]
                own = loader.resolve_import(module.path, 0, top) if local is not None else None
                if own is not None:
                    local_imports.setdefault(top, (own, None))
                else:
                    imports.setdefault(top, top)
        return
    source = statement.module or ""
    local = loader.resolve_import(module.path, statement.level, source)
    for alias in statement.names:
        if alias.name == "*":
            if local is not None:
                module.local_stars.append(local)
            elif not statement.level:
                module.stars.append(source)
            continue
        name = alias.asname or alias.name
        submodule = loader.resolve_import(
            module.path, statement.level, f"{source}.{alias.name}" if source else alias.name)
        if submodule is not None and local is not None \
                and os.path.basename(local) == "__init__.py":
            # ``from pkg import X``: what pkg's __init__ binds to X (rosserial_arduino's
            # ``from .SerialClient import *`` binds the class over the submodule of the
            # same name), else the submodule (``Scopes.lookup`` falls back to it)
            local_imports[name] = (local, alias.name)
        elif submodule is not None:
            local_imports[name] = (submodule, None)
        elif local is not None:
            local_imports[name] = (local, alias.name)
        elif not statement.level:
            # roslib's legacy ``ros`` package imports the ROS package a ``from ros import
            # X`` names (Doosan's dmodel.py: ``from ros import rosparam``)
            imports[name] = alias.name if source == "ros" else f"{source}.{alias.name}"


# a statement at the start of a line, or after a compound statement's colon on it
# (``if verbose: print x``, ``else: print y``)
_HEAD = (r"^(\s*(?:(?:if|elif|while|for|with|except)\b[^#:'\"]*:\s*"
         r"|(?:else|try|finally)\s*:\s*)?)")
_PRINT = re.compile(_HEAD + r"print\b(?!\s*\()(?!\s*=)(.*)$")
_EXEC = re.compile(_HEAD + r"exec\s+(?!\()(.*)$")
# ``except E, e:``, ``except (E1, E2), e:`` and the unpacked ``except E, (errno, msg):``
_EXCEPT = re.compile(r"^(\s*except\s+(?:\([^()]*\)|[^,:()]+)),\s*(\w+|\(\s*\w+[\w\s,]*\))\s*:")
# ``010`` but not a float's exponent (``2e-06``)
_OCTAL = re.compile(r"(?<![\w.])(?<![\d.][eE][-+])0([0-7]+)(?![\w.])")
_LONG = re.compile(r"(?<![\w.])(\d+)[lL](?!\w)")
_BACKTICK = re.compile(r"`([^`\n]*)`")
_RAISE = re.compile(r"^(\s*raise\s+[\w.]+)\s*,\s*(.+)$")
# tuple parameters (gone with PEP 3113): ``lambda (msg): ...``, ``lambda (k, v): v``, and
# a flat tuple in a ``def``'s parameter list on its line, ``def f(self, (x, y)):``
_LAMBDA_TUPLE = re.compile(r"\blambda\s*\(([\w\s,]*)\)(?=\s*:)")
_DEF_HEAD = re.compile(r"^\s*def\s+\w+\s*\(")
_PARAM_TUPLE = re.compile(r"(?<=[(,])(\s*)\(([\w\s,]*)\)(?=\s*[,)])")


def _repair_python2(text: str) -> str:
    """Rewrite Python 2 statements line by line, keeping line numbers and call columns.

    ``print x`` and ``exec x`` become ``pass``-like expressions, ``except E, e:``
    becomes ``except E as e:``, octal and long literals and backticks are modernised.
    Only a repair for reading ROS calls: the result is never run.
    """
    lines = text.split("\n")
    going: tuple[int, str] | None = None  # a print / exec statement that goes on
    for i, line in enumerate(lines):
        fixed = line
        if going is not None:
            fixed, going = _close_call(fixed, going)
        else:
            for pattern, word in ((_PRINT, "print"), (_EXEC, "exec")):
                found = pattern.match(fixed)
                if found is not None:
                    rest = _strip_chevron(found.group(2)) if word == "print" else found.group(2)
                    fixed, going = _close_call(f"{found.group(1)}{word}({rest}", (-1, ""))
                    break
        fixed = _EXCEPT.sub(lambda m: f"{m.group(1)} as {_first_name(m.group(2))}:", fixed)
        fixed = _RAISE.sub(lambda m: f"{m.group(1)}({m.group(2)})", fixed)
        fixed = _BACKTICK.sub(lambda m: f"repr({m.group(1)})", fixed)
        if "0" in fixed:
            fixed = _OCTAL.sub(lambda m: f"0o{m.group(1)}", fixed)
        fixed = _LONG.sub(lambda m: m.group(1), fixed)
        fixed = fixed.replace("ur\"", "\"").replace("ur'", "'")
        if "(" in fixed:
            fixed = _untuple_parameters(fixed)
        lines[i] = fixed
    return "\n".join(lines)


def _first_name(target: str) -> str:
    """The name an ``except`` clause binds in Python 3: a tuple target's first name
    (``(errno, msg)``: ``errno``; the others stay unbound, which a reading of ROS calls
    does not mind)."""
    return re.findall(r"\w+", target)[0]


def _untuple_parameters(line: str) -> str:
    """Python 2's tuple parameters on ``line`` made plain names, the brackets turned into
    spaces so the columns stay (``lambda (msg): f(msg)`` -> ``lambda  msg : f(msg)``;
    the names of ``(x, y)`` become parameters of their own, which is all a reading of
    ROS calls needs: the result is never run). Nested tuples are left alone."""
    def spaced(found: re.Match[str]) -> str:
        return found.group(0).replace("(", " ").replace(")", " ")

    line = _LAMBDA_TUPLE.sub(spaced, line)
    head = _DEF_HEAD.match(line)
    if head is not None:
        start = head.end() - 1
        line = line[:start] + _PARAM_TUPLE.sub(spaced, line[start:])
    return line


def _expand_python2_tabs(text: str) -> tuple[str, dict[int, int]]:
    """Python 2's indentation: a tab goes to the next multiple of 8 columns, so a block
    may mix tabs and spaces (``\t`` and ``    \t`` are one level) where Python 3 raises
    TabError. The leading whitespace of every line that starts a statement is expanded
    that way; lines inside brackets, triple-quoted strings or after a backslash are left
    alone. Returns the text and, per line number (1-based) changed, how many characters
    its indentation grew, for `_shift_columns`."""
    lines = text.split("\n")
    shifts: dict[int, int] = {}
    depth, quote, joined = 0, "", False
    for i, line in enumerate(lines):
        starts = depth <= 0 and not quote and not joined
        if starts:
            body = line.lstrip(" \t\f")
            indent = line[:len(line) - len(body)]
            if "\t" in indent and body:
                width = 0
                for char in indent:
                    width = (width // 8 + 1) * 8 if char == "\t" else width + 1
                lines[i] = " " * width + body
                shifts[i + 1] = width - len(indent)
        opened, comment, quote, _ = _scan(line, quote)
        depth = max(depth + opened, 0)
        joined = not quote and line[:comment].rstrip().endswith("\\")
    return "\n".join(lines), shifts


def _shift_columns(tree: ast.AST, shifts: dict[int, int]) -> None:
    """Put the columns of a tree parsed from `_expand_python2_tabs`'s text back on the
    file's own lines (the text other readers slice with them)."""
    if not shifts:
        return
    for node in ast.walk(tree):
        line, column = getattr(node, "lineno", None), getattr(node, "col_offset", None)
        if line in shifts and isinstance(column, int):
            node.col_offset = max(column - shifts[line], 0)  # type: ignore[attr-defined]
        line, column = getattr(node, "end_lineno", None), getattr(node, "end_col_offset", None)
        if line in shifts and isinstance(column, int):
            node.end_col_offset = max(column - shifts[line], 0)  # type: ignore[attr-defined]


def _strip_chevron(rest: str) -> str:
    rest = rest.strip()
    if rest.startswith(">>"):
        rest = rest[2:].split(",", 1)[1] if "," in rest else ""
    return rest  # a trailing comma goes where the statement ends (_close_call)


def _close_call(line: str, state: tuple[int, str]) -> tuple[str, tuple[int, str] | None]:
    """A line of a print / exec statement made a call. ``state``: the brackets open
    before the line, the call's own ``(`` not counted (-1 on the first line, which holds
    that ``(``), and the triple quote of a string still open. The line with the call's
    ``)`` where the statement ends (before a comment, so a statement continued by a
    backslash, an open bracket or a long string keeps its lines), and the state after
    it, None once the statement has ended."""
    depth, quote = state
    opened, comment, quote, end = _scan(line, quote, depth)
    if end is not None:  # ``print x;`` or ``print x; y = 1``: the call ends at the ``;``
        code = line[:end].rstrip()
        return code.rstrip(",") + ")" + line[len(code):], None
    depth += opened
    code = line[:comment].rstrip()
    if depth > 0 or quote or code.endswith("\\"):
        return line, (depth, quote)
    return code.rstrip(",") + ")" + line[len(code):], None


def _scan(code: str, quote: str = "",
          depth: int = 0) -> tuple[int, int, str, int | None]:
    """Brackets opened minus closed in ``code`` outside strings, where its comment starts
    (its length when none), the triple quote of a string open at its end and where a
    ``;`` ends a statement (outside strings and brackets, ``depth`` those open at its
    start: Python 2's ``print x;``, a C habit of kinetic-era nodes), None when none does;
    ``quote``: the string open at its start."""
    opened, i, end = 0, 0, None
    while i < len(code):
        char = code[i]
        if quote:
            if char == "\\":
                i += 1
            elif code.startswith(quote, i):
                i += len(quote) - 1
                quote = ""
        elif char == "#":
            return opened, i, "", end
        elif char in "\"'":
            quote = char * 3 if code.startswith(char * 3, i) else char
            i += len(quote) - 1
        elif char in "([{":
            opened += 1
        elif char in ")]}":
            opened -= 1
        elif char == ";" and end is None and depth + opened == 0:
            end = i
        i += 1
    return opened, len(code), quote if len(quote) == 3 else "", end


@functools.lru_cache(maxsize=1)
def api_modules() -> frozenset[str]:
    """The top modules whose calls the API tables read (``rospy``, ``rclpy``,
    ``actionlib``, ...): never read from a workspace package's sources."""
    from . import rclpy, rospy

    return frozenset(module for module, _ in (*rospy.ROWS, *rclpy.ROWS))
