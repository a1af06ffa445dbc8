"""A name taken from a command-line option that C's getopt / getopt_long parses.

pr2_ethercat's ``main`` reads its options with ``getopt_long(argc, argv, "hi:usx:r:",
long_options, &index)`` in a loop, ``switch (c) { ... case 'r': g_options.rosparam_ =
optarg; break; }``, and its control loop reads the parameter ``g_options.rosparam_``
names. ``option_held(read, decl, source)`` tells, for a variable or member ``decl``, the
option whose argument it holds: the flags (the case's letter when the optstring has it,
``-r``, and each long name of the ``struct option`` table that returns that letter,
``--rosparam``), the program's options as getopt reads them (``PrimitiveCall.name_getopt``:
the optstring, then the table's long names with ``:`` / ``::``, or ``--?`` when the table
is not a constant array read here) and its value when no option sets it (a string
literal written before the loop, None for a null pointer). Only when every write of it
in the unit's own file is that: ``= optarg`` (or a copy of its text,
``std::string(optarg)``, ``strdup(optarg)``) in the case of an option letter of a
``switch`` over what getopt returned, or a constant written before that ``switch`` in
its function; a read before the ``switch`` in that function is not taken. Anything else
(a write elsewhere, a label not known, an optstring not written as a literal) is None:
the name stays unknown.
"""

from __future__ import annotations

import re

from clang.cindex import Cursor, CursorKind, TypeKind

from .expressions import NULL_POINTERS, initializer, strip, written_arguments
from .writes import by_operator, default_constructed, out_argument, writes_of

GETOPT = frozenset({"getopt", "getopt_long", "getopt_long_only"})
_LEAVE = (CursorKind.BREAK_STMT, CursorKind.RETURN_STMT, CursorKind.CONTINUE_STMT,
          CursorKind.GOTO_STMT)
# <getopt.h>'s macros for a long option's ``has_arg``
_HAS_ARG = {"no_argument": 0, "required_argument": 1, "optional_argument": 2}
_DEFAULT = -1  # the label ``default:``
_UNKNOWN = -2  # a label whose value is not read here


def _file(cursor: Cursor) -> str | None:
    where = cursor.location.file
    return where.name if where is not None else None


def _number(expr: Cursor, source: dict[str, bytes] | None = None) -> int | None:
    """An integer or character literal's value, an enumerator's; None otherwise."""
    expr = strip(expr)
    if expr.kind == CursorKind.CHARACTER_LITERAL:
        tokens = [t.spelling for t in expr.get_tokens()]
        text = tokens[0] if tokens else ""
        if len(text) == 3 and text[0] == text[2] == "'" and text[1] != "\\":
            return ord(text[1])
        return None
    if expr.kind == CursorKind.INTEGER_LITERAL:
        tokens = [t.spelling for t in expr.get_tokens()] or _written(
            expr, source or {})
        if len(tokens) == 1 and tokens[0] in _HAS_ARG:
            return _HAS_ARG[tokens[0]]
        try:
            return int(tokens[0].rstrip("uUlL"), 0) if tokens else None
        except ValueError:
            return None
    if expr.kind == CursorKind.DECL_REF_EXPR and expr.referenced is not None and (
            expr.referenced.kind == CursorKind.ENUM_CONSTANT_DECL):
        return int(expr.referenced.enum_value)
    return None


def _written(expr: Cursor, source: dict[str, bytes]) -> list[str]:
    """The word written where a macro's expansion is (``required_argument``), which has
    no tokens of its own."""
    where = expr.location
    text = source.get(where.file.name) if where.file is not None else None
    match = re.match(rb"[A-Za-z_][A-Za-z_0-9]*", text[where.offset:where.offset + 64]) if (
        text is not None) else None
    return [match.group(0).decode("ascii")] if match else []


def _null(expr: Cursor) -> bool:
    expr = strip(expr)
    return expr.kind in NULL_POINTERS or _number(expr) == 0


def _text(expr: Cursor) -> str | None:
    from .values import literal  # (values imports this module)

    expr = strip(expr)
    inner = _copied(expr)  # (``std::string topic = "chatter"``: built from the text)
    if inner is not None:
        expr = strip(inner)
    return literal(expr.spelling) if expr.kind == CursorKind.STRING_LITERAL else None


# the C library's functions that return a copy of the text they are given
_COPIES = frozenset({"strdup"})


def _copied(expr: Cursor) -> Cursor | None:
    """What ``expr`` holds a copy of, the same text: the one argument of a
    ``std::string`` built from it (``std::string(optarg)``, ``std::string{optarg}``) or
    of the C library's ``strdup(optarg)``; None for any other expression."""
    if expr.kind != CursorKind.CALL_EXPR or expr.referenced is None:
        return None
    args = written_arguments(expr)
    if len(args) != 1:
        return None
    target = expr.referenced
    if target.kind == CursorKind.CONSTRUCTOR:
        owner = target.semantic_parent
        named = owner.spelling.split("<")[0] if owner is not None else ""
        space = owner.semantic_parent if owner is not None else None
        return args[0] if named == "basic_string" and space is not None and (
            space.spelling == "std") else None
    if target.spelling in _COPIES and _file(target) != expr.translation_unit.spelling:
        return args[0]
    return None


