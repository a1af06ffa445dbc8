"""Cursors that remember what libclang told them: one walk of the syntax tree per unit.

Every analysis of a translation unit (values, wrappers, call sites, conditions, the
visitor) walks the same function bodies, and each step of libclang's Python binding is a
call through ctypes: ``get_children`` calls back into Python for every child and makes
a new cursor object each time, so what the binding caches on a cursor (its location,
extent, spelling, ...) is lost at the next walk. ``root(tu)`` gives the unit's cursor as
a ``Node``: a ``Cursor`` of the same bytes that keeps its children, kind, location,
extent, spelling and the cursors it refers to, each asked of libclang once. Every
cursor reached from it (children, ``referenced``, parents, definitions, arguments) is
the one ``Node`` of those bytes in the unit, so later walks run over Python lists.

Nothing here changes an answer: a ``Node`` is the cursor libclang gave, its cached
facts are those libclang returns for it (a parsed unit never changes), and two nodes
are equal exactly when ``clang_equalCursors`` says so. One exception, for libclang 18:
``this->member_`` in a class template is a dependent member access there (clang 19
looks the current instantiation up at definition), which refers to nothing; its
``referenced`` is the data member of that name the class (or a base it names) declares,
as clang 19 and a compiler's instantiation find it (``_this_member``).
"""

from __future__ import annotations

import ctypes
import functools
import os
import sys
import threading
from collections.abc import Callable, Iterator
from ctypes import c_uint
from typing import Any, Generic, TypeVar

from clang.cindex import (
    Cursor,
    CursorKind,
    File,
    SourceLocation,
    SourceRange,
    TranslationUnit,
    Type,
    TypeKind,
    c_object_p,
    callbacks,
    conf,
)

from ...processes import held_signals

__all__ = ["Node", "by_file", "child_spellings", "children_in", "line_of",
           "namespace_blocks", "overloads", "release", "root", "visit_children"]

_VISIT = callbacks["cursor_visit"]
Value = TypeVar("Value")
_DECLARATION: dict[int, bool] = {}  # kind id -> clang_isDeclaration
_KINDS: dict[int, CursorKind] = {}
_TYPE_KINDS: dict[int, TypeKind] = {}
_WHOLE: dict[int, bool] = {}  # kind id -> its subtree is visited at once
_BODIES = frozenset({
    CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD, CursorKind.CONSTRUCTOR,
    CursorKind.DESTRUCTOR, CursorKind.FUNCTION_TEMPLATE, CursorKind.CONVERSION_FUNCTION,
    CursorKind.FIELD_DECL, CursorKind.VAR_DECL, CursorKind.PARM_DECL,
})
_IN_BODY: dict[int, bool] = {}  # kind id -> a statement or expression
# the same two facts by the four bytes of the kind id in a cursor (``_alone``)
_BODY: dict[bytes, bool] = {}
_DECLARES: dict[bytes, bool] = {}
_KIND_OF: dict[bytes, CursorKind] = {}
_NONE = bytes(8)
MAX_OVERLOADS = 8  # the declarations of an overloaded name read
_PARENT = slice(16, 24)  # data[1] of a CXCursor: kind, xdata (4 bytes each), data[3]


class _RawString(ctypes.Structure):
    """libclang's ``CXString``, read and disposed of where it is asked for (the
    binding's own makes three objects and a finaliser per string)."""

    _fields_ = [("data", ctypes.c_void_p), ("flags", c_uint)]


