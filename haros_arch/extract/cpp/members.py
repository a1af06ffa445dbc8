"""Member variables that hold a parameter's value, for deciding conditions over them.

``nh.param("publish_acceleration", publish_acceleration_, false)`` in one method and
``if (publish_acceleration_) pub_ = nh.advertise(..)`` in another: the publisher exists
exactly when the parameter is true, as long as nothing else writes the member. This
module counts, over the functions of one file, the writes of each member variable of a
plain type (an assignment, a compound assignment, ``++`` / ``--``, its address taken,
passing it by non-const reference, a non-const method called on it); a constructor's
member initialiser is its first value, not a write. A parameter read that stores into
a member (its out argument, or ``member_ = nh.param<T>(..)`` / ``declare_parameter``)
names the member in ``PrimitiveCall.variable`` only when that read is the member's one
write in the file.
"""

from __future__ import annotations

from clang.cindex import Cursor, CursorKind

from .tested import Key, key
from .values import _may_write, _plain_value, _walk, key_of, strip

_REFS = (CursorKind.MEMBER_REF_EXPR, CursorKind.DECL_REF_EXPR)
_ASSIGNING = ("++", "--", "&")
_READING = ("&&", "||", "==", "!=", "<", ">", "<=", ">=", "+", "-", "*", "/", "%")


def member_of(expr: Cursor | None) -> Cursor | None:
    """The member variable of a plain type that ``expr`` names, or None."""
    if expr is None:
        return None
    expr = strip(expr)
    decl = expr.referenced if expr.kind in _REFS else None
    if decl is None or decl.kind != CursorKind.FIELD_DECL or not _plain_value(decl):
        return None
    return decl


class MemberWrites:
    """The writes of each member variable in one file's functions, and the member each
    call's result is assigned to (``x_ = nh.param<T>(..)``)."""

    def __init__(self, functions: list[Cursor], source: dict[str, bytes]) -> None:
        self.source = source
        self.count: dict[tuple[str, int], int] = {}
        self.assigned: dict[Key, Cursor] = {}  # a call -> the member its result is put in
        for function in functions:
            for node in _walk(function):
                self._visit(node)

    def writes(self, member: Cursor) -> int:
        return self.count.get(key_of(member), 0)

    def _add(self, member: Cursor | None) -> None:
        if member is not None:
            where = key_of(member)
            self.count[where] = self.count.get(where, 0) + 1

    def _assign(self, target: Cursor, source: Cursor) -> None:
        """``target = source``: a write of the member, and the call whose value it keeps."""
        member = member_of(target)
        self._add(member)
        value = strip(source)
        made = key(value) if value.kind == CursorKind.CALL_EXPR else None
        if member is not None and made is not None:
            self.assigned[made] = member

    def _visit(self, node: Cursor) -> None:
        kind = node.kind
        if kind == CursorKind.BINARY_OPERATOR:
            children = list(node.get_children())
            if len(children) == 2 and self._between(children[0], children[1]) == "=":
                self._assign(children[0], children[1])
        elif kind == CursorKind.COMPOUND_ASSIGNMENT_OPERATOR:
            children = list(node.get_children())
            if children:
                self._add(member_of(children[0]))
        elif kind == CursorKind.UNARY_OPERATOR:
            tokens = [t.spelling for t in node.get_tokens()]
            if tokens and (tokens[0] in _ASSIGNING or tokens[-1] in ("++", "--")):
                for child in node.get_children():
                    self._add(member_of(child))
        elif kind == CursorKind.CALL_EXPR:
            self._call(node)

    def _call(self, call: Cursor) -> None:
        args = list(call.get_arguments())
        if call.spelling == "operator=" and len(args) == 2:  # a std::string member
            self._assign(args[0], args[1])
            return
        if call.referenced is None and len(args) == 2 and (
            self._between(args[0], args[1]) in _READING
        ):
            return  # ``a_ && f(x)`` in a template: an operator clang leaves unresolved
        for index, arg in enumerate(args):
            if arg.kind in _REFS and _may_write(call, index):
                self._add(member_of(arg))
        children = list(call.get_children())
        method = call.referenced
        if children and children[0].kind == CursorKind.MEMBER_REF_EXPR and (
            method is not None and method.kind == CursorKind.CXX_METHOD
            and not method.is_const_method()
        ):
            for obj in children[0].get_children():
                self._add(member_of(obj))

    def _between(self, first: Cursor, second: Cursor) -> str:
        end, start = first.extent.end, second.extent.start
        if end.file is None or start.file is None or end.file.name != start.file.name:
            return ""
        text = self.source.get(end.file.name)
        if text is None:
            return ""
        return text[end.offset:start.offset].decode("utf-8", "replace").strip()