def _is_optarg(expr: Cursor | None) -> bool:
    """``optarg``, the library's variable (declared in a header, not the unit's file),
    or a copy of its text (``_copied``)."""
    if expr is None:
        return False
    expr = strip(expr)
    inner = _copied(expr)
    if inner is not None:
        expr = strip(inner)
    decl = expr.referenced if expr.kind == CursorKind.DECL_REF_EXPR else None
    return decl is not None and decl.kind == CursorKind.VAR_DECL and (
        decl.spelling == "optarg") and _file(decl) != decl.translation_unit.spelling


def _getopt_call(expr: Cursor | None) -> Cursor | None:
    if expr is None:
        return None
    expr = strip(expr)
    target = expr.referenced if expr.kind == CursorKind.CALL_EXPR else None
    if target is None or expr.spelling not in GETOPT or (
            _file(target) == expr.translation_unit.spelling):
        return None
    return expr


def _walk(cursor: Cursor):  # type: ignore[no-untyped-def]
    stack = [cursor]
    while stack:
        node = stack.pop()
        yield node
        stack.extend(node.get_children())


def _cases(switch: Cursor, source: dict[str, bytes]) -> list[tuple[int, int, frozenset[int]]]:
    """(start, end, labels) of each statement of a ``switch``'s body with the labels
    that reach it (falling through from the case before, until a ``break``)."""
    children = list(switch.get_children())
    body = children[-1] if children else None
    if body is None or body.kind != CursorKind.COMPOUND_STMT:
        return []
    found: list[tuple[int, int, frozenset[int]]] = []
    active: set[int] = set()
    for statement in body.get_children():
        inner = statement
        while inner.kind in (CursorKind.CASE_STMT, CursorKind.DEFAULT_STMT):
            parts = list(inner.get_children())
            if inner.kind == CursorKind.DEFAULT_STMT:
                active.add(_DEFAULT)
            else:
                value = _number(parts[0], source) if parts else None
                active.add(_UNKNOWN if value is None else value)
            if not parts:
                break
            inner = parts[-1]
        found.append((statement.extent.start.offset, statement.extent.end.offset,
                      frozenset(active)))
        if inner.kind in _LEAVE:
            active = set()
    return found


def _table(argument: Cursor, source: dict[str, bytes]) -> list[tuple[str, int, int | None]] | None:
    """(name, has_arg, value returned or None when it sets a flag) of each entry of a
    ``struct option`` constant array; None when it is not one read here."""
    held = strip(argument)
    decl = held.referenced if held.kind == CursorKind.DECL_REF_EXPR else None
    if decl is None or decl.kind != CursorKind.VAR_DECL or (
            decl.type.get_canonical().kind != TypeKind.CONSTANTARRAY):
        return None
    items = initializer(decl)
    if items is None or items.kind != CursorKind.INIT_LIST_EXPR:
        return None
    entries: list[tuple[str, int, int | None]] = []
    for item in items.get_children():
        fields = [c for c in item.get_children() if c.kind.is_expression()]
        if item.kind != CursorKind.INIT_LIST_EXPR or len(fields) != 4:
            return None
        name, has_arg = _text(fields[0]), _number(fields[1], source)
        if name is None:
            if _null(fields[0]):
                break  # the table's end, {0, 0, 0, 0}
            return None
        value = _number(fields[3], source) if _null(fields[2]) else None
        if has_arg not in (0, 1, 2) or (_null(fields[2]) and value is None):
            return None
        entries.append((name, has_arg, value))
    return entries


class _Parse:
    """One ``switch`` over what a getopt call returned: its cases and the options."""

    def __init__(self, switch: Cursor, call: Cursor, source: dict[str, bytes]) -> None:
        self.switch = switch
        self.cases = _cases(switch, source)
        args = written_arguments(call)
        self.optstring = _text(args[2]) if len(args) >= 3 else None
        self.table: list[tuple[str, int, int | None]] | None = []
        if call.spelling != "getopt":
            self.table = _table(args[3], source) if len(args) >= 4 else None

    def spec(self) -> str:
        if self.table is None:
            return f"{self.optstring} --?"
        longs = [name + ":" * has_arg for name, has_arg, _ in self.table]
        return " ".join([self.optstring or "", *longs])

    def labels(self, offset: int) -> frozenset[int] | None:
        for start, end, labels in self.cases:
            if start <= offset <= end:
                return labels
        return None

    def flags(self, labels: frozenset[int]) -> list[str] | None:
        letters = (self.optstring or "").lstrip("+-:")
        out: list[str] = []
        for label in sorted(labels):
            if label < 0:
                return None
            if 0 < label < 128 and chr(label) != ":" and chr(label) in letters:
                out.append("-" + chr(label))
            for name, has_arg, value in self.table or ():
                if value == label and has_arg:
                    out.append("--" + name)
        return out


