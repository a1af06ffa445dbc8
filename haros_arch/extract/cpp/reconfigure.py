"""dynamic_reconfigure (ROS 1): the ``<Name>Config.h`` header it generates at build time,
from the package's ``cfg/*.cfg`` (and those a few folders down), and the other .cfg files
its CMakeLists.txt hands ``generate_dynamic_reconfigure_options``.

A ``.cfg`` is a Python script (``gen = ParameterGenerator()``, ``gen.add("name", double_t,
level, "description", default, min, max)``, ``gen.enum([gen.const(...)])``, groups from
``gen.add_group``, ``exit(gen.generate(PACKAGE, "node", "Name"))``). It is read here with
``ast``, never run: the literal arguments of those calls. A ``Server<pkg::NameConfig>``
reads every parameter of the config from the parameter server under the namespace of
its node handle when it starts (a parameter not set takes the .cfg default) and writes
them all back as read (no write is said: it changes no value); the C++ code reads their
values as fields of the config
(``config.inflation_radius``).

No build happens here, so the header is synthesised (``render``): the config class with
a field per parameter, the enums' constants and the generated methods, declarations
only. The class carries one ``annotate`` attribute per parameter (``parameters`` reads
them back from the parsed class): the visitor turns the construction of a server into a
read of each, beside the server's own service and topics. A parameter whose
name is not a literal (built in a loop) makes the config partial: the parameters known
are still read, and ``CPP_RECONFIGURE_PARTIAL`` says so.
"""

from __future__ import annotations

import ast
import functools
import json
import os
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from clang.cindex import Cursor, CursorKind

from ... import diagnostics as diag
from ...diagnostics import Diagnostic
from ...evaluate import syntax
from ...files import read_text
from ...model.location import Location
from .parameter_library import annotation

_MARK = "haros_arch.reconfigure "  # the annotation of one parameter
_CONFIG_MARK = "haros_arch.reconfigure_config"
_PARTIAL_MARK = "haros_arch.reconfigure_partial"
_NAME = re.compile(r"[A-Za-z_]\w*")
# the .cfg's types: C++ field type, ROS parameter type (as the extractor writes them)
TYPES = {"int_t": ("int", "int"), "double_t": ("double", "double"),
         "str_t": ("std::string", "str"), "bool_t": ("bool", "bool")}
MAX_CFG_BYTES = 1 << 20
# the message headers the generated header includes (synthesised like any message's)
MESSAGES = ("dynamic_reconfigure/Config.h", "dynamic_reconfigure/ConfigDescription.h")


@dataclass
class Config:
    """What one ``.cfg`` generates."""

    package: str
    name: str  # ``Name``: the class is ``NameConfig``
    path: str
    parameters: list[tuple[str, str, Any]] = field(default_factory=list)  # name, type, default
    constants: list[tuple[str, str, Any]] = field(default_factory=list)  # name, type, value
    partial: bool = False
    # the C++ namespace of the class: ``generate``'s first argument, the package the .cfg
    # names (PX4-Avoidance's local_planner generates ``avoidance::LocalPlannerNodeConfig``
    # with ``PACKAGE = "avoidance"``); its own package when that is not a literal
    namespace: str = ""


def _literal(node: ast.AST | None) -> Any:
    if node is None:
        return None
    try:
        return ast.literal_eval(node)
    except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
        return None


def _makes_generator(call: ast.Call) -> bool:
    """``ParameterGenerator()`` or ``gen.add_group(...)``."""
    func = call.func
    return (isinstance(func, ast.Name) and func.id == "ParameterGenerator") or (
        isinstance(func, ast.Attribute) and func.attr in ("ParameterGenerator", "add_group"))


def _type_name(node: ast.AST | None) -> str | None:
    if isinstance(node, ast.Name) and node.id in TYPES:
        return node.id
    if isinstance(node, ast.Constant) and node.value in ("int", "double", "str", "bool"):
        return f"{node.value}_t"
    return None


