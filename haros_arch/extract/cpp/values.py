"""Walking C++ values backwards: what string, integer or boolean an argument holds.

A string value is a tuple of parts, each a known ``str`` or ``None`` for a part that is
only known at run time; ``render`` writes the unknown parts as ``?``. Resolved:
literals (also through ``#define``), ``const`` / ``constexpr`` variables, local variables
written exactly once (at their declaration or by one assignment), ``std::string``
construction, ``+`` concatenation and ``.c_str()``, and a function's parameter when every
call of the function in the same file passes the same value (``CallSites``). Anything
else is unknown.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator
from typing import TypeVar

from clang.cindex import Cursor, CursorKind, TypeKind

Parts = tuple[str | None, ...]
# A part standing for "the argument the callers in other files pass": PLACEHOLDER, the
# function's USR, SEPARATOR, the parameter's index, PLACEHOLDER. A ROS 1 node's
# translation units are joined by ``links.resolve`` once all of them are read.
PLACEHOLDER = "\x00"
SEPARATOR = "\x01"
Value = TypeVar("Value")
UNKNOWN: Parts = (None,)
MAX_DEPTH = 24

# expression kinds that only wrap their operand (implicit conversions, casts, parens, ...)
WRAPPERS = frozenset({
    CursorKind.UNEXPOSED_EXPR, CursorKind.PAREN_EXPR, CursorKind.CXX_FUNCTIONAL_CAST_EXPR,
    CursorKind.CSTYLE_CAST_EXPR, CursorKind.CXX_STATIC_CAST_EXPR,
    CursorKind.CXX_CONST_CAST_EXPR,
})
_REFS = frozenset({CursorKind.TYPE_REF, CursorKind.NAMESPACE_REF, CursorKind.TEMPLATE_REF})
_ESCAPES = {"n": "\n", "t": "\t", "\\": "\\", '"': '"', "'": "'", "0": "\0"}
_TOKEN = re.compile(rb"[A-Za-z_]\w*|[-+]?(?:0[xX][0-9a-fA-F]+|\d+)[uUlL]*")
_INT = re.compile(r"([-+]?(?:0[xX][0-9a-fA-F]+|\d+))[uUlL]*")


def render(parts: Parts) -> str:
    """The name with ``?`` for each unknown run of parts."""
    text: list[str] = []
    for part in parts:
        if part is None:
            if not text or text[-1] != "?":
                text.append("?")
        else:
            text.append(part)
    return "".join(text)


def is_default_argument(cursor: Cursor) -> bool:
    """True for an argument the call did not write (a default argument)."""
    return cursor.extent.start.file is None


def written_arguments(call: Cursor) -> list[Cursor]:
    return [arg for arg in call.get_arguments() if not is_default_argument(arg)]


def operand(cursor: Cursor) -> Cursor | None:
    """The expression a wrapper wraps, or None."""
    inner = [c for c in cursor.get_children() if c.kind not in _REFS]
    return inner[-1] if inner else None


def strip(cursor: Cursor) -> Cursor:
    """``cursor`` without the wrappers around it."""
    while cursor.kind in WRAPPERS:
        inner = operand(cursor)
        if inner is None:
            break
        cursor = inner
    return cursor


class Scope:
    """What the values of one function body depend on: its variables' writes, macros."""

    def __init__(self, body: Cursor | None, macros: dict[str, str],
                 source: dict[str, bytes], sites: CallSites | None = None) -> None:
        self.body = body
        self.sites = sites
        self.macros = macros
        self.source = source
        # variable key -> the expressions written to it; None for an unknown write
        self.writes: dict[tuple[str, int], list[Cursor | None]] = {}
        # variable key -> (call, argument index) of the last call it was passed to by
        # reference: a parameter read writes its value this way
        self.passed: dict[tuple[str, int], tuple[Cursor, int]] = {}
        if body is not None:
            self._collect(body)

    # -- writes -----------------------------------------------------------------------

    def _collect(self, body: Cursor) -> None:
        for node in _walk(body):
            kind = node.kind
            if kind == CursorKind.VAR_DECL:
                init = initializer(node)
                if init is not None and not _default_constructed(init):
                    self._write(node, init)
            elif kind == CursorKind.CALL_EXPR:
                self._call_writes(node)
            elif kind == CursorKind.BINARY_OPERATOR:
                children = list(node.get_children())
                if len(children) == 2 and self.operator(node, children) == "=":
                    self._write_ref(children[0], children[1])
            elif kind in (CursorKind.COMPOUND_ASSIGNMENT_OPERATOR, CursorKind.UNARY_OPERATOR):
                for child in node.get_children():
                    self._write_ref(child, None)

    def _call_writes(self, call: Cursor) -> None:
        args = list(call.get_arguments())
        if call.spelling == "operator=" and len(args) == 2:
            self._write_ref(args[0], args[1])
            return
        for index, arg in enumerate(args):  # an lvalue passed as it is: a reference
            if arg.kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) and (
                arg.referenced is not None
            ):
                self.passed[_key(arg.referenced)] = (call, index)
                self._write_ref(arg, None)
        children = list(call.get_children())
        if children and children[0].kind == CursorKind.MEMBER_REF_EXPR:
            method = call.referenced
            if method is not None and not method.is_const_method():
                for obj in children[0].get_children():
                    self._write_ref(strip(obj), None)

    def _write_ref(self, target: Cursor, value: Cursor | None) -> None:
        decl = target.referenced if target.kind == CursorKind.DECL_REF_EXPR else None
        if decl is None:
            return
        if value is None and (decl.type.is_const_qualified() or not _plain_value(decl)):
            return  # calls on objects (a NodeHandle's advertise) do not change what we track
        self._write(decl, value)

    def _write(self, decl: Cursor, value: Cursor | None) -> None:
        self.writes.setdefault(_key(decl), []).append(value)

    def operator(self, node: Cursor, children: list[Cursor]) -> str:
        """The operator token between the two operands of a binary operator."""
        start, end = children[0].extent.end, children[1].extent.start
        if start.file is None or start.file.name != (end.file.name if end.file else None):
            return ""
        text = self.source.get(start.file.name)
        if text is None:
            return ""
        return text[start.offset:end.offset].decode("utf-8", "replace").strip()

    # -- values -----------------------------------------------------------------------

    def passed_to(self, decl: Cursor) -> tuple[Cursor, int] | None:
        """The last call ``decl`` was passed to by reference, and at which index."""
        return self.passed.get(_key(decl))

    def variable(self, decl: Cursor) -> Cursor | None:
        """The one expression variable ``decl`` holds, when there is exactly one."""
        if decl.kind not in (CursorKind.VAR_DECL, CursorKind.FIELD_DECL):
            return None
        writes = self.writes.get(_key(decl))
        if writes is not None:
            return writes[0] if len(writes) == 1 else None
        if decl.type.is_const_qualified() or _string_constant(decl):
            definition = decl.get_definition() or decl
            return initializer(definition)
        return None

    def string(self, cursor: Cursor, depth: int = 0) -> Parts:
        if depth > MAX_DEPTH:
            return UNKNOWN
        cursor = strip(cursor)
        kind = cursor.kind
        if kind == CursorKind.STRING_LITERAL:
            text = _literal(cursor.spelling)
            return UNKNOWN if text is None else (text,)
        if kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
            decl = cursor.referenced
            if decl is not None and self.is_parameter(decl):
                return self.sites.agreed(  # type: ignore[union-attr]
                    decl, lambda arg, scope: scope.string(arg, depth + 1), UNKNOWN)
            value = self.variable(decl) if decl is not None else None
            return UNKNOWN if value is None else self.string(value, depth + 1)
        if kind == CursorKind.CALL_EXPR:
            return self._string_call(cursor, depth)
        return UNKNOWN

    def is_parameter(self, decl: Cursor) -> bool:
        """A parameter this function never assigns, whose callers may tell its value."""
        return self.sites is not None and decl.kind == CursorKind.PARM_DECL and all(
            w is None for w in self.writes.get(_key(decl), []))

    def _string_call(self, call: Cursor, depth: int) -> Parts:
        args = written_arguments(call)
        target = call.referenced
        if call.spelling == "operator+" and len(args) == 2:
            return self.string(args[0], depth + 1) + self.string(args[1], depth + 1)
        if target is None:  # an implicit conversion wrapping the real expression
            inner = operand(call)
            return self.string(inner, depth + 1) if inner is not None else UNKNOWN
        if target.spelling == "getName" and not args and target.semantic_parent is not None \
                and target.semantic_parent.spelling == "this_node":
            return ("~",)  # ros::this_node::getName(): the node's own (private) name
        if target.kind == CursorKind.CONSTRUCTOR and (
            call.type.get_canonical().get_declaration().spelling in ("basic_string",
                                                                     "string_view")
        ):
            if not args:
                return ("",)
            return self.string(args[0], depth + 1) if len(args) == 1 else UNKNOWN
        if call.spelling in ("c_str", "str") and not args:
            children = list(call.get_children())
            if children and children[0].kind == CursorKind.MEMBER_REF_EXPR:
                objects = list(children[0].get_children())
                if objects:
                    return self.string(objects[0], depth + 1)
        return UNKNOWN

    def integer(self, cursor: Cursor, depth: int = 0) -> int | None:
        if depth > MAX_DEPTH:
            return None
        cursor = strip(cursor)
        if cursor.kind == CursorKind.INTEGER_LITERAL:
            token = self.token(cursor)
            return self._int_token(token) if token else None
        if cursor.kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
            decl = cursor.referenced
            if decl is not None and self.is_parameter(decl):
                return self.sites.agreed(  # type: ignore[union-attr]
                    decl, lambda arg, scope: scope.integer(arg, depth + 1), None)
            value = self.variable(decl) if decl is not None else None
            return None if value is None else self.integer(value, depth + 1)
        return None

    def token(self, cursor: Cursor) -> str | None:
        """The source token where ``cursor`` is (a literal, or the macro expanding to it)."""
        where = cursor.location
        text = self.source.get(where.file.name) if where.file is not None else None
        if text is None:
            return None
        match = _TOKEN.match(text, where.offset)
        return match.group(0).decode("ascii") if match else None

    def _int_token(self, token: str, depth: int = 0) -> int | None:
        if depth < MAX_DEPTH and token in self.macros:
            return self._int_token(self.macros[token], depth + 1)
        match = _INT.fullmatch(token)
        return int(match.group(1), 0) if match else None

    def boolean(self, cursor: Cursor) -> bool | None:
        cursor = strip(cursor)
        if cursor.kind == CursorKind.CXX_BOOL_LITERAL_EXPR:
            token = self.token(cursor) or ""
            token = self.macros.get(token, token)
            return {"true": True, "false": False}.get(token)
        if cursor.kind == CursorKind.DECL_REF_EXPR and cursor.referenced is not None:
            value = self.variable(cursor.referenced)
            return None if value is None else self.boolean(value)
        return None