class _Raw:
    """The few libclang functions every node asks, declared once more on a handle of
    our own (the binding's declarations convert every result through Python
    callbacks): a cursor's spelling, location and extent, a range's ends, and a
    location's file, line, column and offset, written into buffers kept here (one
    ``_Raw`` per thread)."""

    def __init__(self) -> None:
        lib = ctypes.CDLL(conf.lib._name)  # the library the binding loaded
        self.spelling = lib.clang_getCursorSpelling
        self.spelling.argtypes, self.spelling.restype = [Cursor], _RawString
        self.text = lib.clang_getCString
        self.text.argtypes, self.text.restype = [_RawString], ctypes.c_char_p
        self.dispose = lib.clang_disposeString
        self.dispose.argtypes, self.dispose.restype = [_RawString], None
        self.location = lib.clang_getCursorLocation
        self.location.argtypes, self.location.restype = [Cursor], _Place
        self.extent = lib.clang_getCursorExtent
        self.extent.argtypes, self.extent.restype = [Cursor], _Span
        self.start = lib.clang_getRangeStart
        self.start.argtypes, self.start.restype = [SourceRange], _Place
        self.end = lib.clang_getRangeEnd
        self.end.argtypes, self.end.restype = [SourceRange], _Place
        self.where = lib.clang_getInstantiationLocation
        self.where.argtypes = [SourceLocation, *[ctypes.c_void_p] * 4]
        self.where.restype = None
        self.referenced = self._to_cursor(lib.clang_getCursorReferenced)
        self.semantic_parent = self._to_cursor(lib.clang_getCursorSemanticParent)
        self.lexical_parent = self._to_cursor(lib.clang_getCursorLexicalParent)
        self.canonical = self._to_cursor(lib.clang_getCanonicalCursor)
        self.definition = self._to_cursor(lib.clang_getCursorDefinition)
        null = bytes(conf.lib.clang_getNullCursor())
        self.null = (null[:4], null[8:])  # what clang_equalCursors compares
        self.handle, self.line, self.column, self.offset = (
            ctypes.c_void_p(), c_uint(), c_uint(), c_uint())
        self.out = tuple(ctypes.addressof(value) for value in (
            self.handle, self.line, self.column, self.offset))

    @staticmethod
    def _to_cursor(function: Any) -> Any:
        function.argtypes, function.restype = [Cursor], Cursor
        return function

    def related(self, function: Any, cursor: Cursor) -> bytes | None:
        """The bytes of the cursor ``function`` gives for ``cursor``; None for the null
        cursor (the binding's ``Cursor.from_result`` asks libclang twice to tell)."""
        raw = bytes(function(cursor))
        return None if (raw[:4], raw[8:]) == self.null else raw

    def spelled(self, cursor: Cursor) -> str | None:
        """What ``Cursor.spelling`` gives (None for a null string, as the binding)."""
        found = self.spelling(cursor)
        text = self.text(found)
        self.dispose(found)
        return None if text is None else text.decode("utf8")

    def instantiation(self, location: SourceLocation) -> tuple[int | None, int, int, int]:
        """The address of the location's file handle (None: no file), its line, column
        and offset."""
        self.where(location, *self.out)
        return self.handle.value, self.line.value, self.column.value, self.offset.value

    def file_handle(self, location: SourceLocation) -> int | None:
        self.where(location, self.out[0], None, None, None)
        return self.handle.value


_RAW = threading.local()  # each thread's own (its buffers), made on first use


def _raw() -> _Raw:
    try:
        found: _Raw = _RAW.raw
    except AttributeError:
        found = _RAW.raw = _Raw()
    return found


class cached(Generic[Value]):
    """An attribute computed on first use and then kept in the instance's ``__dict__``
    (``functools.cached_property`` takes a lock on every first use, a third of the cost
    of a node)."""

    def __init__(self, compute: Any) -> None:
        self.compute = compute
        self.name = compute.__name__

    def __set_name__(self, owner: type, name: str) -> None:
        self.name = name

    def __get__(self, instance: Any, owner: type | None = None) -> Value:
        if instance is None:
            return self  # type: ignore[return-value]
        value: Value = self.compute(instance)
        instance.__dict__[self.name] = value
        return value


