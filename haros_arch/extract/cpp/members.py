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
write in the file. In the ROS 1 idiom ``if (!nh.getParam("use_mag", use_mag_)) use_mag_
= false;`` (imu_tools) the assignment, the only statement of an ``if`` on the negated
read with no ``else``, runs exactly when the parameter is not there: it is the read's
default (the visitor takes it as one), not another write. The writes are those
``writes.writes_of`` reads. The same reading gives what each member of any type is
assigned in the file's functions
(``assignments``): a node handle member set once outside its class's constructors
(``right_nh_.reset(new ros::NodeHandle(nh, "right"))``). A whole write that a later
statement of the same block replaces, with nothing between them that may read the
member, is never seen (``overwritten``): tuw_multi_robot's fake pose nodelet sets ``nh_
= getPrivateNodeHandle();`` then ``nh_ = getNodeHandle();`` and advertises on the
second (``live_assignments``).
"""

from __future__ import annotations

import bisect
from collections.abc import Callable, Sequence

from clang.cindex import Cursor, CursorKind

from .tested import Key, key
from .values import _plain_value, _walk, key_of, strip
from .writes import parameter_callback, writes_of

_REFS = (CursorKind.MEMBER_REF_EXPR, CursorKind.DECL_REF_EXPR)


def _every(_index: int) -> bool:
    return True


_SCOPES = (CursorKind.TRANSLATION_UNIT, CursorKind.NAMESPACE)


def member_of(expr: Cursor | None) -> Cursor | None:
    """The member variable of a plain type that ``expr`` names, or None; also a global
    variable of a plain type that the unit's own source file declares, the only one in
    which it is declared (VINS-Mono's ar_demo: ``int USE_UNDISTORED_IMG;`` beside
    ``main``): no other file can write it, so its writes are those of the file's
    functions, as a member's are. One a header declares (``extern``) may be written by
    any file that includes it: not one."""
    if expr is None:
        return None
    expr = strip(expr)
    decl = expr.referenced if expr.kind in _REFS else None
    if decl is None or not _plain_value(decl):
        return None
    if decl.kind == CursorKind.FIELD_DECL:
        return decl
    return decl if decl.kind == CursorKind.VAR_DECL and _own_global(decl) else None


def _own_global(decl: Cursor) -> bool:
    """Whether ``decl`` is a variable at namespace scope whose every declaration is in the
    main file of its translation unit."""
    parent = decl.semantic_parent
    if parent is None or parent.kind not in _SCOPES:
        return False
    main = decl.translation_unit.spelling
    canonical = decl.canonical
    seen = [canonical, decl, decl.get_definition()]
    return all(d is None or (d.location.file is not None and d.location.file.name == main)
               for d in seen)


def _negates(node: Cursor, source: dict[str, bytes]) -> bool:
    """Whether the unary operator ``node`` is ``!`` (or ``not``)."""
    start = node.extent.start
    data = source.get(start.file.name) if start.file is not None else None
    if data is None:
        return False
    text = data[start.offset:start.offset + 4].decode("utf-8", "replace")
    return text.startswith("!") or (text.startswith("not") and not text[3:4].isalnum())


def _any_within(offsets: Sequence[int], start: int, end: int) -> bool:
    """Whether one of the sorted ``offsets`` is in ``[start, end]``."""
    index = bisect.bisect_left(offsets, start)
    return index < len(offsets) and offsets[index] <= end


class MemberWrites:
    """The writes of each member variable in one file's functions, and the member each
    call's result is assigned to (``x_ = nh.param<T>(..)``).

    Each function is read when an answer may depend on it, once: for the writes of a
    member, every function whose text names the member; for the member a call's result
    goes to, the functions whose text holds the call (the assignment is around it). A
    function whose text is not all its code (a macro expansion or an ``#include`` in
    it, ``opaque``: (file, offset) of each), or whose text is not at hand, is read for
    every question. The answers are those of reading every function."""

    def __init__(self, functions: list[Cursor], source: dict[str, bytes],
                 opaque: Sequence[tuple[str, int]] = ()) -> None:
        self.source = source
        self.count: dict[tuple[str, int], int] = {}
        # a call -> (the index of the function that assigns it, the member its result
        # is put in): the last function's, as a read of all in order gives
        self._assigned: dict[Key, tuple[int, Cursor]] = {}
        self._functions = functions
        # member -> (value, index of the function) of each write that replaces its value
        self._values: dict[tuple[str, int], list[tuple[Cursor, int]]] = {}
        self._read: set[int] = set()
        # the assignments of ``if (!read) member = value;``, which are no writes of
        # their own but the read's default
        self._skipped: set[Key] = set()
        # the values of whole member writes that a later statement of their block
        # replaces before anything may read them (``_overwritten``)
        self._dead: set[Key] = set()
        self._index = 0  # of the function being read
        self._callback = False  # it is a parameter callback (``writes.parameter_callback``)
        self._spans: list[tuple[str, int, int] | None] = []
        self._texts: list[bytes | None] = []
        inside: dict[str, list[int]] = {}
        for where, offset in opaque:
            inside.setdefault(where, []).append(offset)
        for offsets in inside.values():
            offsets.sort()
        for function in functions:
            start, end = function.extent.start, function.extent.end
            name: str | None = start.file.name if start.file is not None else None
            data = source.get(name) if name is not None and end.file is not None and (
                end.file.name == name) else None
            if name is None or data is None or _any_within(
                inside.get(name, ()), start.offset, end.offset
            ):
                self._spans.append(None)
                self._texts.append(None)
                continue
            self._spans.append((name, start.offset, end.offset))
            self._texts.append(data[start.offset:end.offset])

    def writes(self, member: Cursor) -> int:
        spelling = member.spelling.encode("utf-8")
        self._read_where(lambda index: spelling in self._texts[index])  # type: ignore[operator]
        return self.count.get(key_of(member), 0)

    def naming(self, member: Cursor) -> list[Cursor]:
        """The file's functions whose text names ``member`` (all of those whose text is
        not at hand)."""
        spelling = member.spelling.encode("utf-8")
        return [function for function, text in zip(self._functions, self._texts, strict=True)
                if text is None or spelling in text]

    def assignments(self, member: Cursor) -> list[tuple[Cursor, Cursor]]:
        """(value, function) of each write that replaces ``member``'s value (``=``,
        ``reset(p)``) in the file's functions but its destructors, on any object."""
        spelling = member.spelling.encode("utf-8")
        self._read_where(lambda index: spelling in self._texts[index])  # type: ignore[operator]
        return [(value, self._functions[index])
                for value, index in self._values.get(key_of(member), [])
                if self._functions[index].kind != CursorKind.DESTRUCTOR]

    def live_assignments(self, member: Cursor) -> list[tuple[Cursor, Cursor]]:
        """``assignments`` but those a later statement of their block replaces before
        anything may read the member (``_overwritten``): the values the member may hold
        when read."""
        return [(value, function) for value, function in self.assignments(member)
                if key(value) not in self._dead]

    def assigned(self, call: Cursor) -> Cursor | None:
        """The member ``call``'s result is assigned to, if any."""
        made = key(call)
        if made is None:
            return None
        name, start, end = made

        def holds(index: int) -> bool:
            span = self._spans[index]
            return span is not None and span[0] == name and span[1] <= start <= end <= span[2]

        # a call no function's text holds (in an #include in a body): every function
        self._read_where(holds if any(map(holds, range(len(self._spans)))) else _every)
        found = self._assigned.get(made)
        return found[1] if found is not None else None

    def _read_where(self, wanted: Callable[[int], bool]) -> None:
        for index, function in enumerate(self._functions):
            if index in self._read or (self._texts[index] is not None and not wanted(index)):
                continue
            self._read.add(index)
            self._index = index
            self._callback = parameter_callback(function)
            for node in _walk(function):
                self._visit(node)
        self._callback = False

    def _add(self, member: Cursor | None) -> None:
        if member is not None:
            where = key_of(member)
            self.count[where] = self.count.get(where, 0) + 1

    def _if_not_read(self, node: Cursor) -> None:
        """Note ``if (!call) member = value;`` with ``member`` an argument of ``call``."""
        children = list(node.get_children())
        if len(children) != 2:  # an else, or an init-statement / a declaration
            return
        condition, body = strip(children[0]), children[1]
        if condition.kind != CursorKind.UNARY_OPERATOR or not _negates(condition, self.source):
            return
        operands = list(condition.get_children())
        call = strip(operands[0]) if len(operands) == 1 else None
        if call is None or call.kind != CursorKind.CALL_EXPR:
            return
        if body.kind == CursorKind.COMPOUND_STMT:
            statements = list(body.get_children())
            if len(statements) != 1:
                return
            body = statements[0]
        writes = [w for w in writes_of(body, self.source) if w.whole and w.value is not None]
        member = member_of(writes[0].target) if len(writes) == 1 else None
        done = key(body)
        if member is None or done is None or not any(
                member_of(argument) == member for argument in call.get_arguments()):
            return
        self._skipped.add(done)

    def _text(self, node: Cursor) -> bytes | None:
        where = key(node)
        data = self.source.get(where[0]) if where is not None else None
        return data[where[1]:where[2]] if data is not None and where is not None else None

    def _own_write(self, statement: Cursor
                   ) -> tuple[tuple[str, int], Cursor, bytes] | None:
        """(the member, the value, the member's name) when ``statement`` is itself one
        whole write of a member of ``this`` (``nh_ = getNodeHandle();``, ``this->p_ =
        ..;``, ``p_.reset(..)``), else None."""
        writes = writes_of(strip(statement), self.source)
        if len(writes) != 1 or not writes[0].whole or writes[0].value is None:
            return None
        target = writes[0].target
        field = target.referenced if target.kind == CursorKind.MEMBER_REF_EXPR else None
        if field is None or field.kind != CursorKind.FIELD_DECL:
            return None
        base = [strip(child) for child in target.get_children()]
        if base and (len(base) != 1 or base[0].kind != CursorKind.CXX_THIS_EXPR):
            return None
        return key_of(field), writes[0].value, field.spelling.encode("utf-8")

    def _reads(self, node: Cursor, names: set[bytes]) -> set[bytes] | None:
        """Those of ``names`` (of members of ``this``) that ``node``'s text names; None
        when it may read any member (it names ``this``, calls a method of its own class
        or a call the parse left unresolved) or its text is not at hand."""
        text = self._text(node)
        if text is None or b"this" in text:
            return None
        own = self._functions[self._index].semantic_parent
        for inner in _walk(node):
            if inner.kind != CursorKind.CALL_EXPR:
                continue
            callee = inner.referenced
            if callee is None:
                return None
            parent = callee.semantic_parent
            if callee.kind in (CursorKind.CXX_METHOD, CursorKind.FUNCTION_TEMPLATE) and (
                    not callee.is_static_method()) and own is not None and (
                    parent is not None and key_of(parent) == key_of(own)):
                return None
        return {name for name in names if name in text}

    def _overwritten(self, block: Cursor) -> None:
        """Note the whole member writes of ``block``'s statements that a later one of
        its statements replaces, with no statement between them (nor the later value)
        that may read the member (``_reads``): their values are never seen."""
        pending: dict[tuple[str, int], tuple[Cursor, bytes]] = {}  # member -> its last value
        for statement in block.get_children():
            own = self._own_write(statement)
            names = {name for _, name in pending.values()}
            if own is not None:
                names.add(own[2])
            elif not names:
                continue  # no write pending, none made: nothing its reads could change
            reads = self._reads(own[1] if own is not None else statement, names)
            if reads is None:
                pending.clear()
            else:
                for member in [m for m, (_, name) in pending.items() if name in reads]:
                    del pending[member]
            if own is None:
                continue
            member, value, name = own
            earlier = pending.get(member)
            made = key(earlier[0]) if earlier is not None else None
            if made is not None:
                self._dead.add(made)
            pending[member] = (value, name)

    def _visit(self, node: Cursor) -> None:
        if node.kind == CursorKind.IF_STMT:
            self._if_not_read(node)
        if node.kind == CursorKind.COMPOUND_STMT and not self._callback:
            self._overwritten(node)
        if self._skipped and key(node) in self._skipped:
            return
        for write in writes_of(node, self.source):
            target, value = write.target, write.value
            member = member_of(target)
            if not self._callback:  # (a parameter callback's writes come after start-up)
                self._add(member)
            if not write.whole or value is None:
                continue
            if target.kind == CursorKind.MEMBER_REF_EXPR and target.referenced is not None \
                    and target.referenced.kind == CursorKind.FIELD_DECL and not self._callback:
                self._values.setdefault(key_of(target.referenced), []).append(
                    (value, self._index))
            value = strip(value)
            made = key(value) if value.kind == CursorKind.CALL_EXPR else None
            if member is not None and made is not None:
                last = self._assigned.get(made)
                if last is None or last[0] <= self._index:
                    self._assigned[made] = (self._index, member)
