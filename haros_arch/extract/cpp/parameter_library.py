"""generate_parameter_library: the header it generates at build time, from the YAML.

PickNik's generate_parameter_library (``generate_parameter_library(target params.yaml)``
in CMake, recorded by ``haros_arch.cmake``) writes ``<PROJECT_NAME>/<target>.hpp`` when
the package is built. Its YAML has one top-level key, the namespace; under it a mapping
whose values are mappings is a nested struct, and a mapping that holds ``type`` is a
parameter (``default_value``, ``read_only``, ``validation``, ...). A ``__map_<key>``
struct is one entry per element of the list parameter ``<key>`` (looked up from the
struct's scope outwards): its parameters are ``<struct>.<element>.<field>``.

No build happens here, so the header is synthesised from the YAML (``render``): the
``Params`` struct with the fields typed as the library types them, and ``ParamListener``
with its constructors and methods, declarations only. The class carries one
``annotate`` attribute per parameter the listener declares (``listener_parameters``
reads them back from the parsed class): the visitor turns the construction of a
listener into one ``declare`` per parameter, on the node it is given.
"""

from __future__ import annotations

import json
import os
import re
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

import yaml
from clang.cindex import Cursor, CursorKind, TypeKind

from ... import diagnostics as diag
from ... import safe_yaml
from ...diagnostics import Diagnostic
from ...files import read_text
from ...workspace import Workspace

LISTENER = "ParamListener"
MAP = "__map_"
_LISTENER_MARK = "haros_arch.parameter_listener"  # the annotation of a synthesised listener
_PARAMS_MARK = "haros_arch.parameter_struct"  # the annotation of its ``Params`` struct
MAX_FIELD_DEPTH = 20  # the members of a chain read for the parameter it holds
_MARK = "haros_arch.parameter "  # the annotation of one parameter the listener declares
_NAME = re.compile(r"[A-Za-z_]\w*")
# the library's YAML types: C++ field type, ROS parameter type (as the extractor writes
# them: ``list`` for arrays)
_SCALARS = {"bool": ("bool", "bool"), "int": ("int64_t", "int"),
            "double": ("double", "double"), "string": ("std::string", "str")}
_FIXED = re.compile(r"(bool|int|double|string)(_array)?_fixed_\d+")


@dataclass(frozen=True)
class Target:
    """One ``generate_parameter_library`` call of a package."""

    name: str  # the CMake target, the header's name
    yaml: str  # absolute path
    project: str  # PROJECT_NAME: the header is ``<project>/<name>.hpp``
    package: str


@dataclass(frozen=True)
class Parameter:
    name: str  # dotted, ``__map_<key>`` segments kept
    kind: str  # the library's type, as written
    has_default: bool
    default: Any


def targets(workspace: Workspace) -> list[Target]:
    """The ``generate_parameter_library`` calls of the workspace's packages (those whose
    top CMakeLists.txt names the command: the others are not interpreted)."""
    from ... import cmake  # the C++ extractor is imported by the pipeline, after cmake

    found: list[Target] = []
    for package in sorted(workspace.packages.values(), key=lambda p: p.name):
        path = os.path.join(package.root, "CMakeLists.txt") if package.root else ""
        if not path or not os.path.isfile(path):
            continue
        text, _ = read_text(path, workspace.location(path))
        if text is None or "generate_parameter_library" not in text:
            continue
        interpreter, _ = cmake.interpret(package, workspace)
        found += [Target(name, yaml_path, project or package.name, package.name)
                  for name, yaml_path, project in interpreter.parameter_libraries]
    return found


def header_target(header: str, known: list[Target], package: str) -> Target | None:
    """The target whose generated header ``header`` names: ``<project>/<target>.hpp``,
    or ``<target>.hpp`` (the including package's first)."""
    folder, _, base = header.replace("\\", "/").rpartition("/")
    name, dot, extension = base.rpartition(".")
    if not dot or extension not in ("hpp", "h") or "/" in folder:
        return None
    matches = [t for t in known if t.name == name and (not folder or t.project == folder)]
    return next((t for t in matches if t.package == package), None) or next(
        iter(matches), None)


