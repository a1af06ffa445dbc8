"""ROS 2 message, service and action headers we synthesise: ``pkg/msg/laser_scan.hpp``
declares ``pkg::msg::LaserScan`` as ``rosidl_generator_cpp`` would, as far as parsing node
code needs (fields, constants, ``SharedPtr`` / ``ConstSharedPtr`` / ``UniquePtr``, a
service's ``Request`` / ``Response``, an action's ``Goal`` / ``Result`` / ``Feedback``).
"""

from __future__ import annotations

import re

from .interfaces import (
    Field,
    Interface,
    constant_value,
    fields_hook,
    qualified,
    string_literal,
    template_name,
)

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


# what an action's ``Impl`` names besides its own parts (rosidl_generator_cpp's
# ``action_msgs::msg::GoalStatusArray`` and ``action_msgs::srv::CancelGoal``) and the
# fields of its SendGoal / GetResult / FeedbackMessage parts
ACTION_HEADERS = ("unique_identifier_msgs/msg/uuid.hpp", "builtin_interfaces/msg/time.hpp",
                  "action_msgs/msg/goal_status_array.hpp", "action_msgs/srv/cancel_goal.hpp")


def dependencies(interface: Interface, kind: str = "msg") -> list[str]:
    """Headers of the message types the fields use (and, for an action, those its
    ``Impl`` types use)."""
    found: list[str] = list(ACTION_HEADERS) if kind == "action" else []
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
    lines += [f"#include <{dep}>" for dep in dependencies(interface, kind)
              if dep != header(pkg, kind, name)]
    lines.append(f"namespace {pkg} {{ namespace {kind} {{")
    sections = interface.sections or [[]]
    parts: tuple[str, ...] = ()
    if kind == "srv":
        parts = ("Request", "Response")
    elif kind == "action":
        parts = ("Goal", "Result", "Feedback")
    built: list[tuple[str, list[Field]]] = []  # the structs given a builder
    if not parts:
        lines += _struct(name, sections[0], pkg, kind, interface.known)
        built.append((name, sections[0]))
    else:
        sections = [*sections, [], [], []][:len(parts)]
        for part, fields in zip(parts, sections, strict=True):
            lines += _struct(f"{name}_{part}", fields, pkg, kind, interface.known)
            built.append((f"{name}_{part}", fields))
        if kind == "action":
            lines += _action_impl_parts(name)
        lines.append(f"struct {name} {{")
        lines += [f"  using {part} = {name}_{part};" for part in parts]
        if kind == "action":
            # rosidl's ``Impl``: the services and topics an action is made of, as
            # templated code names them (``typename ActionT::Impl::SendGoalService``)
            lines += ["  struct Impl {",
                      f"    using SendGoalService = {name}_SendGoal;",
                      f"    using GetResultService = {name}_GetResult;",
                      f"    using FeedbackMessage = {name}_FeedbackMessage;",
                      "    using GoalStatusMessage = action_msgs::msg::GoalStatusArray;",
                      "    using CancelGoalService = action_msgs::srv::CancelGoal;", "  };"]
        lines.append("};")
    if interface.known:
        lines += [line for struct, fields in built for line in _initialisers(struct, fields)]
    lines.append(f"}} }}  // namespace {pkg}::{kind}")
    # a message known only by name has a builder too (another of its package may be
    # known, which declares ``build`` for all): the message itself, whose fields the
    # parse learns from the chain as from ``msg.field`` (``fields_hook``)
    lines += _builders(pkg, kind, built if interface.known else [
        (struct, []) for struct, _ in built])
    lines += traits(pkg, kind, name)
    lines += ["#endif", ""]
    return "\n".join(lines)


def _initialisers(struct: str, fields: list[Field]) -> list[str]:
    """rosidl_generator_cpp's builder of a struct (``detail/*__builder.hpp``): one class
    per field, in the definition's order, whose method named after the field takes its
    value and gives the next field's class, the last one the struct itself
    (``geometry_msgs::build<Pose>().position(p).orientation(q)`` is a ``Pose``), in the
    namespace ``builder`` of the struct's."""
    names = [fld.name for fld in fields if fld.constant is None]
    lines = ["namespace builder {"]
    for index in range(len(names) - 1, -1, -1):
        field = names[index]
        after = f"Init_{struct}_{names[index + 1]}" if index + 1 < len(names) else struct
        lines += [f"class Init_{struct}_{field} {{", "public:",
                  f"  {after} {field}({struct}::_{field}_type arg);", "};"]
    return [*lines, "}  // namespace builder"]


def _builders(pkg: str, kind: str, built: list[tuple[str, list[Field]]]) -> list[str]:
    """rosidl's ``pkg::build<T>()`` of each struct: its first field's builder class, or
    the struct itself when it has no field (declared again by every header of the
    package, as the generated headers do)."""
    lines = [f"namespace {pkg} {{", "template<class MessageType> auto build();"]
    for struct, fields in built:
        names = [fld.name for fld in fields if fld.constant is None]
        made = f"{kind}::builder::Init_{struct}_{names[0]}" if names else f"{kind}::{struct}"
        lines.append(f"template<> inline auto build<::{pkg}::{kind}::{struct}>() "
                     f"{{ return {made}(); }}")
    return [*lines, f"}}  // namespace {pkg}"]