def _argument(call: ast.Call, index: int, keyword: str) -> ast.AST | None:
    positional = call.args[:index + 1]
    if index < len(call.args) and not any(isinstance(a, ast.Starred) for a in positional):
        return call.args[index]
    return next((k.value for k in call.keywords if k.arg == keyword), None)


# a function a .cfg hands its generator to: read with ``ast`` from the module it is
# imported from (``from local_planner_limits import add_generic_localplanner_params``)
MAX_MODULE_BYTES = 1 << 20
Modules = Callable[[str], "str | None"]


def read_cfg(path: str, text: str, package: str, modules: Modules | None = None
             ) -> tuple[Config | None, list[Diagnostic]]:
    """The config a ``.cfg`` generates; None when it generates none that we can name
    (no ``generate(package, node, "Name")`` with a literal name). A generator handed to
    a function (``add_generic_localplanner_params(gen)``) gets the parameters that
    function's body adds on the parameter it is passed as, when the function is
    defined in the .cfg or in a module ``modules`` finds (module name to file: the
    .cfg's folder, a workspace package's Python modules); else the config is
    partial."""
    try:
        tree = syntax.parse(text, path)
    except (SyntaxError, ValueError, MemoryError, RecursionError) as error:
        line = getattr(error, "lineno", None) or 0
        return None, [diag.make("RECONFIGURE_CFG_INVALID", Location(package, path, line),
                                detail=str(getattr(error, "msg", error)))]
    name: str | None = None
    config = Config(package, "", path)
    # the generator and its groups: handed to a function we cannot read, they may get
    # parameters we cannot see
    generators = {target.id for node in ast.walk(tree) if isinstance(node, ast.Assign)
                  and isinstance(node.value, ast.Call) and _makes_generator(node.value)
                  for target in node.targets if isinstance(target, ast.Name)}
    functions = _functions(tree, modules)
    # the texts the module's top level names (``PACKAGE = "dynamic_tutorials"``)
    texts = {target.id: node.value.value for node in tree.body if isinstance(node, ast.Assign)
             and isinstance(node.value, ast.Constant) and isinstance(node.value.value, str)
             for target in node.targets if isinstance(target, ast.Name)}
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            handed = _handed(node, generators)
            if handed is not None:
                body = functions.get(node.func.id) if isinstance(node.func, ast.Name) \
                    else None
                if body is None or not _take_function(body, handed, config):
                    config.partial = True
        if not isinstance(node, ast.Call) or not isinstance(node.func, ast.Attribute):
            continue
        if node.func.attr == "generate":
            found = _literal(_argument(node, 2, "name"))
            if isinstance(found, str) and _NAME.fullmatch(found):
                name = found
            given = _argument(node, 0, "pkgname")
            space = _literal(given) if not isinstance(given, ast.Name) else texts.get(given.id)
            if isinstance(space, str) and _NAME.fullmatch(space):
                config.namespace = space
        else:
            _take(node, config)
    if name is None:
        return None, []
    config.name = name
    first: dict[str, tuple[str, str, Any]] = {}
    for parameter in config.parameters:  # a name added twice: the first
        first.setdefault(parameter[0], parameter)
    config.parameters = list(first.values())
    return config, []


def _handed(call: ast.Call, generators: set[str]) -> str | int | None:
    """Where ``call`` hands a generator: the argument's index, or its keyword."""
    for index, arg in enumerate(call.args):
        if isinstance(arg, ast.Starred):
            return -1 if isinstance(arg.value, ast.Name) and arg.value.id in generators \
                else None
        if isinstance(arg, ast.Name) and arg.id in generators:
            return index
    for keyword in call.keywords:
        if isinstance(keyword.value, ast.Name) and keyword.value.id in generators:
            return keyword.arg if keyword.arg is not None else -1
    return None