def load(target: Target, workspace: Workspace
         ) -> tuple[tuple[str, dict[str, Any]] | None, list[Diagnostic]]:
    """The namespace and the tree under it of the target's YAML; None with a diagnostic
    (file and line) when it cannot be read or is not shaped as the library wants."""
    text, found = read_text(target.yaml, workspace.location(target.yaml))
    if text is None:
        return None, found
    try:
        document = safe_yaml.load(text)
    except (yaml.YAMLError, ValueError) as err:
        mark = getattr(err, "problem_mark", None)
        where = workspace.location(target.yaml, mark.line + 1 if mark else 0,
                                   mark.column + 1 if mark else 0)
        detail = str(getattr(err, "problem", None) or err)
        return None, [*found, diag.make("CPP_PARAMETER_LIBRARY", where, target=target.name,
                                        detail=detail)]
    if not (isinstance(document, dict) and len(document) == 1):
        detail = "not a mapping with one key, the namespace"
    else:
        namespace, tree = next(iter(document.items()))
        if isinstance(namespace, str) and _namespace(namespace) and isinstance(tree, dict):
            return (namespace, tree), found
        detail = f"the namespace {str(namespace)[:60]!r} is not a C++ namespace holding a mapping"
    return None, [*found, diag.make("CPP_PARAMETER_LIBRARY", workspace.location(
        target.yaml, 1, 1), target=target.name, detail=detail)]


def _namespace(name: str) -> bool:
    return all(_NAME.fullmatch(part) for part in name.split("::"))


def _is_parameter(value: object) -> bool:
    """A leaf of the tree: the library reads a mapping whose first value is not a
    mapping as a parameter."""
    return isinstance(value, dict) and bool(value) and not isinstance(
        next(iter(value.values())), dict)


def parameters(tree: dict[str, Any], prefix: str = "") -> Iterator[Parameter]:
    """The parameters of the tree, in the YAML's order."""
    for key, value in tree.items():
        if not isinstance(key, str) or not isinstance(value, dict):
            continue
        name = f"{prefix}{key}"
        if _is_parameter(value):
            kind = value.get("type")
            if isinstance(kind, str):
                yield Parameter(name, kind, "default_value" in value,
                                value.get("default_value"))
        elif value:
            yield from parameters(value, name + ".")


def cpp_type(kind: str) -> str | None:
    """The C++ type of a field of the library's type ``kind`` (None: no field). A fixed
    size type (``string_fixed_25``, ``double_array_fixed_10``) is declared as its
    unbounded type: the library's rsl containers convert to and from them."""
    fixed = _FIXED.fullmatch(kind)
    if fixed is not None:
        kind = fixed.group(1) + (fixed.group(2) or "")
    if kind in _SCALARS:
        return _SCALARS[kind][0]
    if kind.endswith("_array") and kind[: -len("_array")] in _SCALARS:
        return f"std::vector<{_SCALARS[kind[: -len('_array')]][0]}>"
    return None


def parameter_type(kind: str) -> str | None:
    """The ROS parameter type of the library's type ``kind``, as the extractor writes it."""
    fixed = _FIXED.fullmatch(kind)
    if fixed is not None:
        kind = fixed.group(1) + (fixed.group(2) or "")
    if kind in _SCALARS:
        return _SCALARS[kind][1]
    element = kind.removesuffix("_array")
    # an array as the extractor writes std::vector<T>'s: T[] (string_array: str[])
    return f"{_SCALARS[element][1]}[]" if element != kind and element in _SCALARS else None


def _pascal(name: str) -> str:
    return "".join(word.title() for word in name.split("_"))


def _struct(tree: dict[str, Any], indent: str) -> list[str]:
    """The fields and nested structs of one level of the tree."""
    lines: list[str] = []
    for key, value in tree.items():
        if not isinstance(key, str) or not isinstance(value, dict) or not value:
            continue
        if _is_parameter(value):
            ctype = cpp_type(str(value.get("type", "")))
            if ctype is not None and _NAME.fullmatch(key):
                lines.append(f"{indent}{ctype} {key};")
            continue
        if key.startswith(MAP) and _NAME.fullmatch(key):
            lines.append(f"{indent}struct {_pascal(key)} {{")
            lines += _struct(value, indent + "  ")
            lines.append(f"{indent}}};")
            lines.append(f"{indent}std::map<std::string, {_pascal(key)}> "
                         f"{key[len(MAP):]}_map;")
        elif _NAME.fullmatch(key):
            lines.append(f"{indent}struct {_pascal(key)} {{")
            lines += _struct(value, indent + "  ")
            lines.append(f"{indent}}} {key};")
    return lines