def traits(pkg: str, kind: str, name: str) -> list[str]:
    """rosidl_generator_cpp's traits of an interface (``detail/*__traits.hpp``): each
    message, a service's request and response, an action's goal, result and feedback
    (and the messages of its services) is a message; the service, the action itself.
    Code chooses overloads on them (autoware_utils' ``DebugPublisher::publish<T>``).
    Given where rosidl_runtime_cpp's traits are declared (the rclcpp stand-in includes
    them; a system's real header has the same guard)."""
    scope = f"{pkg}::{kind}::"
    if kind == "msg":
        flags = [("is_message", name)]
    elif kind == "srv":
        flags = [("is_service", name), ("is_message", f"{name}_Request"),
                 ("is_service_request", f"{name}_Request"),
                 ("is_message", f"{name}_Response"),
                 ("is_service_response", f"{name}_Response")]
    else:
        flags = [("is_action", name), ("is_message", f"{name}_Goal"),
                 ("is_action_goal", f"{name}_Goal"), ("is_message", f"{name}_Result"),
                 ("is_action_result", f"{name}_Result"), ("is_message", f"{name}_Feedback"),
                 ("is_action_feedback", f"{name}_Feedback"),
                 ("is_message", f"{name}_FeedbackMessage"),
                 *((trait, f"{name}_{service}_{part}") for service in ("SendGoal", "GetResult")
                   for trait, part in (("is_message", "Request"), ("is_message", "Response"))),
                 *(("is_service", f"{name}_{service}") for service in ("SendGoal", "GetResult"))]
    lines = ["#if __has_include(<rosidl_runtime_cpp/traits.hpp>)",
             "#include <rosidl_runtime_cpp/traits.hpp>", "#endif",
             "#ifdef ROSIDL_RUNTIME_CPP__TRAITS_HPP_"]
    for trait, struct in flags:
        # one guard per specialisation: the rclcpp stand-in specialises those of the
        # messages it defines itself the same way
        guard = f"HAROS_TRAIT_{trait}_{pkg}_{kind}_{struct}".upper()
        lines += [f"#ifndef {guard}", f"#define {guard}",
                  f"template<> struct rosidl_generator_traits::{trait}<{scope}{struct}>"
                  " : std::true_type {};", "#endif"]
    return [*lines, "#endif"]


def _action_impl_parts(name: str) -> list[str]:
    """``Name_SendGoal``, ``Name_GetResult`` (services of a Request and a Response) and
    ``Name_FeedbackMessage``, with the fields rosidl gives them."""
    lines: list[str] = []
    uuid = "unique_identifier_msgs::msg::UUID"
    for struct, fields in (
            (f"{name}_SendGoal_Request", [(uuid, "goal_id"), (f"{name}_Goal", "goal")]),
            (f"{name}_SendGoal_Response", [("bool", "accepted"),
                                           ("builtin_interfaces::msg::Time", "stamp")]),
            (f"{name}_GetResult_Request", [(uuid, "goal_id")]),
            (f"{name}_GetResult_Response", [("int8_t", "status"),
                                            (f"{name}_Result", "result")]),
            (f"{name}_FeedbackMessage", [(uuid, "goal_id"),
                                         (f"{name}_Feedback", "feedback")])):
        lines += [f"struct {struct} {{", f"  {struct}();"]
        lines += [f"  {cpp} {field};" for cpp, field in fields]
        lines += [*_pointer_types(struct), "};", template_name(struct)]
    for service in ("SendGoal", "GetResult"):
        lines += [f"struct {name}_{service} {{",
                  f"  using Request = {name}_{service}_Request;",
                  f"  using Response = {name}_{service}_Response;", "};"]
    return lines


def _pointer_types(name: str) -> list[str]:
    """The pointer types rosidl_generator_cpp gives a struct, with ROS 1's ``Ptr`` and
    ``ConstPtr`` it keeps (deprecated) for code ported from ROS 1."""
    return [f"  using RawPtr = {name} *;", f"  using ConstRawPtr = const {name} *;",
            f"  using SharedPtr = std::shared_ptr<{name}>;",
            f"  using ConstSharedPtr = std::shared_ptr<const {name}>;",
            f"  using UniquePtr = std::unique_ptr<{name}>;",
            f"  using ConstUniquePtr = std::unique_ptr<const {name}>;",
            f"  using WeakPtr = std::weak_ptr<{name}>;",
            f"  using ConstWeakPtr = std::weak_ptr<const {name}>;",
            f"  typedef std::shared_ptr<{name}> Ptr;",
            f"  typedef std::shared_ptr<const {name}> ConstPtr;"]


def _struct(name: str, fields: list[Field], package: str, kind: str = "msg",
            known: bool = True) -> list[str]:
    lines = [f"struct {name} {{", f"  {name}();"]
    if not known:
        lines += fields_hook(f"{package}::{kind}::{name}")
    for fld in fields:
        cpp = _cpp_type(fld.type, package)
        if fld.constant is not None:
            if cpp == "std::string":  # rosidl's value: without its outer quotes
                value = constant_value(fld.type, fld.constant, ros2=True)
                lines.append(f"  static inline const std::string {fld.name} = "
                             f"{string_literal(str(value))};")
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
    if known and not any(fld.constant is None for fld in fields):
        # rosidl_generator_cpp gives a message without fields one placeholder member,
        # which code may set (``request->structure_needs_at_least_one_member = 0``)
        lines.append("  uint8_t structure_needs_at_least_one_member;")
    lines += [f"  bool operator==(const {name}& other) const;",
              f"  bool operator!=(const {name}& other) const;",
              *_pointer_types(name), "};", template_name(name),
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
