"""Whether the errors left in a translation unit can hide a ROS call: the reasons a node
is ``partial``.

A clang error matters only where it can cost a call. Two checks say where, each reason
with its file:line:

- a *missed call site*: a line where a grep finds a call of a ROS API function (a
  member call ``nh.subscribe(``, ``->create_publisher<``, an rclcpp method called bare
  in a node class, ``rclcpp_action::create_server<``) or of one of the unit's own
  wrappers, with no call extracted within ``NEAR`` lines of it (a class an error made
  invalid, code in a template the walk does not reach);
- an *error near a call*: an error inside a function whose text holds such a call site
  (the call may be extracted with a wrong name or type, or not at all).

A third check is about the node, not a call site: an error that names something the
parse does not know (an undeclared identifier, a namespace's unknown member or
template, an unknown type) on a statement that passes the node as an argument
(``node_given``): the node goes to code nobody reads (a vendor library's parameter
getter), which may make ROS calls on it.

Errors anywhere else (a vendor type in a function that makes no ROS call, a field of a
message known only by name) cannot hide a call; they stay information. The files read
are the unit's own source and the workspace headers it includes that hold an error.
The same grep is the recall check ``models build`` runs on a package's sources.
"""

from __future__ import annotations

import ctypes
import functools
import os
import re
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

from clang.cindex import (
    Cursor,
    CursorKind,
    LibclangError,
    SourceRange,
    TranslationUnit,
    conf,
)

from ...ctext import closing, function_macros
from . import api, synthesis
from .cursors import by_file, line_of, visit_children

__all__ = ["NEAR", "Function", "Site", "call_sites", "holding", "missed", "site_pattern"]

NEAR = 2  # lines between a call site and the extracted call it is taken to be
MAX_REASONS = 20  # per unit


# a line that defines a function of the API's name: ``Type Class::create_publisher(``
_DEFINITION = re.compile(r"^\s*(?:[\w:<>,*&]+\s+)+[*&]*\s*(?:\w+::)+\w+\s*\(")
# a line that declares or defines a function (or a method in its class) of a bare name:
# ``static std::string set_parameter(`` (flir's spinnaker_wrapper_impl.cpp, a GenICam
# helper); types and specifiers only before the name, no statement keyword
# (``return set_parameter(`` is a call)
_FREE_DEFINITION = re.compile(
    r"^\s*(?:(?!(?:return|throw|else|case|co_return|co_yield|co_await|new|delete|goto|do)"
    r"\b)[\w:<>,*&]+\s+)+[*&]*\s*(?P<name>\w+)\s*\(")


# an explicit instantiation (``template void Parameters::setParamT<bool>(...);``,
# ``extern template ...``): ``template`` opening the line, with no parameter list after
# it, declares the function for those arguments and calls nothing
# (a type then a name: ``template create_publisher<T>(`` alone on a line is a member call
# going on from the line before)
_INSTANTIATION = re.compile(
    r"^\s*(?:extern\s+)?template\s+(?:(?:class|struct)\b|[\w:<>,*&]+\s+[*&]*\s*[\w:~]+)")
# a line that declares or defines an explicit specialisation of a member template, its
# ``template <>`` on the line before (mrs_lib's param_loader.h: ``ros::Duration
# ParamLoader::loadParam2<ros::Duration>(const std::string& name);``): a return type, the
# qualified name, its template arguments and the parameter list; no statement keyword
# (``return ParamLoader::loadParam2<double>(name);`` is a call)
_SPECIALISATION = re.compile(
    r"^\s*(?:(?!(?:return|throw|else|case|co_return|co_yield|co_await|new|delete|goto|do)"
    r"\b)[\w:<>,*&]+\s+)+[*&]*\s*(?:\w+::)+\w+\s*<[^;{}()]*>\s*\(")


@dataclass(frozen=True)
class Site:
    """A line of source where a grep finds a ROS API call."""

    line: int
    text: str