class CallSites:
    """The calls of the file's own functions, so that a parameter's value can be read at
    its callers: ``setup(nh, "scan")`` makes ``topic`` of ``void setup(NodeHandle& nh,
    const std::string& topic)`` the string ``scan``, when every call agrees."""

    MAX_SITES = 16

    def __init__(self, functions: list[Cursor], macros: dict[str, str],
                 source: dict[str, bytes], external: bool = False) -> None:
        self.functions = functions
        self.macros = macros
        self.source = source
        # a parameter of a function no call in this file calls: a placeholder part that
        # the calls in the node's other files fill (ROS 1)
        self.external = external
        self._index: dict[tuple[str, int], list[tuple[Cursor, Cursor]]] | None = None
        self._scopes: dict[tuple[str, int], Scope] = {}
        self._active: set[tuple[str, int]] = set()  # parameters being read (recursion)

    def agreed(self, parm: Cursor, read: Callable[[Cursor, Scope], Value],
               unknown: Value) -> Value:
        """``read`` of the argument each call passes for ``parm``, when all agree."""
        key = _key(parm)
        if key in self._active:
            return unknown
        if self.external and isinstance(unknown, tuple):
            marker = self.placeholder(parm)
            if marker is not None:
                return (marker,)  # type: ignore[return-value]
        self._active.add(key)
        try:
            values = [read(arg, scope) for arg, scope in self._arguments(parm)]
        finally:
            self._active.discard(key)
        if not values or any(v != values[0] for v in values):
            return unknown
        return values[0]

    def placeholder(self, parm: Cursor) -> str | None:
        """The placeholder part of ``parm`` when no call in this file calls its function
        (other files of the node may), else None."""
        function = parm.semantic_parent
        if function is None or function.kind not in _CALLABLE or (
            self._sites().get(_key(function.canonical))
        ):
            return None
        params = [c for c in function.get_children() if c.kind == CursorKind.PARM_DECL]
        index = next((i for i, p in enumerate(params) if p.spelling == parm.spelling), None)
        usr = function.canonical.get_usr()
        if index is None or not usr or PLACEHOLDER in usr or SEPARATOR in usr:
            return None
        return f"{PLACEHOLDER}{usr}{SEPARATOR}{index}{PLACEHOLDER}"

    def external_sites(self) -> Iterator[tuple[Cursor, Cursor, Cursor]]:
        """(callee, call, caller) for the calls of functions not defined here."""
        defined = {_key(f.canonical) for f in self.functions}
        for key, sites in self._sites().items():
            if key in defined:
                continue
            for call, caller in sites:
                callee = _callee(call)
                if callee is not None:
                    yield callee, call, caller

    def scope(self, function: Cursor) -> Scope:
        return self._scope(function)

    def callers(self, function: Cursor) -> list[tuple[Cursor, Cursor]]:
        """(call, calling function) for the calls of ``function`` in this file."""
        return self._sites().get(_key(function.canonical), [])

    def _arguments(self, parm: Cursor) -> list[tuple[Cursor, Scope]]:
        function = parm.semantic_parent
        if function is None:
            return []
        params = [c for c in function.get_children() if c.kind == CursorKind.PARM_DECL]
        index = next((i for i, p in enumerate(params) if p.spelling == parm.spelling), None)
        sites = self._sites().get(_key(function.canonical), [])
        if index is None or len(sites) > self.MAX_SITES:
            return []
        found = []
        for call, caller in sites:
            args = list(call.get_arguments())
            if index >= len(args) or is_default_argument(args[index]):
                return []  # a call that does not say: the value is not known
            found.append((args[index], self._scope(caller)))
        return found

    def _sites(self) -> dict[tuple[str, int], list[tuple[Cursor, Cursor]]]:
        if self._index is None:
            self._index = {}
            for function in self.functions:
                for node in function.walk_preorder():
                    callee = _callee(node) if node.kind == CursorKind.CALL_EXPR else None
                    if callee is not None:
                        self._index.setdefault(_key(callee.canonical), []).append(
                            (node, function))
        return self._index

    def _scope(self, function: Cursor) -> Scope:
        key = _key(function)
        if key not in self._scopes:
            self._scopes[key] = Scope(function, self.macros, self.source, self)
        return self._scopes[key]


