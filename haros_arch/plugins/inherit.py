"""What a plugin class runs of its base classes' code.

A plugin class often leaves its setup to a base class of the workspace: nav2's
``KeepoutFilter`` derives from ``CostmapFilter``, whose ``onInitialize`` reads
``<name>.enabled`` and ``<name>.filter_info_topic`` for every filter, and that base is
compiled into another library (``nav2_costmap_2d_core``) than the filters. The class's
node takes the files of the libraries its library links that define members of its base
classes, transitively (``inherited_sources``); the calls of a base method that a more
derived class of the chain redefines, and does not call, are not the plugin's
(``overridden``: nav2's ``AsymmetricInflationLayer::onInitialize`` replaces
``InflationLayer``'s).

The classes are read from the text, as the rest of the build stage does: a declaration
``class Name : public Base`` in the class's files or the workspace headers they include,
and out-of-line member definitions ``Base::method(`` starting a line.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence

from ..model.source import Node, PrimitiveCall
from .classes import _MEMBER, Files, _untemplated, with_headers

MAX_BASE_DEPTH = 8  # base classes followed from a plugin class
HEADER_DEPTH = 2  # levels of includes read for a class's declaration
_ACCESS = frozenset({"public", "protected", "private", "virtual"})


def inherited_sources(cls: str, own: Sequence[str], candidates: Sequence[str],
                      workspace: Files) -> list[str]:
    """The ``candidates`` (not in ``own``) that define members of the base classes of
    ``cls``, its bases' bases and so on, in the order of ``candidates``."""
    defining = {source: {match.group(1) for match in _MEMBER.finditer(_text(source, workspace))}
                for source in candidates if source not in own}
    if not defining:
        return []
    files = list(own)
    chain(cls, files, workspace, defining)
    return [s for s in candidates if s in files and s not in own]


def chain(cls: str, files: list[str], workspace: Files,
          defining: dict[str, set[str]] | None = None) -> list[str]:
    """``cls`` and its base classes, most derived first (plain names), as the
    declarations in ``files`` and their headers give them; with ``defining`` (the
    classes whose members each other file defines), a base's defining files are read
    for its own bases and appended to ``files``."""
    out = [_plain(cls)]
    texts: dict[str, list[str]] = {}
    index = 0
    while index < len(out) and len(out) <= MAX_BASE_DEPTH:
        current = out[index]
        index += 1
        if defining is not None:
            files.extend(s for s, defined in defining.items()
                         if current in defined and s not in files)
        for source in files:
            if source not in texts:
                texts[source] = with_headers(source, workspace, HEADER_DEPTH)
        bases = _bases(current, [t for source in files for t in texts[source]])
        out.extend(b for b in bases if b not in out)
    return out


def overridden(node: Node, workspace: Files) -> list[tuple[str, int, int]]:
    """The spans (file, first line, last line) of the node's files that define a method
    of a base class of its plugin class which a more derived class of the chain
    redefines, unless the node's code calls that base method by name
    (``ObstacleLayer::onInitialize();`` in ``VoxelLayer::onInitialize``)."""
    if not node.plugin_class:
        return []
    bases = chain(node.plugin_class, list(node.sources), workspace)
    if len(bases) < 2:
        return []
    rank = {name: i for i, name in enumerate(bases)}
    spans: list[tuple[str, str, str, int, int]] = []
    texts = {source: _text(source, workspace) for source in node.sources}
    for source, text in texts.items():
        found = [(m.group(1), m.group(2), text.count("\n", 0, m.start()) + 1)
                 for m in _MEMBER.finditer(text)]
        last = text.count("\n") + 1
        for i, (cls, method, line) in enumerate(found):
            if cls in rank:
                end = found[i + 1][2] - 1 if i + 1 < len(found) else last
                spans.append((source, cls, method, line, end))
    defined = {(cls, method) for _, cls, method, _, _ in spans}
    headers = [t for source in node.sources for t in with_headers(source, workspace, 1)]
    defined |= {(cls, method) for cls in bases for method in _inline_methods(cls, headers)}
    out = []
    for source, cls, method, first, end in spans:
        derived = any((other, method) in defined for other in bases[:rank[cls]])
        if derived and not _called(cls, method, texts.values()):
            out.append((source, first, end))
    return out


def without_overridden(node: Node, calls: list[PrimitiveCall],
                       workspace: Files) -> list[PrimitiveCall]:
    """``calls`` but those made in a base method the plugin class redefines."""
    spans = overridden(node, workspace) if node.kind in ("plugin", "nodelet") else []
    if not spans:
        return calls
    return [c for c in calls if not any(
        c.location.file == f and first <= c.location.line <= end for f, first, end in spans)]


def _bases(cls: str, texts: list[str]) -> list[str]:
    """The base classes (plain names) a declaration ``class cls : ... {`` lists."""
    head = re.compile(r"\b(?:class|struct)\s+(?:\w+\s+)*?" + re.escape(cls)
                      + r"\s*(?:final\s*)?:(?!:)([^{;]*)\{")
    for text in texts:
        match = head.search(text)
        if match:
            out = []
            listed = match.group(1)
            for _ in range(MAX_BASE_DEPTH):  # template arguments, innermost first
                listed = re.sub(r"<[^<>]*>", "", listed)
            for part in listed.split(","):
                words = [w for w in part.split() if w not in _ACCESS]
                if words:
                    out.append(_plain(words[-1]))
            return out
    return []


# the head of a definition in a class body, up to its ``{``: ``void f(int x) const override``
_METHOD_HEAD = re.compile(r"(~?[A-Za-z_]\w*)\s*\([^{};]*\)[^{};()]*$")
MAX_CLASS_BODY = 200_000  # characters of a class body read for its inline methods


def _inline_methods(cls: str, texts: list[str]) -> set[str]:
    """The methods a class defines in its body (``void onInit() override { ... }``), from
    the first declaration of it in ``texts`` that has a body."""
    head = re.compile(r"\b(?:class|struct)\s+(?:\w+\s+)*?" + re.escape(cls)
                      + r"\b[^;{]*\{")
    for text in texts:
        match = head.search(text)
        if match is None:
            continue
        names: set[str] = set()
        depth, start = 1, match.end()
        end = min(len(text), match.end() + MAX_CLASS_BODY)
        for index in range(match.end(), end):
            char = text[index]
            if char == "{":
                if depth == 1:
                    found = _METHOD_HEAD.search(text[start:index])
                    if found:
                        names.add(found.group(1))
                depth += 1
            elif char == "}":
                depth -= 1
                if depth == 0:
                    break
                if depth == 1:
                    start = index + 1
            elif char in ";:" and depth == 1 and text[index:index + 2] != "::" and (
                    text[index - 1:index + 1] != "::"):
                start = index + 1  # a declaration ends, or an access label
        return names
    return set()


def _called(cls: str, method: str, texts: Iterable[str]) -> bool:
    """Whether an indented line of the texts calls ``cls::method(``."""
    call = re.compile(r"^[ \t]+.*\b" + re.escape(cls) + r"\s*::\s*" + re.escape(method)
                      + r"\s*\(", re.MULTILINE)
    return any(call.search(text) for text in texts)


def _plain(name: str) -> str:
    return _untemplated(name).rsplit("::", 1)[-1]


def _text(source: str, workspace: Files) -> str:
    return with_headers(source, workspace, 0)[0]