@functools.lru_cache(maxsize=8)
def site_pattern(extra: frozenset[str] = frozenset(), ros2: bool | None = None
                 ) -> re.Pattern[str]:
    """The grep for API call sites: every method of the API tables (longer than four
    letters, so ``get`` / ``set`` / ``call`` of other classes do not count) as a member
    call; rclcpp's ``snake_case`` methods also bare (``create_publisher<T>(`` in a node
    class) and with their namespace (``rclcpp_action::create_server<``); ``extra`` names
    (a unit's wrappers) as member or bare calls. ``ros2``: the unit's code is ROS 2, whose
    code cannot call an API of ROS 1 only (``api.ROS1_ONLY``): ublox's ROS 2 driver calls
    asio's ``resolver.resolve(query)``, no ``tf::TransformListener::resolve``; nor ROS 1
    code (``ros2`` False) an API of ROS 2 only (``api.ROS2_ONLY``): ORK's renderer calls
    its own ``renderer.set_parameters(...)``, no ``rclcpp::Node::set_parameters``."""
    # a method of a class (``ros::NodeHandle``) is called on an object; a function of a
    # namespace (``ros::param::search``, ``ros::service::exists``) is not, and ``.search(``
    # on any other object is no call of it: it is found written with its namespace
    rows = {key: row for key, row in api.ALL.items()
            if not (ros2 and key[0].split("::", 1)[0] in api.ROS1_ONLY)
            and not (ros2 is False and key[0].split("::", 1)[0] in api.ROS2_ONLY)}
    names = {name for (owner, name), row in rows.items() if name[:1].islower()
             and len(name) > 4 and _is_class(owner) and row.call_site}
    scoped = {f"{owner.rsplit('::', 1)[-1]}::{name}" for owner, name in rows
              if name[:1].islower() and not _is_class(owner)}
    bare = {name for name in names if "_" in name} | set(extra)
    member = "|".join(sorted(map(re.escape, names | set(extra)), key=len, reverse=True))
    free = "|".join(sorted(map(re.escape, bare | scoped), key=len, reverse=True))
    # the API's classes whose construction is the call, written qualified, made with a
    # factory or new (``make_unique<message_filters::Subscriber<M, Node>>(``)
    made = "|".join(sorted((re.escape(owner) for owner, name in rows
                            if "::" in owner and owner.rsplit("::", 1)[1] == name),
                           key=len, reverse=True))
    # (a template's ``<``, not a shift or comparison: ``<< options.param << ":"``)
    return re.compile(rf"(?:(?:\.|->)\s*(?:template\s+)?(?P<member>{member})"
                      rf"|(?<![\w.>:~])(?:\w+::)?(?P<bare>{free}))\s*(?:\(|<(?![<=]))"
                      rf"|(?:make_shared|make_unique)\s*<\s*(?:::)?(?:{made})\s*[<>(]"
                      rf"|\bnew\s+(?:::)?(?:{made})\s*[<(]")


def _is_class(owner: str) -> bool:
    """Whether an API row's owner is a class (``ros::NodeHandle``, ``rclcpp::Node``), not a
    namespace (``ros::param``, ``rclcpp``, ``image_transport``): ROS names its classes
    in CamelCase and its namespaces in lowercase."""
    return owner.rsplit("::", 1)[-1][:1].isupper()


# a line of the preprocessor's conditionals: the directive and the rest of the line
DIRECTIVE = re.compile(r"^\s*#\s*(if|ifdef|ifndef|elif|else|endif)\b(.*)$")


def first_site(sites: Sequence[Site], first: int, last: int) -> Site | None:
    """The first of ``sites`` strictly between lines ``first`` and ``last`` (a
    conditional block's directive lines)."""
    return next((s for s in sites if first < s.line < last), None)