def _take(node: ast.Call, config: Config) -> None:
    """A generator's ``add`` (a parameter) or ``const`` (a constant) call into
    ``config``; a parameter named otherwise than by a literal makes it partial."""
    assert isinstance(node.func, ast.Attribute)
    method = node.func.attr
    if method == "add" and len(node.args) + len(node.keywords) >= 4:
        kind = _type_name(_argument(node, 1, "paramtype"))
        if kind is None:
            return  # not a parameter's add (a set's, a list's)
        written = _literal(_argument(node, 0, "name"))
        if not isinstance(written, str) or not _NAME.fullmatch(written):
            config.partial = True
            return
        default = _literal(_argument(node, 4, "default"))
        config.parameters.append((written, kind, default))
    elif method == "const":
        written = _literal(_argument(node, 0, "name"))
        kind = _type_name(_argument(node, 1, "paramtype"))
        value = _literal(_argument(node, 2, "value"))
        if isinstance(written, str) and _NAME.fullmatch(written) and kind is not None:
            config.constants.append((written, kind, value))


def _functions(tree: ast.Module, modules: Modules | None) -> dict[str, ast.FunctionDef]:
    """The functions a .cfg may call by name: those it defines at its top level, and
    those it imports by name (``from module import f [as g]``) from a module
    ``modules`` finds and ``ast`` reads."""
    found: dict[str, ast.FunctionDef] = {}
    read: dict[str, dict[str, ast.FunctionDef]] = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            found[node.name] = node
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level and (
            modules is not None
        ):
            if node.module not in read:
                read[node.module] = _module_functions(modules(node.module))
            for alias in node.names:
                function = read[node.module].get(alias.name)
                if function is not None:
                    found[alias.asname or alias.name] = function
    return found


def _module_functions(path: str | None) -> dict[str, ast.FunctionDef]:
    """The top-level functions of the Python file at ``path`` (none when it cannot be
    read or parsed)."""
    if path is None:
        return {}
    try:
        if os.path.getsize(path) > MAX_MODULE_BYTES:
            return {}
    except OSError:
        return {}
    text, _ = read_text(path, Location(None, path))
    if text is None:
        return {}
    try:
        module = syntax.parse(text, path)
    except (SyntaxError, ValueError, MemoryError, RecursionError):
        return {}
    return {node.name: node for node in module.body if isinstance(node, ast.FunctionDef)}


def _take_function(function: ast.FunctionDef, handed: str | int, config: Config) -> bool:
    """The parameters ``function`` adds on the generator it is handed (at argument
    index or keyword ``handed``); False when that cannot be told: the parameter is not
    found, or the body hands it on to another function or keeps it elsewhere."""
    params = [*function.args.posonlyargs, *function.args.args]
    if isinstance(handed, int):
        if handed < 0 or handed >= len(params):
            return False
        own = params[handed].arg
    else:
        names = {p.arg for p in [*params, *function.args.kwonlyargs]}
        if handed not in names:
            return False
        own = handed
    for node in ast.walk(function):
        if isinstance(node, ast.Name) and node.id == own:
            continue
        if isinstance(node, ast.Call):
            if _handed(node, {own}) is not None:
                return False  # handed on: not followed
            func = node.func
            if isinstance(func, ast.Attribute) and isinstance(func.value, ast.Name) and (
                func.value.id == own
            ):
                _take(node, config)
        elif isinstance(node, ast.Assign | ast.AugAssign | ast.AnnAssign | ast.NamedExpr):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            if any(isinstance(target, ast.Name) and target.id == own for target in targets) \
                    or (isinstance(node.value, ast.Name) and node.value.id == own):
                return False  # the generator rebound or stored: not followed
    return True


def configs(folder: str, package: str, modules: Modules | None = None
            ) -> tuple[dict[str, Config], list[Diagnostic]]:
    """The configs of a package's ``cfg/*.cfg`` by class name (``NameConfig``); the
    modules a .cfg imports are looked for beside it (Python's path starts with the
    script's folder), then by ``modules``."""
    found: dict[str, Config] = {}
    problems: list[Diagnostic] = []
    cfg = os.path.join(folder, "cfg")
    for path in dict.fromkeys([*_cfg_files(cfg), *_cmake_cfg_files(folder)]):
        here = os.path.dirname(path)
        try:
            if os.path.getsize(path) > MAX_CFG_BYTES:
                continue
        except OSError:
            continue
        text, read_problems = read_text(path, Location(package, path))
        problems += read_problems
        if text is None:
            continue
        config, more = read_cfg(path, text, package,
                                functools.partial(_beside_or, here, modules))
        problems += more
        if config is not None:
            found.setdefault(config.name + "Config", config)
    return found, problems


