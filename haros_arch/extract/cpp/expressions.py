"""The shape of C++ expressions as libclang gives them: what an expression is once the
wrappers around it (implicit conversions, casts, parentheses) are taken off, what a
declaration initialises its variable with, which arguments a call writes."""

from __future__ import annotations

from clang.cindex import Cursor, CursorKind, TypeKind, conf

from .cursors import Node

# expression kinds that only wrap their operand (implicit conversions, casts, parens, ...)
WRAPPERS = frozenset({
    CursorKind.UNEXPOSED_EXPR, CursorKind.PAREN_EXPR, CursorKind.CXX_FUNCTIONAL_CAST_EXPR,
    CursorKind.CSTYLE_CAST_EXPR, CursorKind.CXX_STATIC_CAST_EXPR,
    CursorKind.CXX_CONST_CAST_EXPR,
})
_REFS = frozenset({CursorKind.TYPE_REF, CursorKind.NAMESPACE_REF, CursorKind.TEMPLATE_REF})
# the null pointer literals: ``nullptr``, and ``NULL`` as GNU's headers define it
NULL_POINTERS = (CursorKind.CXX_NULL_PTR_LITERAL_EXPR, CursorKind.GNU_NULL_EXPR)
# the declarations a qualified name is made of
_SCOPES = frozenset({
    CursorKind.NAMESPACE, CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL,
    CursorKind.CLASS_TEMPLATE, CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION,
})


def qualified_name(cursor: Cursor | None) -> str:
    """``ros::NodeHandle`` for the NodeHandle class declaration, and so on (a unit's
    node keeps its own: the analyses ask of the same classes and their parents)."""
    if isinstance(cursor, Node):
        kept: str | None = cursor.__dict__.get("_qualified")
        if kept is None:
            kept = cursor.__dict__["_qualified"] = _qualified(cursor)
        return kept
    return _qualified(cursor)


def _qualified(cursor: Cursor | None) -> str:
    parts: list[str] = []
    while cursor is not None and cursor.kind in _SCOPES:
        if cursor.spelling:
            parts.append(cursor.spelling)
        cursor = cursor.semantic_parent
    return "::".join(reversed(parts))


def constructed_name(expr: Cursor, class_name: str) -> Cursor | None:
    """The first argument of ``expr`` when it builds an object of ``class_name``
    (``rclcpp::Parameter(name, value)``: the parameter's name); else None."""
    values = constructed_arguments(expr, class_name)
    return values[0] if values else None


def constructed_arguments(expr: Cursor, class_name: str) -> list[Cursor] | None:
    """The arguments written to ``expr`` when it builds an object of ``class_name``,
    also where the construction depends on a template parameter and clang leaves it
    unresolved (a wrapper's ``rclcpp::Parameter(param_name, param_value)`` of ``const
    T&``: a call with no declaration, its children the class's references and then the
    arguments); None when it builds none."""
    inner = strip(expr)
    if inner.kind != CursorKind.CALL_EXPR:
        return None
    target = inner.referenced
    if target is not None:
        if target.kind != CursorKind.CONSTRUCTOR or (
            qualified_name(target.semantic_parent) != class_name
        ):
            return None
        return written_arguments(inner)
    children = list(inner.get_children())
    named = [c for c in children if c.kind == CursorKind.TYPE_REF]
    if not named or qualified_name(named[-1].referenced) != class_name:
        return None
    return [c for c in children if c.kind not in _REFS]


def is_default_argument(cursor: Cursor) -> bool:
    """True for an argument the call did not write (a default argument)."""
    return cursor.extent.start.file is None


def written_arguments(call: Cursor) -> list[Cursor]:
    return [arg for arg in call.get_arguments() if not is_default_argument(arg)]


def operand(cursor: Cursor) -> Cursor | None:
    """The expression a wrapper wraps, or None (also for an operator call the parse
    left unresolved, ``unresolved_operator``: its last child is its right operand, not
    its value)."""
    inner = [c for c in cursor.get_children() if c.kind not in _REFS]
    if len(inner) == 3 and unresolved_operator(cursor) is not None:
        return None
    return inner[-1] if inner else None


def unresolved_operator(cursor: Cursor) -> tuple[str, Cursor, Cursor] | None:
    """``a + b`` in a template where an operand's type depends on a template parameter
    and the operator is an overload set looked up at instantiation (depthai's
    ``Detection<T>``: ``"~/" + getName() + "/detections"``, ``getName()`` of a base):
    a call with no declaration whose children are the left operand, a reference to the
    overloaded ``operator+``, the right operand. The operator's symbol and the two
    operands, else None."""
    if cursor.kind != CursorKind.CALL_EXPR or cursor.referenced is not None:
        return None
    children = list(cursor.get_children())
    if len(children) != 3 or children[1].kind != CursorKind.DECL_REF_EXPR:
        return None
    refs = list(children[1].get_children())
    if len(refs) != 1 or refs[0].kind != CursorKind.OVERLOADED_DECL_REF or not (
            refs[0].spelling.startswith("operator")):
        return None
    return refs[0].spelling[len("operator"):], children[0], children[2]