def declared(tree: dict[str, Any]) -> list[tuple[str, str | None, bool, Any, str | None]]:
    """What a listener declares: (name, ROS type, has default, default, list) per
    parameter. A parameter under one ``__map_<key>`` is one per element of the list
    parameter ``<key>`` (looked up from its scope outwards) in the configuration: named
    with ``?`` for the element, and ``list`` names that parameter (the graph makes one
    declare per element of its value: the launch files', else its default; without one,
    the ``?`` stays). Under several, each ``__map_`` is the elements of its list's
    default, or ``?``, and ``list`` is None."""
    found: list[tuple[str, str | None, bool, Any, str | None]] = []
    every = {p.name: p for p in parameters(tree)}
    for param in every.values():
        kind = parameter_type(param.kind)
        if kind is None:
            continue  # ``none``: no value
        listed = _mapped_over(param.name, every)
        if listed is not None:
            found.append((listed[0], kind, param.has_default, param.default, listed[1]))
            continue
        for name in _expanded(param.name, every):
            found.append((name, kind, param.has_default, param.default, None))
    return found


def _mapped_over(name: str, every: dict[str, Parameter]) -> tuple[str, str] | None:
    """``name`` with its one ``__map_<key>`` segment (not the last) as ``?``, and the
    list parameter ``<key>`` it maps over; None for a name of no or several such
    segments, or whose list is not a parameter of the YAML."""
    segments = name.split(".")
    maps = [i for i, s in enumerate(segments[:-1]) if s.startswith(MAP)]
    if len(maps) != 1:
        return None
    index = maps[0]
    listed = _list_parameter(segments[index][len(MAP):], segments[:index], every)
    if listed is None:
        return None
    return ".".join([*segments[:index], "?", *segments[index + 1:]]), listed


def _expanded(name: str, every: dict[str, Parameter]) -> list[str]:
    """The declared names of ``name``: each ``__map_<key>`` segment replaced by the
    elements of the default of ``<key>`` (from its scope outwards), or by ``?``."""
    names = [""]
    segments = name.split(".")
    for index, segment in enumerate(segments):
        if not segment.startswith(MAP) or index == len(segments) - 1:
            names = [f"{n}.{segment}" if n else segment for n in names]
            continue
        keys = _keys(segment[len(MAP):], segments[:index], every)
        names = [f"{n}.{k}" if n else k for n in names for k in keys]
    return names


def _list_parameter(key: str, scope: list[str], every: dict[str, Parameter]) -> str | None:
    """The name of the parameter ``key`` from ``scope`` outwards, as the library looks
    a ``__map_<key>``'s list up; None when the YAML has none."""
    plain = [s for s in scope if not s.startswith(MAP)]  # the library's struct name
    while True:
        candidate = ".".join([*plain, key])
        if candidate in every:
            return candidate
        if not plain:
            return None
        plain.pop()


def _keys(key: str, scope: list[str], every: dict[str, Parameter]) -> list[str]:
    listed = _list_parameter(key, scope, every)
    value = every[listed].default if listed is not None else None
    if isinstance(value, list) and value and all(isinstance(v, str) and v for v in value):
        return list(dict.fromkeys(value))
    return ["?"]


def annotation(text: str) -> str:
    """The attribute that carries ``text`` on a synthesised class (read back from the
    parse as an ``ANNOTATE_ATTR`` child: ``listener_parameters``, ``reconfigure``)."""
    escaped = text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n")
    return f'__attribute__((annotate("{escaped}")))'


