"""ROS 2 message, service and action headers we synthesise: ``pkg/msg/laser_scan.hpp``
declares ``pkg::msg::LaserScan`` as ``rosidl_generator_cpp`` would, as far as parsing node
code needs (fields, constants, ``SharedPtr`` / ``ConstSharedPtr`` / ``UniquePtr``, a
service's ``Request`` / ``Response``, an action's ``Goal`` / ``Result`` / ``Feedback``).
"""

from __future__ import annotations

import re

from .interfaces import Field, Interface, fields_hook, qualified, string_literal

KINDS = ("msg", "srv", "action")
PRIMITIVES = {
    "bool": "bool", "int8": "int8_t", "uint8": "uint8_t", "byte": "uint8_t",
    "char": "uint8_t", "int16": "int16_t", "uint16": "uint16_t", "int32": "int32_t",
    "uint32": "uint32_t", "int64": "int64_t", "uint64": "uint64_t", "float32": "float",
    "float64": "double", "string": "std::string", "wstring": "std::u16string",
}
BUILTIN = {"time": "builtin_interfaces/Time", "duration": "builtin_interfaces/Duration"}
_BOUNDED = re.compile(r"^(w?string)<=\d+$")


def snake_case(name: str) -> str:
    """``LaserScan`` -> ``laser_scan``, ``TFMessage`` -> ``tf_message`` (rosidl's rule)."""
    name = re.sub(r"(.)([A-Z][a-z]+)", r"\1_\2", name)
    return re.sub(r"([a-z0-9])([A-Z])", r"\1_\2", name).lower()


def camel_case(snake: str, candidates: list[str] = ()) -> str:  # type: ignore[assignment]
    """The type name a header's file name stands for: one of ``candidates`` (names seen
    in the package's files) whose snake case it is, else each word capitalised."""
    for candidate in candidates:
        if snake_case(candidate) == snake:
            return candidate
    return "".join(word[:1].upper() + word[1:] for word in snake.split("_"))


def header(package: str, kind: str, name: str) -> str:
    return f"{package}/{kind}/{snake_case(name)}.hpp"


def dependencies(interface: Interface) -> list[str]:
    """Headers of the message types the fields use."""
    found: list[str] = []
    for section in interface.sections:
        for fld in section:
            full = _full(fld.type, interface.package)
            if full is not None:
                pkg, name = full.split("/")
                path = header(pkg, "msg", name)
                if path not in found:
                    found.append(path)
    return found


def _full(kind: str, package: str) -> str | None:
    kind = _BOUNDED.sub(r"\1", kind)
    if kind in PRIMITIVES:
        return None
    if kind in BUILTIN:
        return BUILTIN[kind]
    return qualified(kind, package)


def render(interface: Interface, kind: str) -> str:
    """C++ source of ``pkg/<kind>/<name>.hpp`` for a message, service or action."""
    pkg, name = interface.package, interface.name
    guard = f"HAROS_SYNTH2_{pkg.upper()}_{kind.upper()}_{name.upper()}_HPP"
    lines = [f"// synthesised by haros_arch for {pkg}/{kind}/{name}", f"#ifndef {guard}",
             f"#define {guard}", "#include <cstdint>", "#include <string>", "#include <vector>",
             "#include <array>", "#include <memory>"]
    lines += [f"#include <{dep}>" for dep in dependencies(interface)
              if dep != header(pkg, kind, name)]
    lines.append(f"namespace {pkg} {{ namespace {kind} {{")
    sections = interface.sections or [[]]
    parts: tuple[str, ...] = ()
    if kind == "srv":
        parts = ("Request", "Response")
    elif kind == "action":
        parts = ("Goal", "Result", "Feedback")
    if not parts:
        lines += _struct(name, sections[0], pkg, kind, interface.known)
    else:
        sections = [*sections, [], [], []][:len(parts)]
        for part, fields in zip(parts, sections, strict=True):
            lines += _struct(f"{name}_{part}", fields, pkg, kind, interface.known)
        lines.append(f"struct {name} {{")
        lines += [f"  using {part} = {name}_{part};" for part in parts]
        if kind == "action":
            lines += ["  struct Impl { struct SendGoalService { struct Request {}; "
                      "struct Response {}; }; }; };"]
        lines.append("};")
    lines += [f"}} }}  // namespace {pkg}::{kind}", "#endif", ""]
    return "\n".join(lines)


def _struct(name: str, fields: list[Field], package: str, kind: str = "msg",
            known: bool = True) -> list[str]:
    lines = [f"struct {name} {{", f"  {name}();"]
    if not known:
        lines += fields_hook(f"{package}::{kind}::{name}")
    for fld in fields:
        cpp = _cpp_type(fld.type, package)
        if fld.constant is not None:
            if cpp == "std::string":
                lines.append(f"  static inline const std::string {fld.name} = "
                             f"{string_literal(fld.constant)};")
            else:
                value = fld.constant if re.fullmatch(r"-?\d+(\.\d*)?([eE]-?\d+)?",
                                                     fld.constant) else "0"
                lines.append(f"  static constexpr {cpp} {fld.name} = {value};")
        else:
            if fld.array is not None and fld.array:
                cpp = f"std::array<{cpp}, {fld.array}>"
            elif fld.array is not None:
                cpp = f"std::vector<{cpp}>"
            # the generated setter of each field (``header.set__frame_id("map")``)
            lines += [f"  {cpp} {fld.name};", f"  using _{fld.name}_type = {cpp};",
                      f"  {name}& set__{fld.name}(const {cpp}& _arg);"]
    lines += [f"  bool operator==(const {name}& other) const;",
              f"  bool operator!=(const {name}& other) const;",
              f"  using SharedPtr = std::shared_ptr<{name}>;",
              f"  using ConstSharedPtr = std::shared_ptr<const {name}>;",
              f"  using UniquePtr = std::unique_ptr<{name}>;",
              f"  using WeakPtr = std::weak_ptr<{name}>;", "};",
              # rosidl's YAML of a message, beside it (``RCLCPP_INFO_STREAM(logger,
              # geometry_msgs::msg::to_yaml(pose))``)
              f"std::string to_yaml(const {name}& msg, bool use_flow_style = false);",
              f"std::string to_flow_style_yaml(const {name}& msg);",
              f"std::string to_block_style_yaml(const {name}& msg);"]
    return lines


def _cpp_type(kind: str, package: str) -> str:
    bare = _BOUNDED.sub(r"\1", kind)
    full = _full(bare, package)
    if full is None:
        return PRIMITIVES[bare]
    pkg, name = full.split("/")
    return f"{pkg}::msg::{name}"