_CALLABLE = frozenset({CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD, CursorKind.CONSTRUCTOR,
                       CursorKind.FUNCTION_TEMPLATE})
_MAKERS = frozenset({"make_shared", "make_unique", "allocate_shared"})


def _callee(call: Cursor) -> Cursor | None:
    """The function a call calls; for ``std::make_shared<T>(args)`` / ``make_unique``
    (std or boost) the one constructor of ``T`` that takes as many arguments."""
    target = call.referenced
    if target is None or target.kind not in _CALLABLE:
        return None
    if target.spelling not in _MAKERS or target.kind == CursorKind.CONSTRUCTOR:
        return target
    ctype = call.type.get_canonical()
    if ctype.kind != TypeKind.RECORD or ctype.get_num_template_arguments() < 1:
        return None
    decl = ctype.get_template_argument_type(0).get_canonical().get_declaration()
    count = len(written_arguments(call))
    found = [c for c in decl.get_children() if c.kind == CursorKind.CONSTRUCTOR
             and len([p for p in c.get_children() if p.kind == CursorKind.PARM_DECL]) == count]
    return found[0] if len(found) == 1 else None


def initializer(decl: Cursor) -> Cursor | None:
    """The expression a variable declaration initialises it with, if any."""
    exprs = [c for c in decl.get_children() if c.kind.is_expression()]
    return exprs[-1] if exprs else None