def call_sites(text: str, extra: Iterable[str] = (), bare: Iterable[str] = (),
               ros2: bool | None = None, qualifiers: Iterable[tuple[str, str]] = ()
               ) -> list[Site]:
    """The API call sites of one file's text (comments left out, and lines that define
    a function of the same name: ``Node::create_publisher(``, or declare one:
    ``static std::string set_parameter(``). ``extra`` are the unit's wrappers, and
    ``bare`` those of them a call with no argument may be: a call of another one is a
    site only with an argument or template arguments, and never written in ``std::``
    (``ptr.get()``, ``std::get<I>(t)`` where the unit has a wrapper ``get(node,
    name)``). The headers of a package are read by each of its units: the sites of a
    text are kept (a few texts). ``ros2``: the code is ROS 2 (``site_pattern``); None
    when not known. ``qualifiers``: (name, namespace) for the namespaces a call of a
    wrapper of ``extra`` that is a free function may be qualified with, and (name, "")
    where every wrapper of the name is one (``Wrappers.site_qualifiers``)."""
    return list(_call_sites(text, frozenset(extra), frozenset(bare), ros2,
                            frozenset(qualifiers)))


@functools.lru_cache(maxsize=64)
def _call_sites(text: str, extra: frozenset[str], bare: frozenset[str],
                ros2: bool | None = None,
                qualifiers: frozenset[tuple[str, str]] = frozenset()) -> tuple[Site, ...]:
    pattern = site_pattern(extra, ros2)
    found = []
    for number, shown, code, named in _code_lines(text):
        if any(not _unevaluated(code, m.start()) and not _named_type(code, m, extra)
               and m.start("bare") != named
               and not _not_a_wrapper(code, m, extra, bare, qualifiers)
               and not _constructor_declared(code, m, extra)
               for m in pattern.finditer(code)):
            found.append(Site(number, shown.strip()[:80]))
    return tuple(found)


@functools.lru_cache(maxsize=256)
def _code_lines(text: str) -> tuple[tuple[int, str, str, int | None], ...]:
    """The lines of ``text`` that may hold a call site, whatever the unit's wrappers
    (``_call_sites``: each unit of a package asks of the same headers with its own):
    (number, the line without its comments, that with its literals masked, where a free
    function's name it defines starts); not a directive's, nor one that defines or
    instantiates a function of the API's name."""
    found = []
    in_comment = False
    for number, line in enumerate(text.splitlines(), 1):
        if in_comment:
            if "*/" not in line:
                continue
            line, in_comment = line.split("*/", 1)[1], False
        while "/*" in line:
            head, _, tail = line.partition("/*")
            if "*/" in tail:
                line = head + " " + tail.split("*/", 1)[1]
            else:
                line, in_comment = head, True
        shown = line.split("//", 1)[0]
        # what a string or character literal holds is no call: the message of moveit's
        # ``RCLCPP_FATAL_STREAM(logger_, "requestPlanningSceneState() to self-provided
        # service")`` names a wrapper of the unit
        code = _masked(shown)
        if code.lstrip().startswith("#") or _DEFINITION.match(code) or (
                _INSTANTIATION.match(code)) or _SPECIALISATION.match(code):
            continue
        declared = _FREE_DEFINITION.match(code)
        found.append((number, shown, code,
                      declared.start("name") if declared is not None else None))
    return tuple(found)


def _masked(code: str) -> str:
    """``code`` with what its string and character literals hold blanked (their quotes
    kept, the length the same); a quote between a digit and another digit or letter is
    C++14's digit separator (``1'000``), no literal."""
    out = list(code)
    quote = ""
    escaped = False
    for i, char in enumerate(code):
        if quote:
            if escaped:
                escaped = False
            elif char == "\\":
                escaped = True
            elif char == quote:
                quote = ""
                continue
            out[i] = " "
        elif char == '"' or (char == "'" and not (i and code[i - 1].isalnum())):
            quote = char
    return "".join(out)