class _Unit:
    """The nodes of one translation unit by their bytes, and its files by handle."""

    def __init__(self, tu: TranslationUnit) -> None:
        self.tu = tu
        self.nodes: dict[bytes, Node] = {}
        self.files: dict[int | None, _File] = {}

    def node(self, cursor: Cursor | None) -> Node | None:
        return None if cursor is None else self.made(bytes(cursor))

    def made(self, raw: bytes) -> Node:
        """The one node of the cursor whose bytes are ``raw``."""
        found = self.nodes.get(raw)
        if found is None:
            found = Node.from_buffer_copy(raw)
            kind = _KIND_OF.get(raw[:4])
            if kind is None:
                kind = _KIND_OF[raw[:4]] = _kind(found._kind_id)
            facts = found.__dict__  # the instance's own attributes, set directly
            facts["_tu"], facts["_unit"], facts["kind"] = self.tu, self, kind
            self.nodes[raw] = found
        return found

    def release(self) -> None:
        """Forget every node and what each keeps (the unit is done with): the nodes
        refer to the unit and to each other, cycles the reference counts alone would
        never free; broken here, the unit's millions of objects go at once, with no
        collection of the cyclic garbage collector walking them."""
        for node in self.nodes.values():
            node.__dict__.clear()
        self.nodes.clear()
        self.files.clear()

    def file(self, handle: File | None) -> _File | None:
        if handle is None:
            return None
        return self.handle(ctypes.cast(handle.obj, ctypes.c_void_p).value)

    def handle(self, key: int | None) -> _File | None:
        """The one ``_File`` of the file handle whose address is ``key``."""
        if not key:
            return None
        found = self.files.get(key)
        if found is None:
            found = self.files[key] = _File(ctypes.cast(key, c_object_p))
            found._tu = self.tu
        return found


def _kind(kind_id: int) -> CursorKind:
    found = _KINDS.get(kind_id)
    if found is None:
        found = _KINDS[kind_id] = CursorKind.from_id(kind_id)
    return found


def _alone(raw: bytes, parent: bytes) -> bytes:
    """A statement's or expression's cursor as a visit of its parent alone makes it.

    A cursor of a statement or expression holds the declaration that encloses it
    (``data[0]``), which libclang's visitor passes down from the nearest declaration it
    visited: a visit of the whole subtree of a function gives every statement of the
    body that function, a visit of one statement gives its children none. Cursors with
    other ``data[0]`` are equal (``clang_equalCursors``) to different cursors, so the
    bytes are made those of a visit of the parent alone: the parent's declaration when
    it is one, else none."""
    body = _BODY.get(raw[:4])
    if body is None:
        body = _BODY[raw[:4]] = _in_body(int.from_bytes(raw[:4], sys.byteorder, signed=True))
    if not body:
        return raw
    declares = _DECLARES.get(parent[:4])
    if declares is None:
        declares = _DECLARES[parent[:4]] = _declares(
            int.from_bytes(parent[:4], sys.byteorder, signed=True))
    if declares:
        return raw  # the parent's declaration in both visits
    return raw[:8] + _NONE + raw[16:]


def _in_body(kind: int) -> bool:
    found = _IN_BODY.get(kind)
    if found is None:
        cursor_kind = _kind(kind)
        found = _IN_BODY[kind] = bool(cursor_kind.is_statement() or cursor_kind.is_expression())
    return found


def _whole(kind: int) -> bool:
    """Whether a cursor of this kind is visited with its whole subtree."""
    found = _WHOLE.get(kind)
    if found is None:
        found = _WHOLE[kind] = _in_body(kind) or _kind(kind) in _BODIES
    return found


def _declares(kind: int) -> bool:
    found = _DECLARATION.get(kind)
    if found is None:
        found = _DECLARATION[kind] = bool(_kind(kind).is_declaration())
    return found


def root(tu: TranslationUnit) -> Node:
    """The translation unit's cursor as a ``Node``."""
    node = _Unit(tu).node(tu.cursor)
    assert node is not None
    return node


def release(node: Node) -> None:
    """Free the nodes of ``node``'s unit (``_Unit.release``): no node of it may be used
    after this."""
    node._unit.release()


def line_of(location: SourceLocation) -> int:
    """The line of a source location (where it is instantiated), asked of libclang once
    (``_Raw.instantiation``)."""
    return _raw().instantiation(location)[1]


def by_file(judge: Callable[[str], Value]) -> Callable[[Any], Value | None]:
    """``judge`` of the name of the file a source location is in, asked once per file;
    None for a location in no file. Each file is told by its handle (one libclang call
    per location, no ``File`` or ``SourceLocation`` made), so a visit over the thousands
    of cursors of a unit's headers asks each file's name once."""
    file_handle = _raw().file_handle
    judged: dict[int | None, Value | None] = {None: None}

    def of(location: Any) -> Value | None:
        key = file_handle(location)
        if key not in judged:
            assert key is not None  # None is judged above: no file
            judged[key] = judge(File(ctypes.cast(key, c_object_p)).name)
        return judged[key]

    return of