def _string_constant(decl: Cursor) -> bool:
    """``static const char* kTopic = "x";`` outside functions: the usual way to write a
    name constant, whose pointer is not const but is not written either."""
    parent = decl.semantic_parent
    if parent is None or parent.kind not in (CursorKind.NAMESPACE, CursorKind.TRANSLATION_UNIT):
        return False
    ctype = decl.type.get_canonical()
    return ctype.kind == TypeKind.POINTER and ctype.get_pointee().is_const_qualified() and (
        ctype.get_pointee().get_canonical().kind in (TypeKind.CHAR_S, TypeKind.CHAR_U))


def _default_constructed(init: Cursor) -> bool:
    init = strip(init)
    return (init.kind == CursorKind.CALL_EXPR and init.referenced is not None
            and init.referenced.kind == CursorKind.CONSTRUCTOR
            and not written_arguments(init) and not list(init.get_children()))


def _plain_value(decl: Cursor) -> bool:
    """True for variables of a builtin or string type, the values we resolve."""
    ctype = decl.type.get_canonical()
    if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        ctype = ctype.get_pointee().get_canonical()
    return ctype.kind != TypeKind.RECORD or ctype.get_declaration().spelling == "basic_string"


def _key(decl: Cursor) -> tuple[str, int]:
    where = decl.location
    return (where.file.name if where.file else "", where.offset)


def _walk(cursor: Cursor) -> Iterator[Cursor]:
    stack = [cursor]
    while stack:
        node = stack.pop()
        yield node
        stack.extend(node.get_children())


def _literal(spelling: str) -> str | None:
    """The text of a plain C string literal as clang spells it, or None."""
    if len(spelling) < 2 or not spelling.startswith('"') or not spelling.endswith('"'):
        return None
    body, out, i = spelling[1:-1], [], 0
    while i < len(body):
        char = body[i]
        if char == "\\" and i + 1 < len(body):
            out.append(_ESCAPES.get(body[i + 1], body[i + 1]))
            i += 2
        else:
            out.append(char)
            i += 1
    return "".join(out)