def first_operand(cursor: Cursor) -> Cursor | None:
    """The first expression among ``cursor``'s children, without the wrappers around it
    (a call's callee, the object of a member access); None when it has none."""
    found = next((c for c in cursor.get_children() if c.kind.is_expression()), None)
    return strip(found) if found is not None else None


def strip(cursor: Cursor) -> Cursor:
    """``cursor`` without the wrappers around it."""
    while cursor.kind in WRAPPERS:
        inner = operand(cursor)
        if inner is None:
            break
        cursor = inner
    return cursor


# explicit casts, and the builtin types a cast to which makes a value of that type (not
# the character types: a ``static_cast<uint8_t>(3)`` is read by the value under it)
_CASTS = frozenset({CursorKind.CSTYLE_CAST_EXPR, CursorKind.CXX_STATIC_CAST_EXPR,
                    CursorKind.CXX_FUNCTIONAL_CAST_EXPR})
_SCALARS = frozenset({
    TypeKind.BOOL, TypeKind.SHORT, TypeKind.USHORT, TypeKind.INT, TypeKind.UINT,
    TypeKind.LONG, TypeKind.ULONG, TypeKind.LONGLONG, TypeKind.ULONGLONG, TypeKind.FLOAT,
    TypeKind.DOUBLE,
})


def stripped_to_cast(cursor: Cursor) -> Cursor:
    """``cursor`` without the wrappers around it, stopping at an explicit cast to a
    builtin scalar type: the expression whose type is the value's as written
    (``static_cast<double>(0)`` is a double, not the int literal under it; implicit
    conversions, parentheses and casts to classes are taken off as ``strip`` does)."""
    while cursor.kind in WRAPPERS:
        if cursor.kind in _CASTS and cursor.type.get_canonical().kind in _SCALARS:
            return cursor
        inner = operand(cursor)
        if inner is None:
            break
        cursor = inner
    return cursor


def initializer(decl: Cursor) -> Cursor | None:
    """The expression a variable declaration initialises it with, if any."""
    exprs = [c for c in decl.get_children() if c.kind.is_expression()]
    return exprs[-1] if exprs else None


def binary_operator(cursor: Cursor, children: list[Cursor]) -> str | None:
    """The operator token of a binary operator the parse kept as one (not a call of
    ``operator+``): the first token after its left operand."""
    end = children[0].extent.end.offset
    return next((t.spelling for t in cursor.get_tokens() if t.extent.start.offset >= end),
                None)


def construction_lost(variable: Cursor) -> bool:
    """Whether ``variable`` is declared without an initialiser and clang marked it
    invalid: the parse kept no construction of it (a variable of a class abstract to
    the parse, whose overriders' types are in error)."""
    return variable.kind == CursorKind.VAR_DECL and bool(
        conf.lib.clang_isInvalidDeclaration(variable)) and not any(
        c.kind.is_expression() for c in variable.get_children())


def lost_class(variable: Cursor) -> Cursor | None:
    """The class (its definition) of a variable whose construction the parse lost
    (``construction_lost``), which C++ default-constructs all the same; None for any
    other variable, or one not of a class."""
    if not construction_lost(variable):
        return None
    ctype = variable.type.get_canonical()
    if ctype.kind != TypeKind.RECORD:
        return None
    decl = ctype.get_declaration()
    return decl.get_definition() or decl


def ros_init(main: Cursor) -> Cursor | None:
    """The call ``ros::init(argc, argv, ...)`` of ``main``'s own two parameters written
    as a statement of its body (roscpp's, which takes the ``:=`` words off ``argc`` and
    ``argv``): the statements of the body before it run before it, those after it after
    it. None when there is no such statement."""
    params = [c for c in main.get_children() if c.kind == CursorKind.PARM_DECL]
    body = next((c for c in main.get_children() if c.kind == CursorKind.COMPOUND_STMT), None)
    for statement in body.get_children() if body is not None and len(params) >= 2 else ():
        call = strip(statement)
        target = call.referenced if call.kind == CursorKind.CALL_EXPR else None
        parent = target.semantic_parent if target is not None else None
        if target is None or target.spelling != "init" or parent is None or (
                parent.kind != CursorKind.NAMESPACE or parent.spelling != "ros"):
            continue
        args = [strip(a).referenced for a in call.get_arguments()]
        if len(args) >= 2 and all(a is not None and a == p for a, p in zip(
                args[:2], params[:2], strict=True)):
            return call
    return None