CFG_DEPTH = 3  # folders below ``cfg/`` searched for .cfg files


def _cfg_files(cfg: str) -> list[str]:
    """The ``.cfg`` files of a package's ``cfg/`` folder and of its folders a few levels
    down (``CFG_DEPTH``): ``generate_dynamic_reconfigure_options`` takes any path of the
    package, and the header a .cfg makes is named after its generator, not its folder
    (bebop_driver's ``cfg/autogenerated/BebopArdrone3.cfg`` makes
    ``<bebop_driver/BebopArdrone3Config.h>``). Those of ``cfg/`` itself first, then each
    folder's, in name order."""
    found: list[str] = []
    todo = [(cfg, 0)]
    while todo:
        folder, depth = todo.pop(0)
        try:
            entries = sorted(os.listdir(folder))
        except OSError:
            continue
        for entry in entries:
            path = os.path.join(folder, entry)
            if entry.endswith(".cfg") and os.path.isfile(path):
                found.append(path)
            elif depth < CFG_DEPTH and not entry.startswith(".") and os.path.isdir(path) and (
                    not os.path.islink(path)):
                todo.append((path, depth + 1))
    return found


_GENERATE = re.compile(r"\bgenerate_dynamic_reconfigure_options\s*\(([^)]*)\)", re.IGNORECASE)
_CMAKE_COMMENT = re.compile(r"#[^\n]*")
_SOURCE_DIRS = ("${CMAKE_CURRENT_SOURCE_DIR}/", "${PROJECT_SOURCE_DIR}/",
                "${CMAKE_SOURCE_DIR}/")
MAX_CMAKE_BYTES = 1 << 20


def _cmake_cfg_files(folder: str) -> list[str]:
    """The ``.cfg`` files the package's CMakeLists.txt hands
    ``generate_dynamic_reconfigure_options`` outside its ``cfg/`` folder
    (moveit_ros_planning's ``trajectory_execution_manager/cfg/
    TrajectoryExecutionDynamicReconfigure.cfg``): paths written literally, relative to
    the package (or after ``${CMAKE_CURRENT_SOURCE_DIR}/``), that are files in it; a
    path built of other variables is not known and left out."""
    path = os.path.join(folder, "CMakeLists.txt")
    try:
        if os.path.getsize(path) > MAX_CMAKE_BYTES:
            return []
        with open(path, encoding="utf-8", errors="replace") as handle:
            text = _CMAKE_COMMENT.sub("", handle.read())
    except OSError:
        return []
    root = os.path.realpath(folder)
    found: list[str] = []
    for call in _GENERATE.finditer(text):
        for word in re.findall(r'"([^"]*)"|(\S+)', call.group(1)):
            written = word[0] or word[1]
            for prefix in _SOURCE_DIRS:
                written = written.removeprefix(prefix)
            if not written.endswith(".cfg") or "${" in written or os.path.isabs(written):
                continue
            candidate = os.path.realpath(os.path.join(folder, written))
            if candidate.startswith(root + os.sep) and os.path.isfile(candidate):
                found.append(os.path.join(folder, written))
    return found


def _beside_or(folder: str, modules: Modules | None, name: str) -> str | None:
    """The file of module ``name`` beside the .cfg (in ``folder``), else ``modules``'."""
    return _beside(folder, name) or (modules(name) if modules is not None else None)


def _beside(folder: str, name: str) -> str | None:
    """The file of Python module ``name`` (dotted) in ``folder``, if there."""
    return module_file([folder], name)