def _switches(function: Cursor, source: dict[str, bytes]) -> list[_Parse]:
    """The ``switch`` statements of ``function`` over a getopt call's result: the call
    itself, or a local every write of which in the function is that one call."""
    found: list[_Parse] = []
    writes: dict[tuple[str | None, int], list[Cursor | None]] = {}
    nodes = list(_walk(function))
    for node in nodes:
        for write in writes_of(node, source):
            variable = write.variable
            if variable is not None:
                writes.setdefault(key(variable), []).append(write.value if write.whole else None)
    for node in nodes:
        if node.kind != CursorKind.SWITCH_STMT:
            continue
        tested = next(iter(node.get_children()), None)
        if tested is None or not tested.kind.is_expression():
            continue
        call = _getopt_call(tested)
        if call is None:
            held = strip(tested)
            variable = held.referenced if held.kind == CursorKind.DECL_REF_EXPR else None
            values = writes.get(key(variable), []) if variable is not None else []
            calls = [_getopt_call(v) for v in values]
            if not calls or any(c is None for c in calls) or len(
                    {key(c) for c in calls if c is not None}) != 1:
                continue
            call = calls[0]
        assert call is not None
        parse = _Parse(node, call, source)
        if parse.optstring is not None:
            found.append(parse)
    return found


def option_held(read: Cursor, decl: Cursor, source: dict[str, bytes]
                ) -> tuple[str, str, str | None, bool] | None:
    """(flags, getopt's options, value when no option sets it, whether that is a null
    pointer written) of the option whose argument the variable or member ``decl`` that
    ``read`` names holds; None when it is not one (the module's rules)."""
    if decl.kind not in (CursorKind.FIELD_DECL, CursorKind.VAR_DECL):
        return None
    unit = decl.translation_unit
    main = unit.spelling
    text = source.get(main)
    if text is None or b"optarg" not in text or _file(decl) != main:
        return None
    spelling = decl.spelling.encode()
    functions = [c for top in unit.cursor.get_children() if _file(top) == main
                 for c in _walk(top) if c.is_definition() and c.kind in (
                     CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD,
                     CursorKind.CONSTRUCTOR, CursorKind.DESTRUCTOR,
                     CursorKind.FUNCTION_TEMPLATE)]
    options: list[tuple[Cursor, _Parse, frozenset[int]]] = []
    constants: list[tuple[Cursor, int, str | None]] = []
    for function in functions:
        extent = function.extent
        if spelling not in text[extent.start.offset:extent.end.offset]:
            continue
        parses: list[_Parse] | None = None
        for node in _walk(function):
            for write in writes_of(node, source):
                if write.variable is None or write.variable != decl:
                    continue
                if not write.whole and not (by_operator(write) or out_argument(write)):
                    continue  # (what a call takes by value or const reference)
                if not write.whole or write.value is None:
                    return None
                if parses is None:
                    parses = _switches(function, source)
                offset = write.at.extent.start.offset
                if _is_optarg(write.value):
                    inside = [(p, p.labels(offset)) for p in parses]
                    chosen = [(p, labels) for p, labels in inside if labels]
                    if len(chosen) != 1:
                        return None
                    options.append((function, chosen[0][0], chosen[0][1]))
                    continue
                value = _text(write.value)
                if value is None and not _null(write.value):
                    return None
                constants.append((function, offset, value))
    if not options or len({key(p.switch) for _, p, _ in options}) != 1:
        return None
    function, parse, _ = options[0]
    start = parse.switch.extent.start.offset
    flags: list[str] = []
    for _, _, labels in options:
        found = parse.flags(labels)
        if found is None:
            return None
        flags.extend(f for f in found if f not in flags)
    if not flags:
        return None
    default: str | None = None
    null = False
    last = -1
    for where, offset, value in constants:
        if where != function or offset >= start:
            return None  # a write elsewhere, or after the options are read
        if offset > last:
            last, default, null = offset, value, value is None
    if _inside(read, function) and read.extent.start.offset < start:
        return None  # read before the options are
    if decl.kind == CursorKind.VAR_DECL and last < 0:
        made = initializer(decl)
        if made is not None and not default_constructed(made):  # (``std::string s;``)
            default = _text(made)
            if default is None and not _null(made):
                return None
            null = default is None
    return " ".join(flags), parse.spec(), default, null


def key(cursor: Cursor) -> tuple[str | None, int]:
    return _file(cursor), cursor.extent.start.offset


def _inside(read: Cursor, function: Cursor) -> bool:
    start, end = function.extent.start, function.extent.end
    return _file(read) == _file(function) and (
        start.offset <= read.extent.start.offset <= end.offset)