# what comes before a class name that is made there (``std::make_shared<``, ``new``),
# and before one that is a base class (``class C : public Wrapper<T> {``)
_MADE_AFTER = re.compile(r"(?:\b(?:make_shared|make_unique)\s*<|\bnew)\s*(?:::)?(?:\w+::)?$")
_BASE_AFTER = re.compile(r"\b(?:public|protected|private)\s+(?:virtual\s+)?(?:\w+::)?$")
# what follows its template arguments where it is built: ``(`` / ``{`` (a temporary, a
# base or member initialiser), a variable with its arguments (``Wrapper<T> w(...)``), a
# static factory (``Wrapper<T>::make(``)
_BUILT_BEFORE = re.compile(r"\s*(?:[({]|\w+\s*[({]|::\s*\w+\s*\()")


def _named_type(code: str, match: re.Match[str], extra: frozenset[str]) -> bool:
    """Whether ``match`` is one of the unit's wrappers (``extra``), a class template,
    written as a type, not built: ``using P = std::shared_ptr<nav2::ServiceClient<T>>``,
    a member's type ``ServiceClient<T>::SharedPtr client_;``, a base class. It is built
    after ``make_shared<`` / ``new`` or where its closed template arguments are
    followed by ``(`` or ``{`` (``_BUILT_BEFORE``); with the arguments not closed on the
    line, it may be either: a call site."""
    name = match.group("bare")
    if name is None or name not in extra or not match.group(0).endswith("<"):
        return False
    before = code[:match.start("bare")]
    if _BASE_AFTER.search(before):
        return True
    if _MADE_AFTER.search(before):
        return False
    depth, at = 0, match.end() - 1
    for at in range(match.end() - 1, len(code)):
        depth += {"<": 1, ">": -1}.get(code[at], 0)
        if depth == 0:
            break
    else:
        return False  # the template arguments go on past the line
    rest = code[at + 1:]
    member = _MEMBER_AFTER.match(rest)
    if member is not None and (member.group(1).lstrip("~") == name or (
            _TYPE_BEFORE.search(before) and not _KEYWORD_BEFORE.search(before))):
        # a member of the class template defined out of it, not a static factory's
        # call: its constructor, ``Wrapper<T>::Wrapper(``, or a method after its return
        # type, ``void Wrapper<T>::start(`` (depthai_bridge's BridgePublisher.hpp)
        return True
    return bool(rest.strip()) and not _BUILT_BEFORE.match(rest)


# a member named after a class's template arguments: ``::name(``
_MEMBER_AFTER = re.compile(r"\s*::\s*(~?\w+)\s*\(")
# a return type ends just before the class's name (a name, ``>``, ``*``, ``&``), a
# statement keyword does not
_TYPE_BEFORE = re.compile(r"[\w>*&]\s+$")
_KEYWORD_BEFORE = re.compile(r"\b(?:return|co_return|throw|else|case|do)\s+$")
# a constructor's declaration in its class, with no return type: the name opens the line
# (after ``explicit`` / ``inline`` / ``constexpr``), and its first parameter declares a
# name after its type (``BridgePublisher(std::shared_ptr<Queue> queue,``,
# ``BridgePublisher(const BridgePublisher& other);``), which no call's argument does
_DECLARATION_START = re.compile(r"^\s*(?:(?:explicit|inline|constexpr)\s+)*$")
_FIRST_PARAMETER = re.compile(
    r"\s*(?:const\s+)?(?:typename\s+)?[\w:]+(?:<[^()]*>)?(?:\s*[*&]+\s*|\s+)\w+\s*[,)=]")


def _constructor_declared(code: str, match: re.Match[str], extra: frozenset[str]) -> bool:
    """Whether ``match``, one of the unit's wrappers (``extra``) called bare, is a
    constructor's declaration in its class (``_DECLARATION_START``, ``_FIRST_PARAMETER``):
    a class template's constructor is a wrapper, and its class declares it."""
    name = match.group("bare")
    if name is None or name not in extra or not match.group(0).endswith("("):
        return False
    return bool(_DECLARATION_START.match(code[:match.start("bare")])) and bool(
        _FIRST_PARAMETER.match(code, match.end()))


