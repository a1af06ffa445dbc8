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
are equal exactly when ``clang_equalCursors`` says so.
"""

from __future__ import annotations

import ctypes
from collections.abc import Iterator
from typing import Any, Generic, TypeVar

from clang.cindex import (
    Cursor,
    CursorKind,
    File,
    SourceLocation,
    SourceRange,
    TranslationUnit,
    callbacks,
    conf,
)

__all__ = ["Node", "root"]

_VISIT = callbacks["cursor_visit"]
Value = TypeVar("Value")
_DECLARATION: dict[int, bool] = {}  # kind id -> clang_isDeclaration
_PARENT = slice(16, 24)  # data[1] of a CXCursor: kind, xdata (4 bytes each), data[3]
_NO_PARENT = bytes(8)


class cached_property(Generic[Value]):  # noqa: N801 - functools' name, without its lock
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
        if cursor is None:
            return None
        raw = bytes(cursor)
        found = self.nodes.get(raw)
        if found is None:
            found = Node.from_buffer_copy(raw)
            found._tu = cursor._tu
            found._unit = self
            self.nodes[raw] = found
        return found

    def file(self, handle: File | None) -> _File | None:
        if handle is None:
            return None
        key = ctypes.cast(handle.obj, ctypes.c_void_p).value
        found = self.files.get(key)
        if found is None:
            found = self.files[key] = _File(handle.obj)
            found._tu = self.tu
        return found


def root(tu: TranslationUnit) -> Node:
    """The translation unit's cursor as a ``Node``."""
    node = _Unit(tu).node(tu.cursor)
    assert node is not None
    return node


class _File(File):  # type: ignore[misc]
    """A file whose name is asked once."""

    @cached_property
    def name(self) -> str:  # type: ignore[override]
        return str(File.name.fget(self))  # type: ignore[attr-defined]


class _Place(SourceLocation):  # type: ignore[misc]
    """A source location whose file is the unit's one ``_File``."""

    _unit: _Unit

    @cached_property
    def file(self) -> _File | None:  # type: ignore[override]
        return self._unit.file(SourceLocation.file.fget(self))  # type: ignore[attr-defined]


def _place(location: SourceLocation, unit: _Unit) -> _Place:
    place = _Place.from_buffer_copy(location)
    place._unit = unit
    return place


class _Span(SourceRange):  # type: ignore[misc]
    """A source range whose ends are asked once."""

    _unit: _Unit

    @cached_property
    def start(self) -> _Place:  # type: ignore[override]
        return _place(SourceRange.start.fget(self), self._unit)  # type: ignore[attr-defined]

    @cached_property
    def end(self) -> _Place:  # type: ignore[override]
        return _place(SourceRange.end.fget(self), self._unit)  # type: ignore[attr-defined]


class Node(Cursor):  # type: ignore[misc]
    """A cursor of a translation unit that asks libclang each of its facts once."""

    _unit: _Unit

    def __eq__(self, other: object) -> bool:
        if type(other) is Node:
            return self._identity == other._identity
        return bool(Cursor.__eq__(self, other))

    def __ne__(self, other: object) -> bool:
        return not self.__eq__(other)

    __hash__ = Cursor.__hash__  # clang_hashCursor: equal cursors hash alike

    @cached_property
    def _identity(self) -> bytes:
        """The bytes ``clang_equalCursors`` compares: a declaration's are its own
        without ``data[1]`` (whether it came first in its group)."""
        raw = bytes(self)
        kind = self._kind_id
        declaration = _DECLARATION.get(kind)
        if declaration is None:
            declaration = _DECLARATION[kind] = bool(CursorKind.from_id(kind).is_declaration())
        return raw[:_PARENT.start] + _NO_PARENT + raw[_PARENT.stop:] if declaration else raw

    @cached_property
    def _children(self) -> list[Node]:
        found: list[Cursor] = []

        def visit(child: Cursor, _parent: Cursor, _data: object) -> int:
            found.append(child)
            return 1  # CXChildVisit_Continue

        conf.lib.clang_visitChildren(self, _VISIT(visit), None)
        node = self._unit.node
        for child in found:
            child._tu = self._tu
        return [node(child) for child in found]  # type: ignore[misc]

    def get_children(self) -> Iterator[Node]:
        return iter(self._children)

    def walk_preorder(self) -> Iterator[Node]:
        stack = [self]
        while stack:
            node = stack.pop()
            yield node
            stack.extend(reversed(node._children))

    @cached_property
    def kind(self) -> CursorKind:  # type: ignore[override]
        return CursorKind.from_id(self._kind_id)

    @cached_property
    def spelling(self) -> str:  # type: ignore[override]
        return Cursor.spelling.fget(self)  # type: ignore[attr-defined, no-any-return]

    @cached_property
    def location(self) -> _Place:  # type: ignore[override]
        return _place(Cursor.location.fget(self), self._unit)  # type: ignore[attr-defined]

    @cached_property
    def extent(self) -> _Span:  # type: ignore[override]
        span = _Span.from_buffer_copy(Cursor.extent.fget(self))  # type: ignore[attr-defined]
        span._unit = self._unit
        return span

    @cached_property
    def type(self):  # type: ignore[no-untyped-def, override]
        return Cursor.type.fget(self)  # type: ignore[attr-defined]

    @cached_property
    def referenced(self) -> Node | None:  # type: ignore[override]
        return self._unit.node(Cursor.referenced.fget(self))  # type: ignore[attr-defined]

    @cached_property
    def semantic_parent(self) -> Node | None:  # type: ignore[override]
        return self._unit.node(Cursor.semantic_parent.fget(self))  # type: ignore[attr-defined]

    @cached_property
    def lexical_parent(self) -> Node | None:  # type: ignore[override]
        return self._unit.node(Cursor.lexical_parent.fget(self))  # type: ignore[attr-defined]

    @cached_property
    def canonical(self) -> Node | None:  # type: ignore[override]
        return self._unit.node(Cursor.canonical.fget(self))  # type: ignore[attr-defined]

    @cached_property
    def _definition(self) -> Node | None:
        return self._unit.node(Cursor.get_definition(self))

    def get_definition(self) -> Node | None:
        return self._definition

    @cached_property
    def _arguments(self) -> list[Node | None]:
        return [self._unit.node(arg) for arg in Cursor.get_arguments(self)]

    def get_arguments(self) -> Iterator[Node | None]:
        return iter(self._arguments)

    @cached_property
    def _is_definition(self) -> bool:
        return bool(Cursor.is_definition(self))

    def is_definition(self) -> bool:
        return self._is_definition
