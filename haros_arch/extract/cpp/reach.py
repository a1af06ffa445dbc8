"""The functions of other packages' headers that a unit's own code can reach, by name.

A translation unit holds every inline function, class template and method of every
workspace header it includes: in navigation2 six in seven of the syntax nodes the walk
visited were in headers (nav2_ros_common's lifecycle node, action server and factories),
walked again in every unit that includes them. Another package's header code runs in
this program only where the program names it: the unit's source (and its own package's
headers, which are its code: a library source that only includes them compiles them)
names the classes it builds or holds and the functions it calls; a reached class's
declarations (its bases, its members' types, its initialisers), a reached function's
body, an alias and a macro the unit writes name what they use in turn. What no such
chain names is not run by this unit (the units that run it name it, include its header
and walk it there) and is left out of the walk (``reachable``).

The test errs on the side of walking: any identifier written counts (a string's, a dead
branch's; not a comment's); once its class is named, a constructor, destructor,
conversion, operator, field initialiser, static or virtual method counts (code the
workspace does not hold calls those by convention or through a base: a pluginlib
host, a BehaviorTree factory's ``providedPorts``), and any other method where its name is
written too; a function whose name is no identifier always counts; every variable of
namespace scope (a registration macro's, a static initialiser's) is a root wherever it is.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from typing import Any

from clang.cindex import Cursor, CursorKind

__all__ = ["CLASSES", "FUNCTIONS", "reachable"]

_WORDS = re.compile(rb"[A-Za-z_]\w*")
CLASSES = frozenset({
    CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL, CursorKind.UNION_DECL,
    CursorKind.CLASS_TEMPLATE, CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION,
})
FUNCTIONS = frozenset({
    CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD, CursorKind.CONSTRUCTOR,
    CursorKind.DESTRUCTOR, CursorKind.FUNCTION_TEMPLATE, CursorKind.CONVERSION_FUNCTION,
})
_NAME = re.compile(r"[A-Za-z_]\w*")


# a comment (the words of a string literal count: a name may be looked up by it)
_COMMENTS = re.compile(rb'"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|//[^\n]*|/\*.*?\*/',
                       re.DOTALL)


class _Code:
    """The workspace's files by name as the parse read them (``get``), their comments
    blanked, offsets kept: what a comment names runs nowhere."""

    def __init__(self, source: Any) -> None:
        self.source = source
        self.files: dict[str, bytes | None] = {}

    def get(self, name: str) -> bytes | None:
        if name not in self.files:
            data = self.source.get(name)
            self.files[name] = None if data is None else _COMMENTS.sub(_blank, data)
        return self.files[name]


def _blank(match: re.Match[bytes]) -> bytes:
    text = match.group()
    return text if text[:1] in (b'"', b"'") else b" " * len(text)


def _text(source: Any, cursor: Cursor) -> tuple[bytes, int, int] | None:
    """The bytes of ``cursor``'s file and its extent's offsets (None: no file read)."""
    extent = cursor.extent
    start = extent.start
    data = source.get(start.file.name) if start.file is not None else None
    return None if data is None else (data, start.offset, extent.end.offset)


def _words(source: Any, cursor: Cursor) -> set[bytes]:
    """The identifiers written in ``cursor``'s extent (none when its file is not read)."""
    text = _text(source, cursor)
    return set() if text is None else set(_WORDS.findall(*text))


def _declarations(source: Any, definition: Cursor) -> set[bytes]:
    """The identifiers of a class's or macro's definition, but those in the bodies of
    the methods it defines inline (each counts where the method runs)."""
    text = _text(source, definition)
    if text is None or definition.kind not in CLASSES:
        return set() if text is None else set(_WORDS.findall(*text))
    data, at, end = text
    bodies = sorted((child.extent.start.offset, child.extent.end.offset)
                    for child in definition.get_children()
                    if child.kind in FUNCTIONS and child.is_definition())
    found: set[bytes] = set()
    for first, last in bodies:
        found.update(_WORDS.findall(data, at, max(at, first)))
        at = max(at, last)
    found.update(_WORDS.findall(data, at, end))
    return found


def _key(function: Cursor) -> tuple[bytes | None, bytes | None]:
    """The names that must be written for ``function`` to run: its innermost class's
    for a member (and its own for a method C++ calls only by name: not a constructor,
    destructor, conversion, operator, static or virtual method, which code the workspace
    does not hold may call by convention or through a base), its own for a free
    function; None for a name that need not be written (an operator, a class or
    function with no name)."""
    parent = function.semantic_parent
    name = function.spelling.split("<")[0]
    own = name.encode() if _NAME.fullmatch(name) and not name.startswith("operator") else None
    if parent is None or parent.kind not in CLASSES:
        return None, own
    cls = parent.spelling.split("<")[0]
    owner = cls.encode() if _NAME.fullmatch(cls) else None
    if function.kind not in _METHODS or function.is_static_method() or (
            function.is_virtual_method()):
        own = None
    return owner, own


_METHODS = frozenset({CursorKind.CXX_METHOD, CursorKind.FUNCTION_TEMPLATE})


def reachable(functions: list[Cursor], main: str, source: Any, roots: Iterable[Cursor],
              texts: dict[bytes, list[Cursor]], local: Callable[[str], bool]) -> list[Cursor]:
    """``functions`` (the unit's definitions in workspace files, in order) less those of
    headers that nothing the unit's main file ``main`` writes reaches by name (see the
    module's text). ``roots``: cursors whose text runs wherever the unit does (variables
    of namespace scope); ``texts``: the class, alias and macro definitions of the
    workspace's files by name, whose text counts once their name is written (a class's
    members are built with it; a macro's expansion is written where its name is).
    ``source`` gives a file's bytes by name (``get``); ``local``: whether a file is of the
    unit's own package, whose headers are its code (a library source that only includes
    them compiles them), all kept."""
    source = _Code(source)
    names: set[bytes] = set()
    data = source.get(main)
    if data is not None:
        names.update(_WORDS.findall(data))
    for root in roots:
        names |= _words(source, root)
    pending: list[tuple[Cursor, tuple[bytes | None, bytes | None]]] = []
    kept: set[int] = set()
    for function in functions:
        where = function.location.file
        if where is None or where.name == main:
            kept.add(id(function))
        elif local(where.name):
            kept.add(id(function))
            names |= _words(source, function)
        else:
            pending.append((function, _key(function)))
    unread = set(texts)  # the names whose definitions' text is not yet in ``names``
    changed = True
    while changed and pending:
        changed = False
        named = unread.intersection(names)
        unread -= named
        for name in named:
            for definition in texts[name]:
                names |= _declarations(source, definition)
        left = []
        for function, (owner, own) in pending:
            if (owner is not None and owner not in names) or (
                    own is not None and own not in names):
                left.append((function, (owner, own)))
                continue
            kept.add(id(function))
            changed = True
            names |= _words(source, function)
        pending = left
    return [f for f in functions if id(f) in kept]