_EMPTY_CALL = re.compile(r"\(\s*\)")


def _not_a_wrapper(code: str, match: re.Match[str], extra: frozenset[str],
                   bare: frozenset[str],
                   qualifiers: frozenset[tuple[str, str]] = frozenset()) -> bool:
    """Whether ``match``, a call of a name that only the unit's wrappers (``extra``)
    have, cannot be one of theirs: written in ``std::``, or qualified by a class or a
    namespace none of them is in where each is a free function (``qualifiers``:
    ``TypeGuard::create<T>()`` beside ros_canopen's ``canopen::create(nh, name, ...)``),
    or with no argument where no wrapper of that name can be called so (not in
    ``bare``)."""
    name = match.group("bare") or match.group("member")
    if name is None or name not in extra or site_pattern().match(code, match.start()):
        return False  # (a call the API's own grep finds there too)
    if match.group("bare") is not None and code[:match.start("bare")].endswith("std::"):
        return True
    qualifier = _QUALIFIER.search(code[:match.start("bare")]) if (
        match.group("bare") is not None and (name, "") in qualifiers) else None
    if qualifier is not None and (name, qualifier.group(1)) not in qualifiers:
        return True
    return match.group(0).endswith("(") and name not in bare and bool(
        _EMPTY_CALL.match(code, match.end() - 1))


# the class or namespace a name is qualified with (``X::``; ``X<T>::`` as ``>``)
_QUALIFIER = re.compile(r"(\w+|>)\s*::\s*$")
_UNEVALUATED = re.compile(r"\b(?:decltype|sizeof|alignof|noexcept)\s*\(")


def _unevaluated(code: str, at: int) -> bool:
    """Whether position ``at`` of a line is inside an operand that is never evaluated
    (``decltype(std::declval<NodeT &>().create_publisher<M>(...))`` names a type: no
    call is made there)."""
    for opening in _UNEVALUATED.finditer(code, 0, at):
        if code.count("(", opening.end(), at) >= code.count(")", opening.end(), at):
            return True
    return False


def missed(sites: Sequence[Site], lines: set[int], silent: Sequence[tuple[int, int]]
           ) -> list[Site]:
    """The sites with no extracted call (``lines``) within ``NEAR`` lines, outside the
    line ranges ``silent`` (wrappers: their calls are emitted where they are called)."""
    return [site for site in sites
            if not any(n in lines for n in range(site.line - NEAR, site.line + NEAR + 1))
            and not any(start <= site.line <= end for start, end in silent)]


# first line, last line, name, and whether none of its unqualified names can be a member
# of a base class: a free function, or a method of a class (not a template) that, like
# every class around it, derives from nothing (darknet_ros' YoloObjectDetector calls
# ``XOpenDisplay(NULL)`` of the missing <X11/Xlib.h> in a method: no base can hold it)
# a function's first and last lines, name, and what its class is: FREE (a function, or
# a method of a class without bases), BASES_READ (``_bases_all_read``), else 0
Function = tuple[int, int, str, int]
FREE, BASES_READ = 1, 2
_FREE = CursorKind.FUNCTION_DECL.value
_PLAIN_CLASSES = frozenset({CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL})


def _in(cursor: Cursor, tu: TranslationUnit) -> Cursor:
    """A cursor a visit of ``visit_children`` gives, with its unit (for its parents)."""
    cursor._tu = tu
    return cursor


