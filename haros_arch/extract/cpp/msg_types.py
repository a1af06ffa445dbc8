"""ROS type names from C++ types: ``std_msgs::String::ConstPtr`` -> ``std_msgs/String``.

Works on the canonical type so typedefs (``ConstPtr``, ``StringConstPtr``, ``Request``) and
the real headers' templates (``std_msgs::String_<std::allocator<void>>``) all lead to the
same struct: its namespaces and name give the ROS 1 name.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

from clang.cindex import Cursor, CursorKind, Type, TypeKind

from .expressions import strip, stripped_to_cast

_RECORDS = (CursorKind.STRUCT_DECL, CursorKind.CLASS_DECL, CursorKind.CLASS_TEMPLATE,
            CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION)
_POINTERS = ("shared_ptr", "MessageEvent", "unique_ptr")
_ADAPTERS = ("TypeAdapter", "ImplicitTypeAdapter")
_REFERENCES = (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE, TypeKind.POINTER)

_PARAM_TYPES = {
    TypeKind.BOOL: "bool", TypeKind.INT: "int", TypeKind.UINT: "int", TypeKind.LONG: "int",
    TypeKind.ULONG: "int", TypeKind.LONGLONG: "int", TypeKind.ULONGLONG: "int",
    TypeKind.SHORT: "int", TypeKind.USHORT: "int", TypeKind.FLOAT: "double",
    TypeKind.DOUBLE: "double",
}
# rclcpp's byte array parameter (``PARAMETER_BYTE_ARRAY``), the ``std::vector<uint8_t>``
# a ParameterValue holds; roscpp has no such parameter type (getParam takes no vector of
# bytes), so only ROS 2 code names it
BYTE_ARRAY = "byte[]"
_BYTES = frozenset({"uint8_t", "std::uint8_t", "unsigned char"})


def message_type(ctype: Type, service: bool = False,
                 adapters: Mapping[str, Type] | None = None,
                 ros2: bool | None = None) -> str | None:
    """The ROS name of the message (or, with ``service``, service) type ``ctype`` holds;
    a type adapter (``rclcpp::TypeAdapter<Custom, Ros>``) or a custom type ``adapters``
    maps to its ROS message type (by canonical spelling) holds that ROS type; a
    ``pcl::PointCloud<T>`` is a ``sensor_msgs/PointCloud2`` (pcl_ros)."""
    record = _record(ctype, 0, adapters or {})
    if record is None:
        return None
    decl, templated = record
    name = decl.spelling
    if templated and name.endswith("_"):
        name = name[:-1]
    parent = decl.semantic_parent
    if name in ("Request", "Response") and parent is not None and parent.kind in _RECORDS:
        name, parent = parent.spelling, parent.semantic_parent
    elif service:
        for suffix in ("Request", "Response"):
            if name.endswith(suffix) and len(name) > len(suffix):
                name = name[: -len(suffix)]
                break
    scopes = _namespaces(parent)
    if not scopes and _synthesised(decl) and parent is not None and parent.kind in _RECORDS:
        # ``pkg::Msg::ConstPtr`` where ``pkg::Msg`` is also used as a type: both declared
        # for names the parse did not know, the pointer a class inside the message's
        scopes = _synthesised_scopes(parent)
    if not scopes or not name:
        return None
    if templated and (cloud := template_message(decl, ros2)) is not None:
        return cloud
    if _synthesised(decl):  # declared for a name the parse did not know (``synthesis``)
        return written_type("::".join([*scopes, name]), ros2, used_as_message=True) or "?"
    return "/".join([*scopes, name])


def template_message(decl: Cursor, ros2: bool | None) -> str | None:
    """The ROS message a specialisation of class template ``decl`` is on the wire: a
    ``pcl::PointCloud<T>`` (pcl_ros serialises it) is a ``sensor_msgs/PointCloud2``."""
    if decl.spelling != "PointCloud" or _namespaces(decl.semantic_parent) != ["pcl"]:
        return None
    return "sensor_msgs/msg/PointCloud2" if ros2 else "sensor_msgs/PointCloud2"


_POINTER_SUFFIXES = ("SharedPtr", "ConstSharedPtr", "UniquePtr", "Ptr", "ConstPtr")
_ROS1_TYPEDEFS = ("ConstPtr", "Ptr")
_INTERFACE_FOLDERS = ("msg", "srv", "action")
_INTERFACE_PACKAGE = re.compile(r"[a-z][a-z0-9_]*")


def written_type(text: str, ros2: bool | None, used_as_message: bool = False) -> str | None:
    """The ROS interface a C++ type written ``text`` names, when it looks like one:
    ``pkg::msg::Name`` (ROS 2), ``pkg::Name`` with ``pkg`` a message package (a name
    ending in ``_msgs``, ``_srvs`` or ``_interfaces``, or any package when the code uses
    the type as a message: ``waypoint_follower::lane``; ROS 1); None otherwise.
    ``ros2`` None: either form."""
    parts = [p for p in text.replace(" ", "").lstrip(":").split("::") if p]
    while parts and parts[-1] in _POINTER_SUFFIXES:
        parts.pop()
    if any(not p.isidentifier() for p in parts) or len(parts) not in (2, 3):
        return None
    if not _INTERFACE_PACKAGE.fullmatch(parts[0]):
        return None
    if len(parts) == 2 and ros2 is not True:
        # a ROS 1 message header's own typedefs, ``pkg::NameConstPtr`` / ``pkg::NamePtr``
        # (costmap_converter's map_msgs::OccupancyGridUpdateConstPtr, header missing)
        for suffix in _ROS1_TYPEDEFS:
            if parts[1].endswith(suffix) and len(parts[1]) > len(suffix):
                parts[1] = parts[1][: -len(suffix)]
                break
    if len(parts) == 3 and parts[1] in _INTERFACE_FOLDERS and ros2 is not False:
        return "/".join(parts)
    if len(parts) == 2 and ros2 is not True and ((used_as_message and ros2 is False) or (
        parts[0].endswith(("_msgs", "_srvs", "_interfaces"))
    )):
        return "/".join(parts)
    return None


def _synthesised_scopes(cursor: Cursor) -> list[str]:
    """The namespaces and the classes declared permissively (``_synthesised``) that
    enclose a permissive class, outermost first; empty when a real class is among them
    (a member type of a class the parse knows is not named after a message)."""
    scopes: list[str] = []
    while cursor is not None and cursor.kind in _RECORDS:
        if not _synthesised(cursor):
            return []
        scopes.append(cursor.spelling)
        cursor = cursor.semantic_parent
    return [*_namespaces(cursor), *scopes[::-1]]


def _synthesised(decl: Cursor) -> bool:
    for child in decl.get_children():
        if child.kind == CursorKind.CXX_BASE_SPECIFIER and child.type.spelling == "haros_any":
            return True
    return False


_WRITTEN_SCALARS = {
    "bool": "bool", "float": "double", "double": "double",
    "string": "str", "std::string": "str",
}
_WRITTEN_INTEGER = re.compile(
    r"(?:(?:signed|unsigned|short|long|int|char)\s*)+|(?:std::)?u?int(?:8|16|32|64)_t|"
    r"(?:std::)?size_t")


def written_param_type(text: str) -> str | None:
    """The parameter type of a C++ value type as written (``double``, ``std::string``,
    ``std::vector<int64_t>``), for a call the parse could not resolve: its template
    argument has no type to read, and a builtin one no cursor either. None for any
    other spelling."""
    text = " ".join(text.replace("::", " :: ").split()).replace(" :: ", "::").strip()
    text = text.removeprefix("const ").lstrip(":")
    if text.startswith(("std::vector<", "vector<")) and text.endswith(">"):
        if text[text.index("<") + 1:-1].strip() in _BYTES:
            return BYTE_ARRAY
        inner = written_param_type(text[text.index("<") + 1:-1])
        return f"{inner}[]" if inner is not None and not inner.endswith("[]") else None
    if text in _WRITTEN_SCALARS:
        return _WRITTEN_SCALARS[text]
    if text != "char" and _WRITTEN_INTEGER.fullmatch(text):
        return "int"
    return None


def param_type(ctype: Type) -> str | None:
    """The parameter type of a C++ value type, where cheap: double, int, str, bool, an
    array of one (``T[]``), rclcpp's byte array (``std::vector<uint8_t>``), and
    ``dict`` for a ``std::map`` keyed by strings (roscpp's getParam fills one from a
    dictionary only)."""
    ctype = _bare(ctype)
    if ctype.kind in _PARAM_TYPES:
        return _PARAM_TYPES[ctype.kind]
    if ctype.kind in (TypeKind.CONSTANTARRAY, TypeKind.INCOMPLETEARRAY):
        element = ctype.element_type.get_canonical()
        return "str" if element.kind in (TypeKind.CHAR_S, TypeKind.CHAR_U) else None
    if ctype.kind == TypeKind.POINTER:
        pointee = ctype.get_pointee().get_canonical()
        return "str" if pointee.kind in (TypeKind.CHAR_S, TypeKind.CHAR_U) else None
    decl = ctype.get_declaration()
    if decl.spelling == "basic_string":
        return "str"
    if decl.spelling == "vector" and ctype.get_num_template_arguments() > 0:
        element = ctype.get_template_argument_type(0)
        if element.get_canonical().kind == TypeKind.UCHAR:
            return BYTE_ARRAY
        inner = param_type(element) if element.kind != TypeKind.INVALID else None
        return f"{inner}[]" if inner is not None and not inner.endswith("[]") else None
    if decl.spelling == "map" and ctype.get_num_template_arguments() > 1:
        key = ctype.get_template_argument_type(0)
        return "dict" if key.kind != TypeKind.INVALID and param_type(key) == "str" else None
    return None


def _bare(ctype: Type) -> Type:
    ctype = ctype.get_canonical()
    if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        ctype = ctype.get_pointee().get_canonical()
    return ctype


def _record(ctype: Type, depth: int, adapters: Mapping[str, Type]
            ) -> tuple[Cursor, bool] | None:
    """The struct a (reference to / pointer to / shared_ptr of) type names."""
    ctype = ctype.get_canonical()
    while ctype.kind in _REFERENCES:
        ctype = ctype.get_pointee().get_canonical()
    if ctype.kind != TypeKind.RECORD or depth > 4:
        return None
    decl = ctype.get_declaration()
    arguments = ctype.get_num_template_arguments()
    if decl.spelling in _POINTERS and arguments > 0:
        return _record(ctype.get_template_argument_type(0), depth + 1, adapters)
    adapted = ros_type_of_adapter(ctype)
    if adapted is None:
        adapted = adapters.get(ctype.spelling)
    if adapted is not None:
        return _record(adapted, depth + 1, {})
    return decl, arguments > 0


def ros_type_of_adapter(ctype: Type) -> Type | None:
    """The ROS message type of ``rclcpp::TypeAdapter<Custom, Ros>`` (also written
    ``rclcpp::adapt_type<Custom>::as<Ros>``) or of an ``ImplicitTypeAdapter`` of it."""
    ctype = ctype.get_canonical()
    decl = ctype.get_declaration()
    if decl.spelling not in _ADAPTERS or _namespaces(decl.semantic_parent) != ["rclcpp"]:
        return None
    if decl.spelling == "TypeAdapter" and ctype.get_num_template_arguments() >= 2:
        ros = ctype.get_template_argument_type(1)
        return ros if ros.get_canonical().kind != TypeKind.VOID else None
    for child in (decl.get_definition() or decl).get_children():
        if child.kind == CursorKind.CXX_BASE_SPECIFIER:  # ImplicitTypeAdapter<C>
            return ros_type_of_adapter(child.type)
    return None


def adapted_types(specialisation: Cursor) -> tuple[str, Type] | None:
    """(custom type's canonical spelling, ROS message type) for a specialisation of
    ``rclcpp::TypeAdapter<Custom, Ros>`` or ``rclcpp::ImplicitTypeAdapter<Custom>``."""
    ctype = specialisation.type.get_canonical()
    if ctype.get_num_template_arguments() < 1:
        return None
    ros = ros_type_of_adapter(ctype)
    custom = ctype.get_template_argument_type(0).get_canonical()
    return (custom.spelling, ros) if ros is not None else None


def _namespaces(cursor: Cursor | None) -> list[str]:
    scopes: list[str] = []
    while cursor is not None and cursor.kind == CursorKind.NAMESPACE:
        scopes.append(cursor.spelling)
        cursor = cursor.semantic_parent
    return scopes[::-1]


PARAMETER_VALUE = "rclcpp::ParameterValue"
# the parameter types rclcpp's ParameterType constants name (``rclcpp::PARAMETER_DOUBLE``)
PARAMETER_TYPE_NAMES = {
    "PARAMETER_BOOL": "bool", "PARAMETER_INTEGER": "int", "PARAMETER_DOUBLE": "double",
    "PARAMETER_STRING": "str", "PARAMETER_BOOL_ARRAY": "bool[]",
    "PARAMETER_INTEGER_ARRAY": "int[]", "PARAMETER_DOUBLE_ARRAY": "double[]",
    "PARAMETER_STRING_ARRAY": "str[]", "PARAMETER_BYTE_ARRAY": BYTE_ARRAY,
}
_BUILDS = frozenset({CursorKind.CALL_EXPR, CursorKind.CXX_FUNCTIONAL_CAST_EXPR,
                     CursorKind.UNEXPOSED_EXPR, CursorKind.INIT_LIST_EXPR})


def held_value(expr: Cursor, typed: bool = False) -> Cursor:
    """What an ``rclcpp::ParameterValue`` built of one value (``ParameterValue(0.4)``,
    ``ParameterValue{true}``, as nav2's ``declare_parameter_if_not_declared`` is given
    its default) is built of; ``expr`` itself otherwise. ``typed``: the value as its type
    is written, an explicit cast kept (``ParameterValue(static_cast<double>(0))`` holds a
    double: ``stripped_to_cast``)."""
    take = stripped_to_cast if typed else strip
    node, descended = strip(expr), False
    for _ in range(8):
        if node.kind not in _BUILDS or (
            node.type.get_canonical().spelling.removeprefix("const ") != PARAMETER_VALUE
        ):
            return node if descended else expr
        inner = [c for c in node.get_children() if c.kind.is_expression()]
        if len(inner) != 1:
            return expr
        node, descended = take(inner[0]), True
    return expr


def parameter_type_constant(expr: Cursor) -> str | None:
    """The parameter type an ``rclcpp::ParameterType`` constant names
    (``rclcpp::PARAMETER_DOUBLE``: a declaration typed, with no default), else None."""
    node = strip(expr)
    target = node.referenced if node.kind == CursorKind.DECL_REF_EXPR else None
    if target is None or target.kind != CursorKind.ENUM_CONSTANT_DECL:
        return None
    return PARAMETER_TYPE_NAMES.get(target.spelling)