def visit_children(parent: Cursor, visit: Callable[[Cursor, Cursor, object], int]) -> None:
    """``clang_visitChildren`` of ``parent`` with ``visit``. A Ctrl-C or SIGTERM that
    comes meanwhile (in a run that handles them: ``processes.stop_signals``) is raised
    when the visit ends: its handler runs where the interpreter is, mostly at the start
    of a callback, where ctypes would print the exception and go on, and the run would
    not stop."""
    with held_signals:
        conf.lib.clang_visitChildren(parent, _VISIT(visit), None)


def children_in(parent: Cursor, wanted: Callable[[str], bool]) -> list[Cursor]:
    """The children of ``parent`` (the unit, a namespace, a class) whose location is in
    a file whose name is ``wanted``, in order: what a loop over its children that asks
    each one's ``location.file`` keeps, each file judged once (``by_file``) and a node
    made only for the children kept (most of a unit's are in headers nobody walks). Kept
    with the parent for the same ``wanted``: the visitor's search for definitions and
    ``call_conditions.hidden_facts`` ask the same."""
    assert isinstance(parent, Node)
    asked = parent.__dict__.setdefault("_kept", {})  # by ``wanted``: the same asked again
    if wanted in asked:
        return list(asked[wanted])
    lib = conf.lib
    kept = by_file(wanted)
    found: list[bytes] = []

    def visit(child: Cursor, _parent: Cursor, _data: object) -> int:
        if kept(lib.clang_getCursorLocation(child)):
            found.append(bytes(child))
        return 1  # CXChildVisit_Continue

    visit_children(parent, visit)
    made = parent._unit.made
    asked[wanted] = nodes = [made(raw) for raw in found]
    return list(nodes)


def namespace_blocks(unit: Cursor) -> dict[str | None, list[Cursor]]:
    """The unit's top-level ``namespace`` blocks by name, in order: one visit of its
    children that makes a cursor only for those (most are declarations and
    preprocessing entities of its headers)."""
    raw = _raw()
    namespace = CursorKind.NAMESPACE.value
    tu = unit._tu
    blocks: dict[str | None, list[Cursor]] = {}

    def visit(child: Cursor, _parent: Cursor, _data: object) -> int:
        if child._kind_id == namespace:
            child._tu = tu
            blocks.setdefault(raw.spelled(child), []).append(child)
        return 1  # CXChildVisit_Continue

    visit_children(unit, visit)
    return blocks


def child_spellings(parent: Cursor) -> list[str | None]:
    """The spellings of ``parent``'s children, in order (what ``child.spelling`` gives
    for each), with no cursor kept."""
    raw = _raw()
    found: list[str | None] = []

    def visit(child: Cursor, _parent: Cursor, _data: object) -> int:
        found.append(raw.spelled(child))
        return 1  # CXChildVisit_Continue

    visit_children(parent, visit)
    return found


def overloads(cursor: Cursor) -> list[Cursor | None]:
    """The declarations an overloaded name (``OVERLOADED_DECL_REF``) may be, at most
    ``MAX_OVERLOADS``: a node's asked once."""
    if isinstance(cursor, Node):
        return cursor.overloads
    count = min(conf.lib.clang_getNumOverloadedDecls(cursor), MAX_OVERLOADS)
    return [conf.lib.clang_getOverloadedDecl(cursor, i) for i in range(count)]


class _File(File):
    """A file whose name is asked once."""

    @cached
    def name(self) -> str:
        return str(File.name.fget(self))


class _Place(SourceLocation):
    """A source location whose file is the unit's one ``_File``."""

    _unit: _Unit
    _data: tuple[_File | None, int, int, int] | None = None

    def _get_instantiation(self) -> tuple[_File | None, int, int, int]:
        """What ``SourceLocation`` asks libclang once, with the file told by its handle
        (no ``File`` made each time); its four parts are then the location's own
        attributes (``file``, ``line``, ``column``, ``offset``: no call to read one)."""
        if self._data is None:
            key, line, column, offset = _raw().instantiation(self)
            data = self._data = (self._unit.handle(key), line, column, offset)
            facts = self.__dict__
            facts["file"], facts["line"], facts["column"], facts["offset"] = data
        return self._data

    @cached
    def file(self) -> _File | None:
        return self._get_instantiation()[0]

    @cached
    def line(self) -> int:
        return self._get_instantiation()[1]

    @cached
    def column(self) -> int:
        return self._get_instantiation()[2]

    @cached
    def offset(self) -> int:
        return self._get_instantiation()[3]

    @cached
    def key(self) -> tuple[str, int]:
        """The location's file name ("" for none) and offset: a place of the unit."""
        where = self._get_instantiation()
        return (where[0].name if where[0] is not None else "", where[3])