def _derives(cls: Cursor) -> bool:
    """Whether class ``cls`` names a base: a base specifier, or a ``:`` before its body
    in its text (a base the parse does not know, ``class Gradient : public
    vendor::Layer`` of a missing header, is no base specifier of the parse's class)."""
    if any(child.kind == CursorKind.CXX_BASE_SPECIFIER for child in cls.get_children()):
        return True
    for token in cls.get_tokens():
        if token.spelling in ("{", ";"):
            return False
        if token.spelling == ":":
            return True
    return False


def _without_bases(function: Cursor) -> bool:
    """Whether ``function`` is a method of a class that is no template and, as every
    class it is nested in, has no base class."""
    return _owners_all(function, lambda owner: not _derives(owner))


def _bases_all_read(function: Cursor) -> bool:
    """Whether ``function`` is a method of a class that is no template and, as every
    class it is nested in, has only bases the parse reads whole (``_bases_read``): a
    name it cannot find there is no member of a base it does not know."""
    return _owners_all(function, lambda owner: _bases_read(owner, 0))


def _owners_all(function: Cursor, judge: Callable[[Cursor], bool]) -> bool:
    owner = function.semantic_parent
    if owner is None or owner.kind not in _PLAIN_CLASSES:
        return False
    while owner is not None and owner.kind in _PLAIN_CLASSES:
        if not judge(owner.get_definition() or owner):
            return False
        owner = owner.semantic_parent
    return owner is None or owner.kind in (CursorKind.NAMESPACE, CursorKind.TRANSLATION_UNIT)


MAX_BASE_DEPTH = 8  # how deep a class's bases are followed (``_bases_read``)


def _bases_read(cls: Cursor, depth: int) -> bool:
    """Whether every base of class ``cls``, and of each of those in turn, is a class the
    parse reads a definition of: one no template and not of the names declared
    permissively (ros_phoenix's PhoenixManager, whose only base is rclcpp_components'
    ComponentManager); not when its text names a base the parse dropped (a base of a
    missing header, ``class Gradient : public vendor::Layer``, is no base specifier)."""
    bases = [c for c in cls.get_children() if c.kind == CursorKind.CXX_BASE_SPECIFIER]
    if not bases:
        return not _derives(cls)
    if depth >= MAX_BASE_DEPTH or len(bases) != _bases_written(cls):
        return False
    for base in bases:
        declared = base.type.get_declaration()
        found = declared.get_definition() if declared is not None else None
        if found is None or found.kind not in _PLAIN_CLASSES or found.location.file is None \
                or os.path.basename(found.location.file.name) == synthesis.HEADER_NAME \
                or not _bases_read(found, depth + 1):
            return False
    return True


def _bases_written(cls: Cursor) -> int:
    """How many bases the head of class ``cls`` writes (the commas between ``:`` and its
    body outside template argument lists and parentheses, plus one)."""
    count, depth, after = 0, 0, False
    for token in cls.get_tokens():
        spelling = token.spelling
        if spelling == "{" and depth == 0:
            break
        if spelling == ":" and depth == 0 and not after:
            after, count = True, 1
        elif spelling in ("<", "("):
            depth += 1
        elif spelling in (">", ")"):
            depth -= 1
        elif spelling == ">>":
            depth -= 2
        elif spelling == "," and depth == 0 and after:
            count += 1
    return count


def holding(line: int, functions: Iterable[Function], sites: Sequence[Site]
            ) -> Function | None:
    """The innermost function around ``line`` that holds a call site."""
    around = [f for f in functions if f[0] <= line <= f[1]]
    for function in sorted(around, key=lambda f: f[1] - f[0]):
        if any(function[0] <= site.line <= function[1] for site in sites):
            return function
    return None


STATEMENT_LINES = 6  # how far a statement is read from the line it starts on


def _statement(lines: Sequence[str], start: int) -> list[str]:
    """The lines of the statement that starts on line ``start`` (1-based) of ``lines``:
    to the one that holds its ``;``, at most ``STATEMENT_LINES``."""
    found: list[str] = []
    for text in lines[start - 1:start - 1 + STATEMENT_LINES]:
        found.append(text)
        if ";" in text:
            break
    return found