def render(target: Target, namespace: str, tree: dict[str, Any], source: str) -> str:
    """The header ``generate_parameter_library`` would write, declarations only."""
    notes = [annotation(text) for text in (
        _LISTENER_MARK, *(_MARK + json.dumps(entry, default=str)  # a YAML date: text
                         for entry in declared(tree)))]
    lines = [f"// {target.project}/{target.name}.hpp, as generate_parameter_library writes "
             f"it from {source}: synthesised by haros_arch, declarations only",
             "#pragma once", "#include <cstdint>", "#include <functional>",
             "#include <map>", "#include <memory>", "#include <string>", "#include <vector>",
             "#include <rclcpp/rclcpp.hpp>", "#include <rclcpp_lifecycle/lifecycle_node.hpp>",
             f"namespace {namespace} {{", f"struct {annotation(_PARAMS_MARK)} Params {{",
             *_struct(tree, "  "),
             "  rclcpp::Time __stamp;", "};",
             f"class {' '.join(notes)} {LISTENER} {{", " public:",
             "  template <typename NodeT>",
             f'  {LISTENER}(NodeT node, std::string const & prefix = "");',
             f"  {LISTENER}(const std::shared_ptr<rclcpp::node_interfaces::"
             'NodeParametersInterface> & parameters_interface, std::string const & prefix = "");',
             f"  {LISTENER}(const std::shared_ptr<rclcpp::node_interfaces::"
             "NodeParametersInterface> & parameters_interface, rclcpp::Logger logger, "
             'std::string const & prefix = "");',
             "  Params get_params() const;",
             "  bool try_get_params(Params & params_in) const;",
             "  bool try_update_params(Params & params_in) const;",
             "  bool is_old(Params const & other) const;",
             "  void refresh_dynamic_parameters();",
             "  rcl_interfaces::msg::SetParametersResult update("
             "const std::vector<rclcpp::Parameter> & parameters);",
             "  void declare_params();",
             "  using userParameterUpdateCB = std::function<void(const Params &)>;",
             "  void setUserCallback(const userParameterUpdateCB & callback);",
             "  void clearUserCallback();",
             "};", f"}}  // namespace {namespace}", ""]
    return "\n".join(lines)


def field_parameter(expr: Cursor) -> str | None:
    """The parameter a member chain of a synthesised ``Params`` struct holds:
    ``params_.use_local_topics`` is ``use_local_topics``, ``params_.limits.max_velocity``
    ``limits.max_velocity`` (the listener's own names, before any prefix); None for any
    other expression (a ``__map_`` struct's entry is read through ``at()``)."""
    names: list[str] = []
    node = expr
    for _depth in range(MAX_FIELD_DEPTH):
        target = node.referenced if node.kind == CursorKind.MEMBER_REF_EXPR else None
        if target is None or target.kind != CursorKind.FIELD_DECL:
            return None  # not a field: ``params_.topic.empty()``'s ``empty``
        names.insert(0, node.spelling)
        below = [c for c in node.get_children() if c.kind.is_expression()]
        if len(below) != 1:
            return None
        node = below[0]
        while node.kind == CursorKind.UNEXPOSED_EXPR and len(list(node.get_children())) == 1:
            node = next(iter(node.get_children()))
        kind = node.type.get_canonical()
        if kind.kind == TypeKind.POINTER:
            kind = kind.get_pointee().get_canonical()
        decl = kind.get_declaration()
        if decl is not None and decl.kind == CursorKind.STRUCT_DECL and any(
                c.kind == CursorKind.ANNOTATE_ATTR and c.spelling == _PARAMS_MARK
                for c in decl.get_children()):
            return ".".join(names)
    return None


def listener_parameters(cls: Cursor | None
                        ) -> list[tuple[str, str | None, bool, Any, str | None]] | None:
    """The parameters a synthesised ``ParamListener`` class declares (its annotations,
    as ``declared`` lists them); None when ``cls`` is not one."""
    if cls is None or cls.spelling != LISTENER:
        return None
    found: list[tuple[str, str | None, bool, Any, str | None]] = []
    marked = False
    for child in cls.get_children():
        if child.kind != CursorKind.ANNOTATE_ATTR:
            continue
        marked = marked or child.spelling == _LISTENER_MARK
        if child.spelling.startswith(_MARK):
            try:
                name, kind, has_default, default, listed = json.loads(
                    child.spelling[len(_MARK):])
            except (ValueError, TypeError):
                continue
            found.append((str(name), kind, bool(has_default), default,
                          str(listed) if listed is not None else None))
    return found if marked else None
