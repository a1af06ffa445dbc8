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

import functools
import os
import re
from collections.abc import Callable, Iterable, Sequence

from ..files import read_text
from ..model.source import Node, PrimitiveCall
from .classes import (
    _MEMBER,
    Files,
    _untemplated,
    code_only,
    code_words,
    defined_in,
    derives_from,
    exported_classes,
    named_closure,
    node_classes,
    registered_class,
    remembered,
    uses_ros,
    with_headers,
)

MAX_BASE_DEPTH = 8  # base classes followed from a plugin class
HEADER_DEPTH = 2  # levels of includes read for a class's declaration
_ACCESS = frozenset({"public", "protected", "private", "virtual"})


def inherited_sources(cls: str, own: Sequence[str], candidates: Sequence[str],
                      workspace: Files,
                      elsewhere: Callable[[], list[list[str]]] | None = None) -> list[str]:
    """The ``candidates`` (not in ``own``) that define members of the base classes of
    ``cls``, its bases' bases and so on, in the order of ``candidates``; then, with
    ``elsewhere`` (the sources of other workspace packages' libraries that the class's
    library links, a list per package), those of them that do, with the helpers of their
    package that these name (``_helpers``). A file that defines a base class's members
    runs for the class even when it exports a plugin class of its own (forward_command_
    controller's ``ForwardCommandController``, which position_controllers' class
    derives from); the files that export only other classes are never taken."""
    groups = [[s for s in group if s not in own and s not in candidates]
              for group in (elsewhere() if elsewhere is not None else [])]
    defining = {source: _members(source, workspace)
                for source in [*candidates, *(s for group in groups for s in group)]
                if source not in own}
    if not defining:
        return []
    files = list(own)
    chain(cls, files, workspace, defining)
    out = [s for s in candidates if s in files and s not in own]
    for group in groups:
        found = [s for s in group if s in files]
        if found:
            # the base's own files, whatever they name (forward_command_controller.cpp
            # names no client library: its ParamListener declares the parameters); of
            # their helpers, a file that names none makes no call of the node
            out.extend([*found, *(s for s in _helpers(found, group, [*own, *out], workspace)
                                  if uses_ros(s, workspace))])
    return list(dict.fromkeys(out))


def _helpers(found: list[str], group: list[str], kept: list[str],
             workspace: Files) -> list[str]:
    """The files of ``group`` (one package's libraries) that the base-class files
    ``found`` there need, as an executable takes another package's (``cmake.nodes.
    _with_elsewhere``): those defining what they name, transitively, never one that
    exports classes or that is a node class of its own that the node does not derive
    from."""
    mine = [*kept, *found]
    words = code_words(found, workspace) - defined_in(mine, workspace)
    others = [s for s in group if s not in found
              and not exported_classes(os.path.join(workspace.root, s), workspace)
              and all(derives_from(c, mine, workspace) for c in node_classes(s, workspace))]
    return named_closure(words, others, workspace, anonymous=False)


def _members(source: str, workspace: Files) -> set[str]:
    """The classes whose members ``source`` defines out of line."""
    return remembered("members", source, workspace, lambda: {
        match.group(1) for match in _MEMBER.finditer(_text(source, workspace))})


def chain(cls: str, files: list[str], workspace: Files,
          defining: dict[str, set[str]] | None = None) -> list[str]:
    """``cls`` and its base classes, most derived first (plain names), as the
    declarations in ``files`` and their headers give them; with ``defining`` (the
    classes whose members each other file defines), a base's defining files are read
    for its own bases and appended to ``files``. A base written with its namespace
    (``forward_command_controller::ForwardCommandController``) is defined only by a
    file that opens that namespace or qualifies the class with it: another package's
    class of the same plain name is another class."""
    out = [_plain(cls)]
    spaces = {out[0]: _qualifier(cls)}
    texts: dict[str, list[str]] = {}
    index = 0
    while index < len(out) and len(out) <= MAX_BASE_DEPTH:
        current = out[index]
        index += 1
        if defining is not None:
            files.extend(s for s, defined in defining.items()
                         if current in defined and s not in files
                         and _in_namespace(s, spaces[current], current, workspace))
        for source in files:
            if source not in texts:
                texts[source] = with_headers(source, workspace, HEADER_DEPTH)
        for base in _bases(current, [t for source in files for t in texts[source]]):
            plain = _plain(base)
            if plain not in out:
                out.append(plain)
                spaces[plain] = _qualifier(base)
    return out