def in_call(lines: Sequence[str], sites: Sequence[Site], line: int) -> bool:
    """Whether ``line`` is in the statement (``_statement``) of one of the call ``sites``
    of the file of ``lines``."""
    return any(s.line <= line < s.line + len(_statement(lines, s.line)) for s in sites
               if s.line <= line < s.line + STATEMENT_LINES)


# a logging macro of roscpp / rosconsole, rclcpp, rcutils or nodelet (``ROS_INFO``,
# ``ROS_WARN_STREAM_THROTTLE``, ``RCLCPP_ERROR_ONCE``, ``RCUTILS_LOG_INFO_NAMED``,
# ``NODELET_DEBUG``), to its opening parenthesis: a statement that writes a message
_LOG_MACRO = re.compile(
    rb"\b(?:ROS|RCLCPP|RCUTILS_LOG|NODELET)_(?:DEBUG|INFO|WARN|ERROR|FATAL)(?:_[A-Z_]+)?"
    rb"\s*\(")
LOG_STATEMENT_BYTES = 4096  # how far the end of one is looked for


@functools.lru_cache(maxsize=64)
def log_statements(data: bytes) -> tuple[tuple[int, int], ...]:
    """The logging macro invocations of a file's bytes (``_LOG_MACRO``), each as the
    offsets of its name and just past its closing parenthesis."""
    found = []
    for match in _LOG_MACRO.finditer(data):
        close = closing(data, match.end() - 1, LOG_STATEMENT_BYTES, literals=True)
        if close is not None:
            found.append((match.start(), close + 1))
    return tuple(found)


# clang's messages for a name it does not know, the name in the group ``name`` (or
# ``scope``: a name found, but not as the namespace or class written before ``::``, a
# local variable named after the namespace of a missing header, ``auto raspimouse =
# std::make_shared<raspimouse::Raspimouse>(options)``, where C++ looks that name up
# among namespaces and types only)
UNKNOWN_NAME = re.compile(r"(?:use of undeclared identifier '|no member named '[^']*' in "
                          r"namespace '|no template named '|unknown type name ')(?P<name>[^']*)"
                          r"|^'(?P<scope>\w+)' is not a class, namespace, or enumeration")


def node_given(lines: Sequence[str], line: int, names: Iterable[str]) -> str | None:
    """Whether the statement of the file of ``lines`` that starts on ``line`` (read to
    its ``;``: ``_statement``) passes one of ``names`` (the words that name the node
    there: ``owners.node_names``) as an argument: ``f(node, ...)``, ``T x{*this}``,
    ``g(a, node->get_node_parameters_interface())``, ``h(shared_from_this())``: the
    argument as written (``*this``), or None."""
    words = sorted(names)
    if not words:
        return None
    statement = "\n".join(_statement(lines, line))
    end = statement.find(";")
    if end >= 0:
        statement = statement[:end]
    found = _given(tuple(words)).search(statement)
    if found is None:  # a macro of the file the statement invokes: what it expands to
        macro = re.match(r"\s*(?:if\s*\(\s*!?\s*)?(\w+)\s*\(", statement)
        body = _macro_body(lines, macro.group(1)) if macro is not None else None
        found = _given(tuple(words)).search(body) if body is not None else None
    return found.group(1) if found is not None else None


def assigns_to(lines: Sequence[str], line: int, name: str) -> bool:
    """Whether the statement of the file of ``lines`` that starts on ``line`` assigns
    to ``name`` (``name = ...``): the name then receives what the
    right side makes, not the node or the options an argument there passes (tf2_ros'
    ``optional_default_node_ = rclcpp::Node::make_shared("_", options)``, a member the
    parse does not know, is no call given the options)."""
    statement = "\n".join(_statement(lines, line))
    return re.match(r"\s*" + re.escape(name) + r"\s*=(?!=)", statement) is not None


