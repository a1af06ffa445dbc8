"""dynamic_reconfigure (ROS 1): the ``<Name>Config.h`` header it generates at build time,
from the package's ``cfg/*.cfg``.

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
import json
import os
import re
from dataclasses import dataclass, field
from typing import Any

from clang.cindex import Cursor, CursorKind

from ... import diagnostics as diag
from ...diagnostics import Diagnostic
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


def read_cfg(path: str, text: str, package: str) -> tuple[Config | None, list[Diagnostic]]:
    """The config a ``.cfg`` generates; None when it generates none that we can name
    (no ``generate(package, node, "Name")`` with a literal name)."""
    try:
        tree = ast.parse(text, filename=path)
    except (SyntaxError, ValueError, MemoryError, RecursionError) as error:
        line = getattr(error, "lineno", None) or 0
        return None, [diag.make("RECONFIGURE_CFG_INVALID", Location(package, path, line),
                                detail=str(getattr(error, "msg", error)))]
    name: str | None = None
    config = Config(package, "", path)
    # the generator and its groups: handed to a function we do not read (navigation's
    # ``add_generic_localplanner_params(gen)``, imported from another module), they may
    # get parameters we cannot see
    generators = {target.id for node in ast.walk(tree) if isinstance(node, ast.Assign)
                  and isinstance(node.value, ast.Call) and _makes_generator(node.value)
                  for target in node.targets if isinstance(target, ast.Name)}
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and any(
            isinstance(arg, ast.Name) and arg.id in generators
            for arg in [*node.args, *(k.value for k in node.keywords)]
        ):
            config.partial = True
        if not isinstance(node, ast.Call) or not isinstance(node.func, ast.Attribute):
            continue
        method = node.func.attr
        if method == "generate":
            found = _literal(_argument(node, 2, "name"))
            if isinstance(found, str) and _NAME.fullmatch(found):
                name = found
        elif method == "add" and len(node.args) + len(node.keywords) >= 4:
            kind = _type_name(_argument(node, 1, "paramtype"))
            if kind is None:
                continue  # not a parameter's add (a set's, a list's)
            written = _literal(_argument(node, 0, "name"))
            if not isinstance(written, str) or not _NAME.fullmatch(written):
                config.partial = True
                continue
            default = _literal(_argument(node, 4, "default"))
            config.parameters.append((written, kind, default))
        elif method == "const":
            written = _literal(_argument(node, 0, "name"))
            kind = _type_name(_argument(node, 1, "paramtype"))
            value = _literal(_argument(node, 2, "value"))
            if isinstance(written, str) and _NAME.fullmatch(written) and kind is not None:
                config.constants.append((written, kind, value))
    if name is None:
        return None, []
    config.name = name
    first: dict[str, tuple[str, str, Any]] = {}
    for parameter in config.parameters:  # a name added twice: the first
        first.setdefault(parameter[0], parameter)
    config.parameters = list(first.values())
    return config, []


def configs(folder: str, package: str) -> tuple[dict[str, Config], list[Diagnostic]]:
    """The configs of a package's ``cfg/*.cfg`` by class name (``NameConfig``)."""
    found: dict[str, Config] = {}
    problems: list[Diagnostic] = []
    cfg = os.path.join(folder, "cfg")
    try:
        files = sorted(f for f in os.listdir(cfg) if f.endswith(".cfg"))
    except OSError:
        return found, problems
    for file in files:
        path = os.path.join(cfg, file)
        try:
            if os.path.getsize(path) > MAX_CFG_BYTES:
                continue
        except OSError:
            continue
        text, read_problems = read_text(path, Location(package, path))
        problems += read_problems
        if text is None:
            continue
        config, more = read_cfg(path, text, package)
        problems += more
        if config is not None:
            found.setdefault(config.name + "Config", config)
    return found, problems


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
             f"namespace {config.package} {{",
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
             "};", f"}}  // namespace {config.package}", ""]
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