class _Span(SourceRange):
    """A source range whose ends are asked once."""

    _unit: _Unit

    @cached
    def start(self) -> _Place:
        place: _Place = _raw().start(self)
        place._unit = self._unit
        return place

    @cached
    def end(self) -> _Place:
        place: _Place = _raw().end(self)
        place._unit = self._unit
        return place


class _Type(Type):
    """A type that asks libclang each of its facts once, whose declaration is the
    unit's ``Node`` and whose related types (canonical, pointee, template arguments)
    are ``_Type`` too: the analyses ask the same types again and again."""

    _unit: _Unit

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Type) and bool(conf.lib.clang_equalTypes(self, other))

    def __ne__(self, other: object) -> bool:
        return not self.__eq__(other)

    __hash__ = None  # type: ignore[assignment]  # as Type's: not hashable by value

    @cached
    def kind(self) -> TypeKind:
        found = _TYPE_KINDS.get(self._kind_id)
        if found is None:
            found = _TYPE_KINDS[self._kind_id] = TypeKind.from_id(self._kind_id)
        return found

    @cached
    def spelling(self) -> str:
        return str(Type.spelling.fget(self))

    @cached
    def _argument_types(self) -> tuple[Type, ...]:
        lib = conf.lib
        found = []
        for index in range(lib.clang_getNumArgTypes(self)):
            each = lib.clang_getArgType(self, index)
            if each.kind == TypeKind.INVALID:
                break  # (where the binding's container stops too)
            found.append(each)
        return tuple(found)

    def argument_types(self) -> tuple[Type, ...]:
        """The parameter types the binding's container gives, in order, asked once (the
        binding makes a new container class at every call)."""
        assert self.kind == TypeKind.FUNCTIONPROTO
        return self._argument_types

    @cached
    def _canonical(self) -> _Type:
        return _type(Type.get_canonical(self), self._unit)

    def get_canonical(self) -> _Type:
        return self._canonical

    @cached
    def _pointee(self) -> _Type:
        return _type(Type.get_pointee(self), self._unit)

    def get_pointee(self) -> _Type:
        return self._pointee

    @cached
    def _declaration(self) -> Node | None:
        return self._unit.node(Type.get_declaration(self))

    def get_declaration(self) -> Node | None:
        return self._declaration

    @cached
    def _count(self) -> int:
        return int(Type.get_num_template_arguments(self))

    def get_num_template_arguments(self) -> int:
        return self._count

    @cached
    def _arguments(self) -> dict[int, _Type]:
        return {}

    def get_template_argument_type(self, num: int) -> _Type:
        found: _Type | None = self._arguments.get(num)
        if found is None:
            found = self._arguments[num] = _type(
                Type.get_template_argument_type(self, num), self._unit)
        return found


def _type(plain: Type, unit: _Unit) -> _Type:
    made = _Type.from_buffer_copy(plain)
    made._tu = plain._tu
    made._unit = unit
    return made


