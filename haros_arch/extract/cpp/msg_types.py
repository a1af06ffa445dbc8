"""ROS type names from C++ types: ``std_msgs::String::ConstPtr`` -> ``std_msgs/String``.

Works on the canonical type so typedefs (``ConstPtr``, ``StringConstPtr``, ``Request``) and
the real headers' templates (``std_msgs::String_<std::allocator<void>>``) all lead to the
same struct: its namespaces and name give the ROS 1 name.
"""

from __future__ import annotations

from clang.cindex import Cursor, CursorKind, Type, TypeKind

_RECORDS = (CursorKind.STRUCT_DECL, CursorKind.CLASS_DECL, CursorKind.CLASS_TEMPLATE,
            CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION)
_POINTERS = ("shared_ptr", "MessageEvent")
_REFERENCES = (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE, TypeKind.POINTER)

_PARAM_TYPES = {
    TypeKind.BOOL: "bool", TypeKind.INT: "int", TypeKind.UINT: "int", TypeKind.LONG: "int",
    TypeKind.ULONG: "int", TypeKind.LONGLONG: "int", TypeKind.ULONGLONG: "int",
    TypeKind.SHORT: "int", TypeKind.USHORT: "int", TypeKind.FLOAT: "double",
    TypeKind.DOUBLE: "double",
}


def message_type(ctype: Type, service: bool = False) -> str | None:
    """The ROS name of the message (or, with ``service``, service) type ``ctype`` holds."""
    record = _record(ctype)
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
    if not scopes or not name:
        return None
    return "/".join([*scopes, name])


def param_type(ctype: Type) -> str | None:
    """The parameter type of a C++ value type, where cheap: double, int, str, bool."""
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
    return None


def _bare(ctype: Type) -> Type:
    ctype = ctype.get_canonical()
    if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        ctype = ctype.get_pointee().get_canonical()
    return ctype


def _record(ctype: Type, depth: int = 0) -> tuple[Cursor, bool] | None:
    """The struct a (reference to / pointer to / shared_ptr of) type names."""
    ctype = ctype.get_canonical()
    while ctype.kind in _REFERENCES:
        ctype = ctype.get_pointee().get_canonical()
    if ctype.kind != TypeKind.RECORD or depth > 4:
        return None
    decl = ctype.get_declaration()
    arguments = ctype.get_num_template_arguments()
    if decl.spelling in _POINTERS and arguments > 0:
        return _record(ctype.get_template_argument_type(0), depth + 1)
    return decl, arguments > 0


def _namespaces(cursor: Cursor | None) -> list[str]:
    scopes: list[str] = []
    while cursor is not None and cursor.kind == CursorKind.NAMESPACE:
        scopes.append(cursor.spelling)
        cursor = cursor.semantic_parent
    return scopes[::-1]