def direct_bases(cls: str, sources: Sequence[str], workspace: Files) -> list[str]:
    """The base classes the declaration of ``cls`` in ``sources`` (or the headers they
    include) lists, as written (``joint_trajectory_controller::JointTrajectoryController``)."""
    return _bases(_plain(cls), [text for source in sources
                                for text in with_headers(source, workspace, HEADER_DEPTH)])


def _qualifier(name: str) -> str | None:
    """The innermost namespace a class name is written with (``a::b::C``: ``b``)."""
    parts = [p.strip() for p in _untemplated(name).strip().lstrip(":").split("::")]
    return parts[-2] if len(parts) > 1 and parts[-2] else None


def _in_namespace(source: str, space: str | None, cls: str, workspace: Files) -> bool:
    """Whether ``source`` opens the namespace ``space`` (``namespace a::space``) or
    qualifies ``cls`` with it; any file when ``space`` is None."""
    if space is None:
        return True
    pattern = re.compile(rf"\bnamespace\s+(?:\w+\s*::\s*)*{re.escape(space)}\b"
                         rf"|\b{re.escape(space)}\s*::\s*{re.escape(cls)}\b")
    return pattern.search(_text(source, workspace)) is not None


def overridden(node: Node, workspace: Files) -> list[tuple[str, int, int]]:
    """The spans (file, first line, last line) of the node's files that define a method
    of a base class of its plugin class which a more derived class of the chain
    redefines, unless the node's code calls that base method by name
    (``ObstacleLayer::onInitialize();`` in ``VoxelLayer::onInitialize``)."""
    if not node.plugin_class:
        return []
    # the class the description's type is exported as (mavros' PluginFactoryTemplate<X>
    # stands for X, whose chain is X's bases, not the factory's)
    own = registered_class(node.plugin_class, node.sources, workspace)
    bases = chain(own, list(node.sources), workspace)
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

    def definer(start: str, method: str) -> str | None:
        """The class whose ``method`` ``start::method()`` runs: the first of the chain
        from ``start`` towards its bases that defines it."""
        return next((c for c in bases[rank[start]:] if (c, method) in defined), None)

    out = []
    for source, cls, method, first, end in spans:
        derived = any((other, method) in defined for other in bases[:rank[cls]])
        # called by its class, or through a class between that does not redefine it
        # (``ForwardCommandController::on_init()`` runs ForwardControllersBase's)
        called = any(_called(c, method, texts.values()) for c in bases[:rank[cls] + 1]
                     if definer(c, method) == cls)
        if derived and not called:
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


def without_other_classes(node: Node, calls: list[PrimitiveCall],
                          workspace: Files) -> list[PrimitiveCall]:
    """A plugin's (or nodelet's) ``calls`` but those made in a file of the workspace
    that defines other classes its sources export (a class body, or members out of
    line) and not its own, unless the definition of its own class names one of them (a
    base, a member; its code, not its comments): a library whose one file exports many
    classes that headers or other files of it define (laser_filters'
    ``laser_scan_filters.cpp``, ROS 1 and 2: its filters) gave every class's node all of
    their calls. Unchanged when its class's definition is not found in its sources or
    the headers they include."""
    if node.kind not in ("plugin", "nodelet") or not node.plugin_class:
        return calls
    # the class the description's type is exported as (mavros' factory template stands
    # for its argument), not the factory, which its sources' headers define
    own = _short(registered_class(node.plugin_class, node.sources, workspace))
    exported = {_short(name) for source in node.sources for name, _ in exported_classes(
        os.path.join(workspace.root, source), workspace)}
    others = exported - {own}
    if not others:
        return calls
    own_text = next((found for source in node.sources
                     for text in with_headers(source, workspace)
                     if (found := _class_text(code_only(text, literals=True), own))
                     is not None), None)
    if own_text is None:
        return calls
    named = {other for other in others if re.search(rf"\b{re.escape(other)}\b", own_text)}
    foreign: dict[str, bool] = {}

    def other_code(file: str | None) -> bool:
        if not file:
            return False
        if file not in foreign:
            path = os.path.join(workspace.root, file)
            text = read_text(path, workspace.location(file))[0] or ""
            # the classes the file defines: in a body, or members out of line
            defined = {cls for cls in (*others, own)
                       if _has_class(text, cls) or _has_members(text, cls)}
            foreign[file] = bool(defined & others) and own not in defined and not (
                defined & named)
        return foreign[file]

    return [c for c in calls if not other_code(c.location.file)]


def _short(cls: str) -> str:
    """A class's own name: ``laser_filters::LaserArrayFilter<T>`` is ``LaserArrayFilter``."""
    return _untemplated(cls.strip()).rsplit("::", 1)[-1]