def _macro_body(lines: Sequence[str], name: str) -> str | None:
    """The text the first function-like macro ``name`` defined in the file of ``lines``
    expands to, its continued lines joined (sbus_bridge's ``#define GET_PARAM(name) if
    (!quadrotor_common::getParam(#name, name##_, pnh_)) return false``), or None."""
    found = function_macros("\n".join(lines), name)
    return found[0][2] if found else None


@functools.lru_cache(maxsize=256)
def _given(words: tuple[str, ...]) -> re.Pattern[str]:
    name = "|".join(re.escape(w) + (r"\(\)" if w == "shared_from_this" else "")
                    for w in words)
    return re.compile(r"[({,]\s*([*&]?\s*(?:" + name + r"))\s*(?:[,)}]|->\s*get_node_\w*\(\))")


def definitions(tu: TranslationUnit, files: set[str]) -> dict[str, list[Function]]:
    """The functions the unit defines in ``files`` (absolute paths), per file, in
    namespaces and classes at any depth: what ``holding`` looks in. One visit in
    libclang that goes into the namespaces and classes of ``files`` only, each cursor's
    file judged once (``cursors.by_file``); the functions of a file in
    the reverse of their order in it (those of one line: the last first)."""
    from .visitor import CONTAINERS, FUNCTIONS

    lib = conf.lib
    functions = {kind.value for kind in FUNCTIONS}
    containers = {kind.value for kind in CONTAINERS}
    found: dict[str, list[Function]] = {}

    def asked(name: str) -> str | None:
        full = os.path.abspath(name)
        return full if full in files else None

    file_of = by_file(asked)  # the location's file, when it is one of ``files``

    def visit(cursor: Cursor, _parent: Cursor, _data: object) -> int:
        name = file_of(lib.clang_getCursorLocation(cursor))
        if name is None:
            return 1  # CXChildVisit_Continue: in no file asked about (a namespace or
            # class opened in another file is met through its own cursor)
        kind = cursor._kind_id
        if kind in functions:
            if lib.clang_isCursorDefinition(cursor):
                extent = lib.clang_getCursorExtent(cursor)
                found.setdefault(name, []).append(
                    (line_of(lib.clang_getRangeStart(extent)),
                     line_of(lib.clang_getRangeEnd(extent)), cursor.spelling,
                     FREE if kind == _FREE or _without_bases(_in(cursor, tu)) else
                     BASES_READ if _bases_all_read(_in(cursor, tu)) else 0))
            return 1
        return 2 if kind in containers else 1  # CXChildVisit_Recurse into a container

    visit_children(tu.cursor, visit)
    for listed in found.values():
        listed.reverse()
    return found


class _RangeList(ctypes.Structure):
    _fields_ = [("count", ctypes.c_uint), ("ranges", ctypes.POINTER(SourceRange))]


def skipped_lines(tu: TranslationUnit) -> dict[str, list[tuple[int, int]]]:
    """The line ranges the preprocessor skipped (``#if 0``, an ``#ifdef`` not taken), per
    file: a call site there is no call of this build. Empty when libclang cannot say."""
    try:
        lib = conf.lib
        get = lib.clang_getAllSkippedRanges
        dispose = lib.clang_disposeSourceRangeList
    except (AttributeError, LibclangError):
        return {}
    get.argtypes, get.restype = [ctypes.c_void_p], ctypes.POINTER(_RangeList)
    dispose.argtypes, dispose.restype = [ctypes.POINTER(_RangeList)], None
    found: dict[str, list[tuple[int, int]]] = {}
    listed = get(tu.obj)
    if not listed:
        return found
    try:
        for i in range(listed.contents.count):
            extent = listed.contents.ranges[i]
            start, end = extent.start, extent.end
            if start.file is not None:
                found.setdefault(os.path.abspath(start.file.name), []).append(
                    (start.line, end.line))
    finally:
        dispose(listed)
    return found