class Node(Cursor):
    """A cursor of a translation unit that asks libclang each of its facts once."""

    _unit: _Unit

    def __eq__(self, other: object) -> bool:
        if type(other) is Node:
            return self._identity == other._identity
        if not isinstance(other, Cursor):
            # ``None == node`` asks the node (a member reference the parse left
            # unresolved: ``target.referenced == field``); libclang takes no None
            return False
        return bool(Cursor.__eq__(self, other))

    def __ne__(self, other: object) -> bool:
        return not self.__eq__(other)

    __hash__ = Cursor.__hash__  # clang_hashCursor: equal cursors hash alike

    @cached
    def _identity(self) -> bytes:
        """The bytes ``clang_equalCursors`` compares: the kind and ``data`` (not
        ``xdata``), a declaration's without ``data[1]`` (whether it came first in its
        group)."""
        raw = bytes(self)
        if _declares(self._kind_id):
            return raw[:4] + raw[8:_PARENT.start] + _NONE + raw[_PARENT.stop:]
        return raw[:4] + raw[8:]

    @cached
    def _children(self) -> list[Node]:
        """The children, asked of libclang in one visit of the whole subtree (one
        callback per descendant, not one visit per node) for a function, a variable
        or a statement, whose whole body the analyses walk; one level at a time for a
        namespace or a class (and the unit), whose members are mostly in headers
        nobody walks. The visit gives each cursor the
        bytes a visit of its parent alone gives (``_alone``). A cursor met twice (the
        same expression under two parents) keeps no list from it: its children are
        asked on their own when wanted."""
        if not _whole(self._kind_id):
            return self._visit_children()
        own = bytes(self)
        made = self._unit.made
        lists: dict[bytes, list[Node]] = {own: []}
        twice: set[bytes] = set()
        alone = {own: own}  # the bytes of the visit -> those of a visit of the parent

        def visit(child: Cursor, parent: Cursor, _data: object) -> int:
            above = bytes(parent)
            key = alone.get(above)
            if key is None:  # not met before its children: cannot happen in preorder
                twice.add(own)
                return 0  # CXChildVisit_Break
            real = bytes(child)
            raw = _alone(real, above)
            if raw in lists:
                twice.add(raw)
            else:
                lists[raw] = []
            if alone.setdefault(real, raw) != raw:
                twice.update((raw, alone[real]))
            lists[key].append(made(raw))
            return 2  # CXChildVisit_Recurse

        visit_children(self, visit)
        if own in twice:
            return self._visit_children()
        for raw, children in lists.items():
            if raw not in twice and raw != own:
                made(raw).__dict__["_children"] = children
        return lists[own]

    def _visit_children(self) -> list[Node]:
        found: list[bytes] = []

        def visit(child: Cursor, _parent: Cursor, _data: object) -> int:
            found.append(bytes(child))
            return 1  # CXChildVisit_Continue

        visit_children(self, visit)
        made = self._unit.made
        return [made(raw) for raw in found]

    def get_children(self) -> Iterator[Node]:
        return iter(self._children)

    def walk_preorder(self) -> Iterator[Node]:
        return iter(self._preorder)

    @cached
    def _preorder(self) -> list[Node]:
        """The node and its descendants in preorder, what the binding's
        ``walk_preorder`` yields, made once: the unit's analyses walk the same bodies
        and statements again."""
        return self._kept_walk("_preorder", first_to_last=True)

    def walk_last_first(self) -> Iterator[Node]:
        """The node, then the walk of each child from the last to the first: the order
        of a walk that pops a stack and pushes the children in order (``values._walk``),
        made once per node as ``walk_preorder``'s."""
        return iter(self._last_first)

    @cached
    def _last_first(self) -> list[Node]:
        return self._kept_walk("_last_first", first_to_last=False)

    def _kept_walk(self, kept: str, first_to_last: bool) -> list[Node]:
        """The node, then each child's walk, the children taken first to last or last
        to first; a descendant walked so before (its list kept as ``kept``) gives its
        list whole."""
        found: list[Node] = [self]
        stack: list[Node] = list(reversed(self._children) if first_to_last
                                 else self._children)
        while stack:
            node = stack.pop()
            below: list[Node] | None = node.__dict__.get(kept)
            if below is not None:
                found += below
                continue
            found.append(node)
            stack += reversed(node._children) if first_to_last else node._children
        return found

    @cached
    def kind(self) -> CursorKind:
        return _kind(self._kind_id)  # set when the node is made

    @cached
    def spelling(self) -> str:
        return _raw().spelled(self)  # type: ignore[return-value]  # as the binding's

    @cached
    def location(self) -> _Place:
        place: _Place = _raw().location(self)
        place._unit = self._unit
        return place

    @cached
    def extent(self) -> _Span:
        span: _Span = _raw().extent(self)
        span._unit = self._unit
        return span

    @cached
    def type(self) -> _Type:
        return _type(Cursor.type.fget(self), self._unit)

    def _related(self, function: Any) -> Node | None:
        raw = _raw().related(function, self)
        return None if raw is None else self._unit.made(raw)

    @cached
    def referenced(self) -> Node | None:
        found = self._related(_raw().referenced)
        if found is None and self.kind == CursorKind.MEMBER_REF_EXPR:
            return _this_member(self)
        return found

    @cached
    def semantic_parent(self) -> Node | None:
        return self._related(_raw().semantic_parent)

    @cached
    def lexical_parent(self) -> Node | None:
        return self._related(_raw().lexical_parent)

    @cached
    def canonical(self) -> Node | None:
        return self._related(_raw().canonical)

    @cached
    def _definition(self) -> Node | None:
        return self._related(_raw().definition)

    def get_definition(self) -> Node | None:
        return self._definition

    @cached
    def _arguments(self) -> list[Node | None]:
        return [self._unit.node(arg) for arg in Cursor.get_arguments(self)]

    def get_arguments(self) -> Iterator[Node | None]:
        return iter(self._arguments)

    @cached
    def _usr(self) -> str:
        return str(Cursor.get_usr(self))

    def get_usr(self) -> str:
        return self._usr

    @cached
    def overloads(self) -> list[Node | None]:
        """The declarations an overloaded name (``OVERLOADED_DECL_REF``) may be, at
        most ``MAX_OVERLOADS``."""
        count = min(conf.lib.clang_getNumOverloadedDecls(self), MAX_OVERLOADS)
        return [self._unit.node(conf.lib.clang_getOverloadedDecl(self, i))
                for i in range(count)]

    @cached
    def _is_definition(self) -> bool:
        return bool(Cursor.is_definition(self))

    def is_definition(self) -> bool:
        return self._is_definition