def _class_head(cls: str) -> re.Pattern[str]:
    return re.compile(r"\b(?:class|struct)\s+(?:\w+\s+)*?" + re.escape(cls) + r"\b[^;{]*\{")


def _has_class(text: str, cls: str) -> bool:
    """Whether ``text`` holds a definition of the class named ``cls`` (a body, not a
    declaration)."""
    return _class_head(cls).search(text) is not None


def _has_members(text: str, cls: str) -> bool:
    """Whether ``text`` defines a member of the class named ``cls`` out of line
    (``bool ns::Cls::configure() {``, a namespace before it or not)."""
    return re.search(r"\b" + re.escape(cls) + r"\s*(?:<[^;{}()]*>)?\s*::\s*~?\w+\s*"
                     r"\([^;{}]*\)[^;{}()]*\{", text) is not None


def _class_text(text: str, cls: str) -> str | None:
    """The definition of the class ``cls`` in ``text`` (its head, bases and body, up to
    the brace that closes it), if ``text`` has one."""
    match = _class_head(cls).search(text)
    if match is None:
        return None
    depth, end = 1, match.end()
    limit = min(len(text), end + MAX_CLASS_BODY)
    while depth and end < limit:
        if text[end] == "{":
            depth += 1
        elif text[end] == "}":
            depth -= 1
        end += 1
    return text[match.start():end]


def _bases(cls: str, texts: list[str]) -> list[str]:
    """The base classes a declaration ``class cls : ... {`` lists, as written (without
    template arguments)."""
    for text in texts:
        found = _bases_in(cls, text) if cls in text else None  # (most texts name it nowhere)
        if found is not None:
            return list(found)
    return []


@functools.lru_cache(maxsize=4096)
def _bases_in(cls: str, text: str) -> tuple[str, ...] | None:
    """``_bases`` of one text: None when it declares no ``class cls : ... {``. Kept per
    class and text: every plugin of a family asks its bases' (nav2's costmap layers
    share ``CostmapLayer`` and ``Layer``)."""
    match = _head(cls).search(text)
    if match is None:
        return None
    out = []
    listed = match.group(1)
    for _ in range(MAX_BASE_DEPTH):  # template arguments, innermost first
        listed = re.sub(r"<[^<>]*>", "", listed)
    for part in listed.split(","):
        words = [w for w in part.split() if w not in _ACCESS]
        if words:
            out.append(words[-1])
    return tuple(out)


def base_argument(cls: str, base: str, sources: Sequence[str], workspace: Files) -> str | None:
    """The first template argument the declaration of ``cls`` in ``sources`` (or the
    headers they include) gives its base class ``base`` (``class Announce : public
    TimedBehavior<Action>``: ``Action``), as written; None when it gives none."""
    name = _plain(cls)
    for text in (text for source in sources
                 for text in with_headers(source, workspace, HEADER_DEPTH)):
        match = _head(name).search(text) if name in text else None
        if match is None:
            continue
        listed = match.group(1)
        written = re.search(rf"(?<![\w:]){re.escape(base.strip().lstrip(':'))}\s*<", listed)
        if written is None:
            return None
        depth, start = 0, written.end()
        for index in range(start, len(listed)):
            char = listed[index]
            if char in "<([":
                depth += 1
            elif char in ">)]" and depth:
                depth -= 1
            elif char in ">," and not depth:
                return listed[start:index].strip() or None
        return None
    return None


@functools.lru_cache(maxsize=256)
def _head(cls: str) -> re.Pattern[str]:
    """A declaration ``class cls : ... {``, its base list the group."""
    return re.compile(r"\b(?:class|struct)\s+(?:\w+\s+)*?" + re.escape(cls)
                      + r"\s*(?:final\s*)?:(?!:)([^{;]*)\{")


# the head of a definition in a class body, up to its ``{``: ``void f(int x) const override``
_METHOD_HEAD = re.compile(r"(~?[A-Za-z_]\w*)\s*\([^{};]*\)[^{};()]*$")
MAX_CLASS_BODY = 200_000  # characters of a class body read for its inline methods


def _inline_methods(cls: str, texts: list[str]) -> set[str]:
    """The methods a class defines in its body (``void onInit() override { ... }``), from
    the first declaration of it in ``texts`` that has a body."""
    for text in texts:
        found = _body_methods(cls, text)
        if found is not None:
            return set(found)
    return set()


# what changes the reading of a class body (``_body_methods``): braces, the end of a
# declaration and an access label's colon
_BODY_MARK = re.compile(r"[{};:]")