def module_file(folders: list[str], name: str) -> str | None:
    """The file of Python module ``name`` (dotted: ``a.b``) under one of ``folders``:
    ``a/b.py`` or ``a/b/__init__.py``, the first found."""
    parts = name.split(".")
    if not all(_NAME.fullmatch(part) for part in parts):
        return None
    for folder in folders:
        base = os.path.join(folder, *parts)
        for candidate in (base + ".py", os.path.join(base, "__init__.py")):
            if os.path.isfile(candidate):
                return candidate
    return None


def workspace_modules(workspace: Any) -> Modules:
    """A ``Modules`` over the workspace's packages: the module in a package's ``src``
    folder, where catkin's ``catkin_python_setup`` installs it from
    (``package_dir={'': 'src'}``): base_local_planner's ``local_planner_limits``."""
    folders = sorted(os.path.join(package.root, "src")
                     for package in workspace.packages.values() if package.root)
    return lambda name: module_file(folders, name)


def _constant(kind: str, value: Any) -> str | None:
    if kind == "str_t":
        return None  # no static string constant in a class body
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float):
        return repr(value)
    return None


def render(config: Config, source: str) -> str:
    """The header ``generate_dynamic_reconfigure_options`` would write, declarations
    only."""
    cls = f"{config.name}Config"
    entries = [_MARK + json.dumps([name, TYPES[kind][1], default], default=str)
               for name, kind, default in config.parameters]
    marks = [_CONFIG_MARK, *([_PARTIAL_MARK] if config.partial else []), *entries]
    notes = " ".join(annotation(m) for m in marks)
    fields = [f"  {TYPES[kind][0]} {name};" for name, kind, _ in config.parameters]
    constants = []
    for name, kind, value in config.constants:
        written = _constant(kind, value)
        if written is not None:
            constants.append(f"  static const {TYPES[kind][0]} {name} = {written};")
    lines = [f"// {config.package}/{cls}.h, as dynamic_reconfigure writes it from {source}: "
             "synthesised by haros_arch, declarations only",
             "#pragma once", "#include <string>", "#include <vector>", "#include <ros/ros.h>",
             *(f"#include <{header}>" for header in MESSAGES),
             f"namespace {config.namespace or config.package} {{",
             f"class {notes} {cls} {{", " public:", *fields, *constants,
             "  struct GroupDescription { std::string name; int id; int parent; };",
             "  struct AbstractParamDescription { std::string name; std::string type; };",
             "  typedef std::vector<AbstractParamDescription> ParamDescriptions;",
             f"  static const {cls}& __getDefault__();",
             f"  static const {cls}& __getMin__();",
             f"  static const {cls}& __getMax__();",
             "  static const ParamDescriptions& __getParamDescriptions__();",
             "  static const dynamic_reconfigure::ConfigDescription& __getDescriptionMessage__();",
             "  bool __fromMessage__(dynamic_reconfigure::Config& msg);",
             "  void __toMessage__(dynamic_reconfigure::Config& msg) const;",
             "  void __fromServer__(const ros::NodeHandle& nh);",
             "  void __toServer__(const ros::NodeHandle& nh) const;",
             "  void __clamp__();",
             f"  uint32_t __level__(const {cls}& config) const;",
             "};", f"}}  // namespace {config.namespace or config.package}", ""]
    return "\n".join(lines)


def parameters(cls: Cursor | None) -> tuple[list[tuple[str, str, Any]], bool] | None:
    """The parameters a synthesised config class stands for (its annotations) and
    whether the config is partial; None when ``cls`` is not one."""
    if cls is None or cls.kind not in (CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL):
        return None
    found: list[tuple[str, str, Any]] = []
    marked = partial = False
    for child in cls.get_children():
        if child.kind != CursorKind.ANNOTATE_ATTR:
            continue
        spelling = child.spelling
        marked = marked or spelling == _CONFIG_MARK
        partial = partial or spelling == _PARTIAL_MARK
        if spelling.startswith(_MARK):
            try:
                name, kind, default = json.loads(spelling[len(_MARK):])
            except (ValueError, TypeError):
                continue
            found.append((str(name), str(kind), default))
    return (found, partial) if marked else None