_MEMBERS = frozenset({CursorKind.FIELD_DECL, CursorKind.VAR_DECL})
_CLASSES = frozenset({CursorKind.CLASS_TEMPLATE, CursorKind.CLASS_DECL,
                      CursorKind.STRUCT_DECL,
                      CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION})
MAX_BASES = 4  # base classes followed up from a class template for ``this->member``


def _this_member(access: Node) -> Node | None:
    """The data member ``this->name`` names in a class template, which libclang 18 keeps
    as a dependent member access referring to nothing (yasmin's ``MonitorState<MsgT>``:
    ``this->node_->create_subscription<MsgT>(this->topic_name, ...)``): the field or
    static member of that name the class declares, else one of the classes it derives
    from, nearest first; None for any other access, or a name none of them declares
    (a member of a base that depends on the template's parameters)."""
    children = list(access.get_children())
    if not children or children[0].kind != CursorKind.CXX_THIS_EXPR:
        return None
    this = children[0]
    tokens = [t.spelling for t in access.get_tokens()
              if t.extent.start.offset >= this.extent.end.offset]
    while tokens and tokens[0] in ("->", "template"):
        tokens.pop(0)
    if not tokens or not (tokens[0][0].isalpha() or tokens[0][0] == "_"):
        return None
    pointee: Type = this.type.get_pointee()
    owner = access._unit.node(pointee.get_declaration())
    return _declared_member(owner, tokens[0], 0)


def _declared_member(owner: Node | None, name: str, depth: int) -> Node | None:
    if owner is None or owner.kind not in _CLASSES or depth > MAX_BASES:
        return None
    definition = owner.get_definition() or owner
    bases: list[Node] = []
    for child in definition.get_children():
        if child.kind in _MEMBERS and child.spelling == name:
            return child
        if child.kind == CursorKind.CXX_BASE_SPECIFIER:
            base: Cursor | None = child.referenced or child.type.get_declaration()
            found = base if isinstance(base, Node) else definition._unit.node(base)
            if found is not None:
                bases.append(found)
    for base in bases:
        found = _declared_member(base, name, depth + 1)
        if found is not None:
            return found
    return None


_STANDIN = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "standin")


def from_standin(target: Cursor | None) -> bool:
    """Whether ``target`` (the function, constructor or class a call names) is declared
    in one of our stand-ins (``standin/``, ``standin/fallback`` included), not in a header
    of the workspace."""
    if target is None or target.location.file is None:
        return False
    return in_standin(target.location.file.name)


@functools.lru_cache(maxsize=1024)
def in_standin(path: str) -> bool:
    """Whether the file ``path`` is one of our stand-ins."""
    return os.path.realpath(path).startswith(os.path.realpath(_STANDIN) + os.sep)