@functools.lru_cache(maxsize=4096)
def _body_methods(cls: str, text: str) -> frozenset[str] | None:
    """``_inline_methods`` of one text: None when it has no declaration of ``cls`` with
    a body. Kept per class and text (a family's plugins share their bases), and read
    from brace to brace: only the marks of ``_BODY_MARK`` change what is read."""
    match = _class_head(cls).search(text)
    if match is None:
        return None
    names: set[str] = set()
    depth, start = 1, match.end()
    end = min(len(text), match.end() + MAX_CLASS_BODY)
    # in a constructor's initialiser list (``Layer() : Base(), count_{0} {}``): its
    # name is read at the colon, and a brace there is a member's initialiser until
    # the one that opens the body (after a ``)``, a ``}`` or nothing)
    initialising = False
    for mark in _BODY_MARK.finditer(text, match.end(), end):
        index = mark.start()
        char = text[index]
        if char == "{":
            if depth == 1:
                before = text[start:index]
                if initialising:
                    written = before.rstrip()
                    initialising = bool(written) and written[-1] not in ")}"
                else:
                    found = _METHOD_HEAD.search(before)
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
            if char == ":" and not initialising:
                found = _METHOD_HEAD.search(text[start:index])
                if found and found.group(1) == cls:  # the constructor's list begins
                    names.add(cls)
                    initialising = True
            elif char == ";":
                initialising = False
            start = index + 1  # a declaration ends, or an access label
    return frozenset(names)


@functools.lru_cache(maxsize=4096)
def _call_pattern(cls: str, method: str) -> re.Pattern[str]:
    """``cls::method(`` (``_called``), compiled once per pair: a run asks more pairs than
    the ``re`` module keeps compiled."""
    return re.compile(r"\b" + re.escape(cls) + r"\s*::\s*" + re.escape(method) + r"\s*\(")


def _called(cls: str, method: str, texts: Iterable[str]) -> bool:
    """Whether an indented line of the texts calls ``cls::method(``. Each place the
    class's name is written is found by a plain text search, then the call is matched
    there and its line's indentation looked at: a pattern anchored at every line's start
    costs a backtracking scan of each line, and one that starts with ``\\b`` is tried at
    every character."""
    call = _call_pattern(cls, method)
    for text in texts:
        if method not in text:
            continue
        at = text.find(cls)
        while at >= 0:
            if call.match(text, at) is not None:
                start = text.rfind("\n", 0, at) + 1
                if start < at and text[start] in " \t":
                    return True
            at = text.find(cls, at + 1)
    return False


def _plain(name: str) -> str:
    return _untemplated(name).rsplit("::", 1)[-1]


def _text(source: str, workspace: Files) -> str:
    return with_headers(source, workspace, 0)[0]


MAX_BUILT_ROUNDS = 8  # classes built by classes built by the plugin, and so on


def built_sources(own: Sequence[str], workspace: Files,
                  elsewhere: Callable[[], list[list[str]]] | None = None) -> list[str]:
    """The sources of other workspace packages' libraries (``elsewhere``, a list per
    package) that define members of a class the code of ``own`` builds (``_built``: an
    object of it held by value, a member or a local, or made by ``new`` /
    ``make_shared`` / ``make_unique``), and of the bases of such a class; then what
    those build in turn. The object's constructor and methods run in the plugin, on its
    node and with the names it gives them: dwa_local_planner's ``DWAPlannerROS`` holds
    base_local_planner's ``OdometryHelperRos`` (which subscribes to ``odom``),
    ``LatchedStopRotateController`` and ``MapGridVisualizer`` as members. A class the
    code is only given, by pointer or reference, is not: move_base hands every planner
    the ``Costmap2DROS`` it built, whose calls are move_base's, not the planner's. Not a
    file that defines a class which is a node of its own (a ROS 2 node class: its calls
    are that node's); a file that names no ROS client library is followed for what it
    builds, not kept (it makes no call)."""
    groups = [[s for s in group if s not in own]
              for group in (elsewhere() if elsewhere is not None else [])]
    defining = {source: _defines(source, workspace)
                for group in groups for source in group}
    defining = {source: classes for source, classes in defining.items()
                if classes and not node_classes(source, workspace)}
    if not defining:
        return []
    files = list(own)
    # a class the plugin's own sources define is the one its code names unqualified
    # (nav2's RotationShimController builds its own ParameterHandler, not
    # nav2_controller's class of that name)
    mine = {cls for source in own for cls in _defines(source, workspace)}
    scanned: set[str] = set()
    for _ in range(MAX_BUILT_ROUNDS):
        texts = [code_only(text, literals=True) for source in files if source not in scanned
                 for text in with_headers(source, workspace, HEADER_DEPTH)]
        scanned.update(files)
        classes = {cls for found in defining.values() for cls in found}
        added = False
        # by name: the order of a set of strings changes from one run to the next
        for cls, space in sorted(_built(classes, texts), key=lambda b: (b[0], b[1] or "")):
            if space is None and cls in mine:
                continue
            before = len(files)
            files.extend(s for s, defined in defining.items()
                         if cls in defined and s not in files
                         and _in_namespace(s, space, cls, workspace))
            if len(files) > before:
                chain(cls if space is None else f"{space}::{cls}", files, workspace,
                      defining)
                added = True
        if not added:
            break
    return [s for s in files if s not in own and uses_ros(s, workspace)]


# a class built by a text (code, comments blanked): ``new ns::C(...)``,
# ``make_shared<ns::C>(...)``, or ``ns::C name;`` / ``ns::C name(args);`` / ``ns::C name =
# ...;`` starting a line (a member or a local held by value, not ``ns::C* p``,
# ``ns::C& r``); the class itself, not a type nested in it (``make_shared<SpinAction::
# Feedback>`` builds a Feedback, whichever SpinAction qualifies it). Any name matches here
# and ``_built`` keeps the classes asked for: one pattern for every call, where an
# alternation of the names asked was compiled for each and tried at every line
_QUALIFIED = r"(?:::)?((?:\w+\s*::\s*)*)([A-Za-z_]\w*)\b(?!\s*::)"
_BUILT = re.compile(
    rf"\bnew\s+{_QUALIFIED}|\bmake_(?:shared|unique)\s*<\s*{_QUALIFIED}"
    rf"|^[ \t]*(?:(?:static|mutable|const)\s+)*{_QUALIFIED}\s*(?:<[^;{{}}()]*>)?\s+"
    rf"(?!const\b|operator\b)[A-Za-z_]\w*\s*[;({{=\[]", re.MULTILINE)


def _built(classes: set[str], texts: list[str]) -> set[tuple[str, str | None]]:
    """The classes of ``classes`` that ``texts`` (code, comments blanked) build, each
    with the namespace it is written with (None when unqualified)."""
    if not classes:
        return set()
    return {built for text in texts for built in _built_in(text) if built[0] in classes}


@functools.lru_cache(maxsize=256)
def _built_in(text: str) -> frozenset[tuple[str, str | None]]:
    """Every name ``_BUILT`` finds built in ``text``, with its namespace (a package's
    sources are asked again for each class set: once per text)."""
    found: set[tuple[str, str | None]] = set()
    for match in _BUILT.finditer(text):
        groups = match.groups()
        for index in range(0, len(groups), 2):
            if groups[index + 1]:
                found.add((groups[index + 1], _qualifier(groups[index] + groups[index + 1])))
    return frozenset(found)


# ``C::member(params) const {`` (``C::C(params) : initialisers {`` for a constructor) at
# the start of a line after its indentation and return type: a member of ``C`` defined,
# indented or not (navigation's files define their classes' members inside an indented
# ``namespace`` block); a call ``C::f(x);`` ends without a body, and one inside an
# expression (``v = c ? Eigen::Vector3d::Zero() : w; if (x) {``) starts no line; the
# class may be written with its namespaces (MoveIt's ``ompl_interface::OMPLInterface::
# OMPLInterface(...)``, outside any ``namespace`` block)
_DEFINITION = re.compile(r"^[ \t]*(?:(?!return\b)[\w:<>,*&]+[ \t]+[*&]*)*?[*&]*"
                         r"\b(?:\w+\s*::\s*)*"
                         r"([A-Za-z_]\w*)\s*(?:<[^;{}()<>]*>)?\s*::\s*(~?\w+)\s*"
                         r"\([^;{}]*\)\s*(?:const\b\s*)?(?:noexcept\b\s*)?"
                         r"(:(?!:)[^;{]*)?\{", re.MULTILINE)


def _defines(source: str, workspace: Files) -> set[str]:
    """The classes whose members ``source`` defines out of line (its code, comments
    blanked)."""
    def read() -> set[str]:
        found = set()
        for match in _DEFINITION.finditer(code_only(_text(source, workspace), literals=True)):
            cls, member, initialisers = match.groups()
            if initialisers is None or member == cls:
                found.add(cls)
        return found

    return remembered("defines", source, workspace, read)
