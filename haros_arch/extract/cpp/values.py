"""Walking C++ values backwards: what string, integer or boolean an argument holds.

A string value is a tuple of parts, each a known ``str`` or ``None`` for a part that is
only known at run time; ``render`` writes the unknown parts as ``?``. Resolved:
literals (also through ``#define``), ``const`` / ``constexpr`` variables, local variables
written exactly once (at their declaration, by one assignment or a smart pointer's
``reset(p)``: the writes ``writes.writes_of`` reads), ``std::string``
construction, ``+`` concatenation and ``.c_str()``, formatting calls with a literal
format (``fmt::format``, ``std::format``, ``snprintf`` into an array, ``boost::format``,
``std::to_string``: ``formats``), a function's parameter from the
calls of the function (``call_sites.CallSites``), and a class member from what a
constructor initialises it with. Anything else is unknown.
"""

from __future__ import annotations

import functools
import os
import re
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any, TypeVar

from clang.cindex import Cursor, CursorKind, SourceLocation, TypeKind, conf

from ...ctext import integer_literal
from ...files import package_files
from . import api, formats
from .cursors import Node, _Place
from .expressions import (
    binary_operator,
    first_operand,
    initializer,
    operand,
    qualified_name,
    ros_init,
    strip,
    unresolved_operator,
    written_arguments,
)
from .getopt import option_held
from .reach import FUNCTIONS
from .synthesis import ANY
from .writes import (
    Write,
    appended_to,
    by_operator,
    const_array,
    emptied,
    searched_from_node,
    searched_key,
    writes_in,
    writes_of,
)

if TYPE_CHECKING:
    from .call_sites import CallSites

Parts = tuple[str | None, ...]
# A part standing for "the argument the callers in other files pass": PLACEHOLDER, the
# function's USR, SEPARATOR, the parameter's index, PLACEHOLDER. A ROS 1 node's
# translation units are joined by ``links.resolve`` once all of them are read.
PLACEHOLDER = "\x00"
SEPARATOR = "\x01"
# A part standing for "one of two texts, as a string another file passes is empty or
# not": CHOICE, the tested text (holding a placeholder), CHOICE_SEP, the text when it is
# empty, CHOICE_SEP, the text when it is not, CHOICE_END (``links.choose`` picks one
# once the placeholders are filled): autorally's ``name + (handle.empty() ? "" : "/" +
# handle)``, hector_quadrotor's ``!field.empty() ? field + "/" : ""``
CHOICE = "\x05"
CHOICE_SEP = "\x06"
CHOICE_END = "\x07"
# in a side of a choice: the tested text (a wrapper's ``field + "/"`` where the tested
# string is its name argument, bound at each call site)
BACKREF = "\x08"
Value = TypeVar("Value")
UNKNOWN: Parts = (None,)
MAX_DEPTH = 24


class NodeName(str):
    """The part rclcpp's ``get_name()`` gives: the node's own name, unknown to ``render``;
    in a call's name ``own_name`` makes it ``~`` where a ``/`` or nothing follows it
    (``get_name() + std::string("/manage_nodes")`` is a private name; ``node_name_ +
    ".verbose"`` one that starts with the node's name, not known; a node's namespace
    ``uas->get_fully_qualified_name()`` is another node's name)."""


NODE_NAME = NodeName("~")


class NodeBaseName(NodeName):
    """rclcpp's ``get_name()`` alone: the node's name without its namespace, which the
    graph knows per instance. In the middle of a call's name (nav2's costmap serves
    ``std::string("get_cost_") + get_name()``) it is the call's one unknown run
    (``own_name_run``; ``PrimitiveCall.name_self``)."""


NODE_BASE_NAME = NodeBaseName("~")


class OwnName(str):
    """ROS 1's ``getName()`` (``ros::this_node``'s, a nodelet's): the node's own name, ``~``
    as a value (a NodeHandle made on it is the private one: moveit's benchmarks; a nodelet
    loaded under it runs under the node's name: bebop_driver), and at the start of a
    call's name followed by ``/`` its private namespace; followed by more of its segment
    it is not (kobuki's auto docking serves ``name_ + "_action"``, ``name_`` the
    nodelet's getName(): ``/<nodelet>_action``, not ``~_action``): ``own_name`` makes it
    unknown there, as rclcpp's node name."""


OWN_NAME = OwnName("~")


class NodeNamespace(str):
    """The node's namespace, which rclcpp's ``expand_topic_or_service_name`` puts before
    a relative name (with a ``/``: ``_expanded``): unknown to ``render``; ``own_name``
    leaves it out, with that ``/``, where it begins a call's name (then the name as
    written, which the graph expands in the node's namespace)."""


NODE_NAMESPACE = NodeNamespace("?")


class SearchedName(str):
    """The name roscpp's ``searchParam(key, result)`` wrote to ``result``: ``key`` as
    found in the nearest namespace that has it (a part ``render`` writes as ``key``; a
    call whose whole name it is reads the parameter searched for, ``searched``)."""


class RemappedName(str):
    """A name roscpp resolved and remapped (``ros::names::resolve(name)``, a handle's
    ``resolveName(name)``, remapping as they do by default), written as resolved from
    the handle: the graph resolves and remaps a whole name, and one it begins (the
    call's prefix, ``names_prefix``), with the instance's remaps; a piece appended to
    other text is the piece as remapped, which only the instance knows: unknown there
    (``_appended``; people's face_detector builds ``camera + "/" + rgb_ns + "/" +
    image_topic`` of three resolved names its launch file remaps)."""


def _remapped(parts: Parts) -> Parts:
    """``parts`` of a name roscpp resolved and remapped, as one ``RemappedName`` when
    the text is known."""
    if parts and all(type(p) is str for p in parts):
        return (RemappedName("".join(parts)),)  # type: ignore[arg-type]
    return parts


class ProgramArgument(str):
    """A part that is the process's ``position``-th command-line argument (``argv[1]`` of
    ``main``): unknown to ``render``; a call whose name has it as its one unknown run
    carries ``position`` (``PrimitiveCall.name_arg``), which the graph takes from the
    arguments the launch file gives the instance. ``position`` counts as
    ``PrimitiveCall.program_arg`` does, and from the end when negative (``argv[argc -
    1]``, -1: only after ``ros::init``, which takes roslaunch's ``:=`` words off)."""

    position: int

    def __new__(cls, position: int) -> ProgramArgument:
        made = super().__new__(cls, "?")
        made.position = position
        return made

    def __eq__(self, other: object) -> bool:
        return isinstance(other, ProgramArgument) and other.position == self.position

    def __ne__(self, other: object) -> bool:
        return not self == other

    def __hash__(self) -> int:
        return hash(("argv", self.position))


class ProgramOption(str):
    """A part that is the argument of a command-line option getopt parses
    (``getopt.option_held``: ``flags``, ``-r --rosparam``; ``spec``, the program's
    options; ``default``, its value when the command line does not give it, ``null``
    when that is a null pointer): unknown to ``render``; a call whose name has it as its
    one unknown run carries them (``PrimitiveCall.name_option``, ``name_getopt``,
    ``name_option_default``, ``name_option_null``)."""

    flags: str
    spec: str
    default: str | None
    null: bool

    def __new__(cls, flags: str, spec: str, default: str | None,
                null: bool = False) -> ProgramOption:
        made = super().__new__(cls, "?")
        made.flags, made.spec, made.default, made.null = flags, spec, default, null
        return made

    def _fields(self) -> tuple[str, str, str | None, bool]:
        return self.flags, self.spec, self.default, self.null

    def __eq__(self, other: object) -> bool:
        return isinstance(other, ProgramOption) and other._fields() == self._fields()

    def __ne__(self, other: object) -> bool:
        return not self == other

    def __hash__(self) -> int:
        return hash(("option", *self._fields()))


class TopicOf(str):
    """The topic name of a publisher or subscription the code made (rclcpp's
    ``get_topic_name()``): the name as resolved and remapped in the node, which
    ``base`` is as the code wrote it; unknown to ``render``. Given only for a call's
    name (``program_arguments``): a name it begins (autoware_utils' published-time
    publisher, ``topic_name + "/debug/published_time"``) is named below that topic
    (``PrimitiveCall.name_below``)."""

    base: str

    def __new__(cls, base: str) -> TopicOf:
        made = super().__new__(cls, "?")
        made.base = base
        return made

    def __eq__(self, other: object) -> bool:
        return isinstance(other, TopicOf) and other.base == self.base

    def __ne__(self, other: object) -> bool:
        return not self == other

    def __hash__(self) -> int:
        return hash(("topic", self.base))


# the parts ``render`` writes ``?`` for besides None: known only to the graph or per instance
_UNKNOWN_PARTS = (NodeName, ProgramArgument, ProgramOption, TopicOf)


def topic_base(parts: Parts) -> str | None:
    """The written name of the topic that begins ``parts`` when it is their one unknown
    run (``TopicOf``), else None."""
    unknown = [i for i, part in enumerate(parts)
               if part is None or isinstance(part, (*_UNKNOWN_PARTS, NodeNamespace))]
    if unknown != [0] or not isinstance(parts[0], TopicOf):
        return None
    return parts[0].base


# whether ``Scope.string`` gives a program argument as a ``ProgramArgument`` part (only
# for a call's name, ``program_arguments``; other readers of parts know only None)
_ARGUMENTS = [False]
# a std::string as clang spells its canonical type
_STD_STRING = re.compile(r"^(const )?std::(__\w+::)?basic_string<char\b")


@contextmanager
def program_arguments() -> Iterator[None]:
    """Within it, ``Scope.string`` gives ``argv[K]`` as a ``ProgramArgument`` part."""
    saved = _ARGUMENTS[0]
    _ARGUMENTS[0] = True
    try:
        yield
    finally:
        _ARGUMENTS[0] = saved


def argument_of(parts: Parts) -> int | None:
    """The index of the program argument that is the one unknown run of ``parts``."""
    runs: list[list[str | None]] = []
    after_known = True
    for part in parts:
        if part is None or isinstance(part, (*_UNKNOWN_PARTS, NodeNamespace)):
            if after_known:
                runs.append([])
            runs[-1].append(part)
            after_known = False
        else:  # (an empty part too: ``render`` writes each run's ``?``)
            after_known = True
    if len(runs) != 1 or len(runs[0]) != 1 or not isinstance(runs[0][0], ProgramArgument):
        return None
    return runs[0][0].position


def option_of(parts: Parts) -> ProgramOption | None:
    """The getopt option whose argument is the one unknown run of ``parts``."""
    unknown = [part for part in parts
               if part is None or isinstance(part, (*_UNKNOWN_PARTS, NodeNamespace))]
    if len(unknown) != 1 or not isinstance(unknown[0], ProgramOption):
        return None
    return unknown[0]


def own_name_run(written: Parts, parts: Parts) -> bool:
    """Whether the one unknown run of ``parts`` (``written`` after ``own_name``) is the
    node's name alone (``NodeBaseName``), not its private namespace: the graph puts the
    instance's name there."""
    if len(written) != len(parts) or any(isinstance(p, NodeNamespace) for p in written):
        return False
    unknown = [i for i, part in enumerate(parts)
               if part is None or isinstance(part, _UNKNOWN_PARTS)]
    return len(unknown) == 1 and isinstance(written[unknown[0]], NodeBaseName)


def own_name(parts: Parts) -> Parts:
    """``parts`` with the node's own name unknown where it is not the node's private
    namespace: anywhere but first, or followed by text that does not start with ``/``."""
    if not any(isinstance(part, (NodeName, NodeNamespace, OwnName)) for part in parts):
        return parts
    found: list[str | None] = []
    skip = False
    for index, part in enumerate(parts):
        if skip:  # the ``/`` after the node's namespace that begins the name
            skip = False
            if part == "/":
                continue
            if type(part) is str and part.startswith("/"):
                part = part[1:]  # ``ns + "/events"``: the name relative to it
        if isinstance(part, NodeNamespace):
            skip = not any(p != "" for p in parts[:index])
            if not skip:
                found.append(None)
        elif isinstance(part, (NodeName, OwnName)):
            after = next((p for p in parts[index + 1:] if p != ""), "")
            first = not any(p != "" for p in parts[:index])
            private = first and (after == "" or (after is not None and after.startswith("/")))
            found.append("~" if private else None)
        else:
            found.append(part)
    return tuple(found)

# rclcpp's node interfaces resolve a name: expanded in the node's namespace and remapped
# (unless ``only_expand``). The graph does both when it links a call, so the value is the
# name as written (image_pipeline: ``node_base->resolve_topic_or_service_name("image",
# false)``); ``Scope.resolved`` tells an image_transport call that its base is remapped
# already. (class, method) -> the index of ``only_expand``. Not modelled: a name the code
# uses resolved once more (``getCameraInfoTopic`` of a resolved name, resolved again, is
# remapped by the graph as written, not below the remapped base) and ``only_expand``
# outside image_transport (the graph still remaps the name).
_RESOLVERS: dict[tuple[str, str], int] = {
    ("NodeBaseInterface", "resolve_topic_or_service_name"): 2,
    ("NodeTopicsInterface", "resolve_topic_name"): 1}
_ESCAPES = {"n": "\n", "t": "\t", "\\": "\\", '"': '"', "'": "'", "0": "\0"}
_TOKEN = re.compile(rb"[A-Za-z_]\w*|[-+]?(?:0[xX][0-9a-fA-F']+|0[bB][01']+|\d[\d']*)[uUlLzZ]*")
# a floating literal as written, its suffix (``f``, ``L``) left out
_FLOAT = re.compile(r"((?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?)[fFlL]?")


def _handle_resolve(target: Cursor) -> bool:
    """roscpp's ``NodeHandle::resolveName(name[, remap])``: ``name`` resolved in the
    handle's namespace and remapped. Its value is the name as seen from the node
    (``_handle_resolved``); the graph resolves and remaps it (``names_prefix``)."""
    parent = target.semantic_parent
    return target.spelling == "resolveName" and parent is not None and (
        qualified_name(parent) == "ros::NodeHandle")


def _expands(target: Cursor) -> bool:
    """rclcpp's free ``expand_topic_or_service_name(name, node, namespace[, service])``:
    ``name`` expanded in the namespace given, the node's own where a node passes its
    ``get_namespace()`` (``_expanded``)."""
    parent = target.semantic_parent
    return target.spelling == "expand_topic_or_service_name" and parent is not None and (
        parent.kind == CursorKind.NAMESPACE and parent.spelling == "rclcpp")


def _expanded(name: Parts) -> Parts:
    """``expand_topic_or_service_name(name, ...)``: a global name as it is, a relative
    or private one after the node's namespace (a name it begins is the name as written:
    ``own_name``; stereo_view's ``stereo_ns + "/left" + expand(image)`` has it unknown
    in the middle)."""
    first = next((p for p in name if p != ""), "")
    if isinstance(first, NodeNamespace) or (first is not None and first.startswith("/")):
        return name  # expanded already (humble's stereo_view expands twice)
    return (NODE_NAMESPACE, "/", *name)


def join_parts(namespace: Parts, name: Parts) -> Parts:
    """``name`` as seen from a handle in ``namespace`` (``~`` private, ``""`` the node's):
    ``handles.join_name`` of values whose parts may be unknown."""
    first = next((p for p in name if p != ""), "")
    if (first is not None and first.startswith(("/", "~"))) or namespace == ("",):
        return name
    if all(type(p) is str for p in namespace):
        text = "".join(namespace)  # type: ignore[arg-type]
        return (text if text == "~" or text.endswith("/") else text + "/", *name)
    return (*namespace, "/", *name)


def _ros_names(target: Cursor, function: str) -> bool:
    """Whether ``target`` is roscpp's ``ros::names::<function>``. ``resolve(name[,
    remap])``: ``name`` resolved in the node's namespace and remapped; its value is the
    name as written (the graph expands and remaps it), and a call named by it is told
    the resolved prefix (``names_prefix``). ``remap(name)``: the target of the remapping
    of ``name``, else ``name``; its value too is the name as written, which the graph
    remaps where the call that takes it resolves it (spencer's
    ``subscribe(ros::names::remap(laserTopic), ...)``). ``clean(name)``: ``_cleaned``."""
    parent = target.semantic_parent
    grand = None if parent is None else parent.semantic_parent
    return (target.spelling == function and parent is not None
            and parent.spelling == "names" and grand is not None and grand.spelling == "ros")


def _cleaned(name: Parts) -> Parts:
    """``ros::names::clean(name)``: each run of slashes one slash, and a last slash
    dropped, as roscpp does, in the text the name is known by (image_pipeline's
    stereo_view: ``clean(stereo_ns + "/left" + image)``, ``stereo_ns`` a handle's
    ``resolveName``); an unknown run stays as it is."""
    merged: list[str | None] = []
    for part in name:
        if type(part) is str and merged and type(merged[-1]) is str:
            merged[-1] += part
        else:
            merged.append(part)
    out = [re.sub("/{2,}", "/", part) if type(part) is str else part for part in merged]
    if out and type(out[-1]) is str and out[-1].endswith("/"):
        out[-1] = out[-1][:-1]
    return tuple(out)


def render(parts: Parts) -> str:
    """The name with ``?`` for each unknown run of parts."""
    text: list[str] = []
    for part in parts:
        if part is None or isinstance(part, _UNKNOWN_PARTS):
            if not text or text[-1] != "?":
                text.append("?")
        else:
            text.append(part)
    joined = "".join(text)
    return choose(joined) if CHOICE in joined and PLACEHOLDER not in joined else joined


def emptiness_test(test: Cursor) -> tuple[Cursor, bool] | None:
    """A test of whether a string is empty: (the string, whether the test holds when it
    is empty) for ``s.empty()``, ``!test``, ``s.length() > 0`` / ``!= 0`` / ``>= 1``,
    ``s.size() == 0`` / ``< 1`` / ``<= 0``, ``s == ""``, ``s != ""``; None for any other."""
    test = strip(test)
    kind = test.kind
    children = [c for c in test.get_children() if c.kind.is_expression()]
    if kind == CursorKind.UNARY_OPERATOR and len(children) == 1:
        tokens = list(test.get_tokens())
        if not tokens or tokens[0].spelling != "!":
            return None
        inner = emptiness_test(children[0])
        return None if inner is None else (inner[0], not inner[1])
    if kind == CursorKind.CALL_EXPR:
        args = written_arguments(test)
        if test.spelling == "empty" and not args:
            subject = method_object(test)
            return None if subject is None else (subject, True)
        if test.spelling in ("operator==", "operator!=") and len(args) == 2:
            for subject, other in ((args[0], args[1]), (args[1], args[0])):
                other = strip(other)
                if other.kind == CursorKind.STRING_LITERAL and literal(other.spelling) == "":
                    return subject, test.spelling == "operator=="
        return None
    if kind == CursorKind.BINARY_OPERATOR and len(children) == 2:
        size = _size_of(children[0])
        number = strip(children[1])
        tokens = list(number.get_tokens()) if number.kind == CursorKind.INTEGER_LITERAL else []
        if size is None or len(tokens) != 1 or not tokens[0].spelling.isdigit():
            return None
        pair = (binary_operator(test, children), int(tokens[0].spelling))
        if pair in ((">", 0), ("!=", 0), (">=", 1)):
            return size, False
        if pair in (("==", 0), ("<", 1), ("<=", 0)):
            return size, True
    return None


_CHOSEN = re.compile(f"{CHOICE}([^{CHOICE}{CHOICE_SEP}{CHOICE_END}]*){CHOICE_SEP}"
                     f"([^{CHOICE}{CHOICE_SEP}{CHOICE_END}]*){CHOICE_SEP}"
                     f"([^{CHOICE}{CHOICE_SEP}{CHOICE_END}]*){CHOICE_END}")


def choose(text: str) -> str:
    """``text`` with each choice (``CHOICE``) replaced by its side for the tested text:
    the first when it is empty, the second (its ``BACKREF`` the tested text) when it has
    text; ``?`` while that text holds a placeholder, or is unknown and may be empty."""
    def pick(found: re.Match[str]) -> str:
        tested, if_empty, if_not = found.groups()
        if tested == "":
            return if_empty
        if PLACEHOLDER in tested or not tested.replace("?", ""):
            return "?"
        return if_not.replace(BACKREF, tested)
    while CHOICE in text:
        chosen = _CHOSEN.sub(pick, text)
        if chosen == text:
            return text
        text = chosen
    return text


def is_empty(parts: Parts) -> bool | None:
    """Whether a string value is empty: False when a known part has text (a node's own
    name has), True when every part is known and none has, else None."""
    known = True
    for part in parts:
        if isinstance(part, NodeName):
            return False
        if part is None or isinstance(part, (ProgramArgument, ProgramOption, TopicOf)) or (
                PLACEHOLDER in part) or CHOICE in part:
            known = False
        elif part:
            return False
    return True if known else None


def _choice_text(parts: Parts) -> str:
    """A side of a ``CHOICE``: its text, ``?`` for an unknown run (placeholders kept)."""
    return "".join("?" if part is None or isinstance(part, _UNKNOWN_PARTS)
                   else part for part in parts)


def method_object(call: Cursor) -> Cursor | None:
    """The object of ``obj.method()``."""
    children = list(call.get_children())
    if children and children[0].kind == CursorKind.MEMBER_REF_EXPR:
        objects = list(children[0].get_children())
        return objects[0] if objects else None
    return None


def permissive_conversion(call: Cursor) -> bool:
    """Whether ``call`` converts a permissive value (``synthesis.ANY``, of a library the
    parse does not have) to another type (``held.operator std::string &()``)."""
    target = call.referenced
    return call.kind == CursorKind.CALL_EXPR and target is not None and (
        target.kind == CursorKind.CONVERSION_FUNCTION and not written_arguments(call)
        and target.semantic_parent is not None and target.semantic_parent.spelling == ANY)


def permissive_held(call: Cursor) -> Cursor | None:
    """The permissive value a ``permissive_conversion`` converts."""
    callee = first_operand(call)
    return first_operand(callee) if callee is not None and (
        callee.kind == CursorKind.MEMBER_REF_EXPR) else None


def _size_of(cursor: Cursor) -> Cursor | None:
    """The string of ``s.length()`` / ``s.size()``."""
    call = strip(cursor)
    if call.kind == CursorKind.CALL_EXPR and call.spelling in ("length", "size") and not (
            written_arguments(call)):
        return method_object(call)
    return None


def _resolver(target: Cursor) -> int | None:
    """The index of ``only_expand`` when ``target`` resolves a name (``_RESOLVERS``)."""
    parent = target.semantic_parent
    return None if parent is None else _RESOLVERS.get((parent.spelling, target.spelling))


def camera_info_topic(base: Parts) -> Parts:
    """image_transport's ``getCameraInfoTopic(base)``: ``camera_info`` in the namespace of
    the base (``left/image_rect`` -> ``left/camera_info``); unknown when that namespace
    is."""
    last = base[-1]
    if last is None or PLACEHOLDER in last or isinstance(
            last, (ProgramArgument, ProgramOption, TopicOf)):
        return UNKNOWN
    if "/" in last:
        return (*base[:-1], last.rpartition("/")[0] + "/camera_info")
    return ("camera_info",) if len(base) == 1 else UNKNOWN


class Scope:
    """What the values of one function body depend on: its variables' writes, macros."""

    def __init__(self, body: Cursor | None, macros: dict[str, str],
                 source: dict[str, bytes], sites: CallSites | None = None) -> None:
        self.body = body
        self.sites = sites
        self.macros = macros
        self.source = source
        # read from the body when a value is first asked (most functions hold no ROS
        # call, and nothing asks their values)
        self._writes: dict[tuple[str, int], list[Cursor | None]] | None = None
        self._passed: dict[tuple[str, int], tuple[Cursor, int]] = {}
        # variable -> every (call, argument index) it is passed to by reference
        self._passings: dict[tuple[str, int], list[tuple[Cursor, int]]] = {}
        # member -> (offset, expression) of each ``member_ = value`` of this body
        # member (or chain of members from this object: ``_named``) -> (offset, value)
        # of each assignment in this body
        self._members: dict[Any, list[tuple[int, Cursor]]] = {}
        # the members of this object this body changes to a value not known, by an
        # operator or an assignment (``n_++``, ``n_ += 2``, ``n_ = f()``; not a call it
        # is passed to): what the constructor gave them is not what they hold
        self._changed: set[tuple[str, int]] = set()
        # (start, end) offsets of the parts of this body that may not run, or run later:
        # branches, loop bodies, cases, handlers, lambdas
        self._regions: list[tuple[int, int]] = []
        # the parts of those that may run again or later: loop bodies, lambdas
        self._repeated: list[tuple[int, int]] = []
        self._lambdas: set[tuple[int, int]] = set()
        # local variable -> (start, end, value or None) of each write of it in this body,
        # those of an unknown value too (passed to a reference, ``+=``)
        self._placed: dict[tuple[str, int], list[tuple[int, int, Cursor | None]]] = {}
        # ``test ? a : b`` (by its place) -> the side taken, while a name made of its
        # value is read once per side (``CallFinder._name_choice``)
        self.chosen: dict[tuple[str, int], bool] = {}
        # a member taken to hold one of its values while a name made of it is read once
        # per value (``member_choices``): its key -> that value
        self.fixed: dict[tuple[str, int], Parts] = {}
        # a counting loop's variable (``for (int i = 1; i < 10; i++)``) -> the value of the
        # turn a call made in its body is read for (``CallFinder._emit_one``)
        self.bound: dict[tuple[str, int], int] = {}
        # a lambda's parameter -> the standard algorithm and range it is each element of
        # (``algorithm_range``)
        self._ranges: dict[tuple[str, int], tuple[Cursor, Cursor] | None] = {}

    # -- writes -----------------------------------------------------------------------

    @property
    def writes(self) -> dict[tuple[str, int], list[Cursor | None]]:
        """Variable key -> the expressions written to it; None for an unknown write."""
        if self._writes is None:
            self._writes = {}
            if self.body is not None:
                self._collect(self.body)
        return self._writes

    @property
    def passed(self) -> dict[tuple[str, int], tuple[Cursor, int]]:
        """Variable key -> (call, argument index) of the last call it was passed to by
        reference: a parameter read writes its value this way."""
        _ = self.writes  # both are read from the body together
        return self._passed

    def _collect(self, body: Cursor) -> None:
        for node in _walk(body):
            kind = node.kind
            if kind in _BRANCHING:
                children = list(node.get_children())
                if kind == CursorKind.IF_STMT:
                    parts = children[1:]  # then, else: not the condition
                    if len(parts) == 2 and _leaves(parts[0]):
                        # ``if (argc < 2) { ...; return 1; } else { name = argv[1]; }``:
                        # what follows the ``if`` runs only after the ``else``
                        parts = parts[:1]
                elif kind == CursorKind.DO_STMT:
                    parts = children[:1]  # the body, before the condition
                elif kind in _WHOLE_REGIONS:
                    parts = [node]
                else:
                    parts = children[-1:]  # a loop's or a switch's body
                self._regions.extend((p.extent.start.offset, p.extent.end.offset)
                                     for p in parts)
                if kind in _REPEATED:
                    self._repeated.extend((p.extent.start.offset, p.extent.end.offset)
                                          for p in parts)
                if kind == CursorKind.LAMBDA_EXPR:
                    self._lambdas.add((node.extent.start.offset, node.extent.end.offset))
            elif kind == CursorKind.CALL_EXPR:
                args = list(node.get_arguments())
                if node.spelling == "operator=" and len(args) == 2:
                    args = []  # a write, not a call the variable is passed to
                elif node.spelling == "operator[]" and len(args) == 2:
                    # an element of it (``list[i]["name"]``), not the variable given
                    # away: what filled it (``getParam("plugins", list)``) still holds
                    args = args[1:]
                for index, arg in enumerate(args):
                    if arg.kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) \
                            and arg.referenced is not None:
                        self._passed[key_of(arg.referenced)] = (node, index)
                        self._passings.setdefault(key_of(arg.referenced), []).append(
                            (node, index))
            for write in writes_of(node, self.source):
                self._keep(write)

    def _keep(self, write: Write) -> None:
        """A write of a local variable or parameter (one that changes the value in place
        only for a variable of a plain type: calls on objects, a NodeHandle's
        advertise, do not change what we track), and ``member_ = value`` on this object
        (``this->`` written or not)."""
        target, value = write.target, write.value
        if _printed(write):
            # ``snprintf(buf, n, "lidar_%s", ip)`` writes all of ``buf``: the value of
            # the array is what the call prints (``_string_format``)
            write = Write(target, write.at, write.at, True)
            value = write.value
        if target.kind == CursorKind.VAR_DECL:
            self._write(target, value)
            self._place(target, write)
        elif target.kind == CursorKind.DECL_REF_EXPR and target.referenced is not None:
            decl = target.referenced
            self._place(decl, write)
            if value is None and (decl.type.is_const_qualified() or not _plain_value(decl)):
                return
            self._write(decl, value)
        elif is_own_member(target):
            if value is None:
                if write.whole or by_operator(write):
                    self._changed.add(key_of(target.referenced))
                return
            self._members.setdefault(key_of(target.referenced), []).append(
                (write.at.extent.start.offset, value))
        elif value is not None and target.kind == CursorKind.MEMBER_REF_EXPR and (
            (chain := _named(target)) is not None and len(chain) > 1
        ):  # a member of a member of this object (``params_.controller_ids = ...``)
            self._members.setdefault(chain, []).append(
                (write.at.extent.start.offset, value))

    def _captured(self, decl: Cursor) -> Scope | None:
        """The scope of the function around this lambda that declares ``decl``, a local
        the lambda captures (kr_mav_control's simulator reads each of its parameters
        through ``auto get_param = [&n](const std::string &name) { ... n.getParam(name,
        p) ... }``, ``n`` the constructor's handle): what it holds is written there."""
        if self.body is None or self.body.kind != CursorKind.LAMBDA_EXPR or (
            self.sites is None or decl.kind != CursorKind.VAR_DECL
        ) or self.holds(decl.location):
            return None
        outer = decl.semantic_parent  # (a lambda's own locals are in its body)
        if outer is None or outer.kind not in FUNCTIONS:
            return None
        scope = self.sites.scope(outer)
        return scope if scope.holds(decl.location) else None

    def holds(self, place: SourceLocation) -> bool:
        """Whether ``place`` is in this scope's body: its file, between its ends."""
        if self.body is None:
            return False
        body = self.body.extent
        return (body.start.file is not None and place.file is not None
                and body.start.file.name == place.file.name
                and body.start.offset <= place.offset <= body.end.offset)

    def assigned(self, decl: Cursor, at: Cursor) -> Cursor | None:
        """What this body last assigned to member ``decl`` before ``at`` (``topic_ =
        topic; sub_ = nh.subscribe(topic_, ...)``: base_local_planner's
        OdometryHelperRos::setOdomTopic), when every assignment of it here is written
        before ``at``: the value the read sees when the body runs straight on."""
        _ = self.writes  # read from the body together
        chain = _named(at) if at.kind == CursorKind.MEMBER_REF_EXPR else None
        found = self._members.get(chain if chain is not None and len(chain) > 1
                                  else key_of(decl))
        if not found:
            return None
        where = at.extent.start.offset
        if any(offset > where for offset, _value in found):
            return None
        offset, value = max(found, key=lambda write: write[0])
        if any(start <= offset <= end and not start <= where <= end
               for start, end in self._regions):
            return None  # the assignment may not run before the read (amcl's map_topic_)
        return value

    def _written_maybe(self, decl: Cursor, at: Cursor) -> bool:
        """Whether this body writes member ``decl`` before ``at`` reads it only in
        branches or loops the read is outside of (``if (n > 1) { robot_ = name; }``):
        the read sees that write or what the member held before. A lambda's write runs
        when the lambda is called, a callback's after start-up: not counted."""
        _ = self.writes  # read from the body together
        chain = _named(at) if at.kind == CursorKind.MEMBER_REF_EXPR else None
        found = self._members.get(chain if chain is not None and len(chain) > 1
                                  else key_of(decl))
        where = at.extent.start.offset
        return bool(found) and any(
            offset < where and self._may_skip(offset, where) and not any(
                first <= offset <= last for first, last in self._lambdas)
            for offset, _value in found or ())

    def _overridden(self, decl: Cursor, at: Cursor, depth: int
                    ) -> tuple[bool, Cursor | None]:
        """Whether this body writes member ``decl`` before ``at`` reads it with a write
        that always runs and, after that one, in a branch the read is outside of (the
        DAVIS driver of rpg_dvs_ros: ``ns = ros::this_node::getNamespace(); if (ns ==
        "/") ns = "/dvs";`` then ``advertise(ns + "/events", ...)``): the read sees
        one of those writes, not what a constructor gives the member. With the value
        they all agree on, None when they do not (not known); (False, None) when this
        body writes it otherwise."""
        _ = self.writes  # read from the body together
        chain = _named(at) if at.kind == CursorKind.MEMBER_REF_EXPR else None
        found = self._members.get(chain if chain is not None and len(chain) > 1
                                  else key_of(decl))
        where = at.extent.start.offset
        if not found or any(offset > where for offset, _value in found):
            return False, None
        ordered = sorted(found, key=lambda write: write[0])
        always = [index for index, (offset, _value) in enumerate(ordered)
                  if not self._may_skip(offset, where)]
        if not always or always[-1] == len(ordered) - 1:
            return False, None
        reaching = [value for _offset, value in ordered[always[-1]:]]
        if any(value is None for value in reaching):
            return True, None
        texts = [self.string(value, depth + 1) for value in reaching]
        if None in texts[0] or any(text != texts[0] for text in texts[1:]):
            return True, None
        return True, reaching[0]

    def values_written(self, decl: Cursor, at: Cursor) -> list[Cursor | None]:
        """Every value this body writes to local ``decl``, or to member ``decl`` before
        ``at``, in order (None for a write whose value is not an expression)."""
        _ = self.writes  # read from the body together
        if decl.kind == CursorKind.VAR_DECL:
            return list(self.writes.get(key_of(decl), []))
        chain = _named(at) if at.kind == CursorKind.MEMBER_REF_EXPR else None
        found = self._members.get(chain if chain is not None and len(chain) > 1
                                  else key_of(decl), [])
        where = at.extent.start.offset
        return [value for offset, value in sorted(found, key=lambda w: w[0])
                if offset < where]

    def _write(self, decl: Cursor, value: Cursor | None) -> None:
        self.writes.setdefault(key_of(decl), []).append(value)

    def _place(self, decl: Cursor, write: Write) -> None:
        if decl.kind == CursorKind.VAR_DECL and not write.whole and _namespace_kept(
                decl, write, self.source):
            return  # a roscpp handle's namespace, which the call does not change
        if decl.kind == CursorKind.VAR_DECL:
            value = write.value if write.whole else None
            if not write.whole and write.at.kind == CursorKind.CALL_EXPR and (
                    write.at.spelling == "operator+="
                    or appended_to(write.at, self.source) is not None):
                # ``key += "/port_name"``, ``key.append(...)``: what it held, then that
                value = write.at
            self._placed.setdefault(key_of(decl), []).append(
                (write.at.extent.start.offset, write.at.extent.end.offset, value))

    def written(self, decl: Cursor) -> bool:
        """Whether this body writes variable ``decl`` (assigns, increments, ``+=``) or
        passes it by reference to a call that may."""
        key = key_of(decl)
        return key in self.writes or key in self._placed or key in self._passed

    def written_before(self, decl: Cursor, at: Cursor, depth: int = 0) -> Cursor | None:
        """What local variable ``decl``, written several times in this body, holds where
        ``at`` reads it: the value of the write that ends last before the read (``name
        = prefix + "reset"; create_service(name, ...); name = prefix + "pose"; ...``:
        zed_wrapper's), when that write runs before the read whenever the read runs (not
        in a branch, loop or lambda the read is outside of) and no write may run between
        it and the read: none later in a loop or lambda the read is in (the next turn,
        a later call), none later at all for a read in a lambda. When the writes after
        the last one that always runs may not run (in a branch), the value they all
        agree on (``_agreed``). None otherwise, or when that write's value is not
        known."""
        found = self._reaching(decl, at)
        if found is None:
            return None
        before, where = found
        start, _end, value = max(before, key=lambda w: w[1])
        if value is None:
            return None
        if self._may_skip(start, where):  # it may not run before the read
            value = self._agreed(before, where, depth)
        return value

    def written_between(self, decl: Cursor, after: Cursor, at: Cursor) -> bool:
        """Whether this body assigns local ``decl`` (``=``, ``+=``) after ``after`` (a
        call it was passed to) ends and before ``at`` reads it; not in an ``if`` whose
        condition holds that call (``if (!pnh.getParam("topic", topic)) topic =
        other();``: what it holds where the call did not fill it)."""
        _ = self.writes  # read from the body together
        placed = self._placed.get(key_of(decl))
        if not placed or self.body is None or not self.holds(at.extent.start):
            return False
        start, where = after.extent.end.offset, at.extent.start.offset
        later = [first for first, last, value in placed
                 if start <= first and last <= where and value is not None]
        if not later:
            return False
        testing = [node.extent for node in _walk(self.body) if node.kind == CursorKind.IF_STMT
                   and (children := list(node.get_children()))
                   and children[0].extent.start.offset <= after.extent.start.offset
                   and after.extent.end.offset <= children[0].extent.end.offset]
        return any(not any(e.start.offset <= first <= e.end.offset for e in testing)
                   for first in later)

    def held_before(self, decl: Cursor, at: Cursor) -> tuple[bool, Cursor | None]:
        """Whether local ``decl`` is written with a value (an assignment, not an
        argument passed by reference) before ``at`` reads it, by a write that runs
        whenever the read does (``double v; v = -0.1; ... getParam("x", v);``), and that
        value when no other write of it (a reference passed to a call, a branch's) may
        come between them."""
        _ = self.writes  # read from the body together
        placed = self._placed.get(key_of(decl))
        if not placed or self.body is None or not self.holds(at.extent.start):
            return False, None
        where = at.extent.start.offset
        sure = [(start, end, value) for start, end, value in placed
                if end <= where and value is not None and not self._may_skip(start, where)]
        if not sure:
            return False, None
        _start, end, value = max(sure, key=lambda write: write[1])
        # any other use of it between (a write, or a reference a call may write)
        between = any(node.kind == CursorKind.DECL_REF_EXPR and node.referenced == decl
                      and end < node.extent.start.offset < where for node in _walk(self.body))
        return True, None if between else value

    def _local_reaching(self, cursor: Cursor
                        ) -> tuple[list[tuple[int, int, Cursor | None]], int] | None:
        """``_reaching`` for the local variable (not a parameter of the function)
        ``cursor`` reads; None when it reads none."""
        cursor = strip(cursor)
        decl = cursor.referenced if cursor.kind == CursorKind.DECL_REF_EXPR else None
        if decl is None or decl.kind != CursorKind.VAR_DECL or self.is_parameter(decl):
            return None
        return self._reaching(decl, cursor)

    def _reaching(self, decl: Cursor, at: Cursor
                ) -> tuple[list[tuple[int, int, Cursor | None]], int] | None:
        """The writes of local ``decl`` that end before ``at`` reads it, and where it
        reads it; None when there are fewer than two writes, the read is not in this
        body, or a write may run between them (a later one in a loop or lambda the read
        is in)."""
        _ = self.writes  # read from the body together
        placed = self._placed.get(key_of(decl))
        if not placed or len(placed) < 2 or self.body is None:
            return None
        if not self.holds(at.extent.start):
            return None  # read elsewhere (a value walked back from another function)
        where = at.extent.start.offset
        body = self.body.extent
        before = [w for w in placed if w[1] <= where]
        if not before:
            return None
        later = [w[0] for w in placed if w[1] > where]
        # a variable declared in a loop's body (a lambda's) is a new one each turn (call):
        # the writes after the read in it reach no later read (realsense's ``std::string
        # param_name(_stream_name[s] + "_width"); _pnh.param(param_name, ...); param_name =
        # _stream_name[s] + "_height";`` in a loop over its streams)
        declared = decl.extent.start
        born = declared.offset if declared.file is not None and (
            declared.file.name == body.start.file.name) else -1
        for first, last in self._repeated:
            if first <= born <= last:
                continue
            if first <= where <= last and any(
                    first <= other <= last or self._in_lambda(first, last)
                    for other in later):
                return None
        return before, where

    def written_choices(self, cursor: Cursor, depth: int = 0
                        ) -> tuple[Parts, Parts, Cursor, bool] | None:
        """The two values a local variable may hold where ``cursor`` reads it when the
        last write that always runs before the read and one later write in a side of an
        ``if`` disagree, each known in full (costmap_2d's ``if (!nh.searchParam(
        "published_footprint_topic", key)) key = "published_footprint";`` then
        ``nh.param(key, ...)``: the key the search found, or the fallback): (the first
        value, the value of the side, that ``if``, whether the side is its ``then``);
        None otherwise."""
        found = self._local_reaching(cursor)
        if found is None or self.body is None:
            return None
        before, where = found
        reaching = self._from_last_always(before, where)
        if reaching is None or len(reaching) != 2:
            return None
        (_s, _e, first), (start, _end, side) = reaching
        if first is None or side is None:
            return None
        values = [self.string(first, depth + 1), self.string(side, depth + 1)]
        if any(None in parts for parts in values) or values[0] == values[1]:
            return None
        found_side = self._side_written(start, where)
        if found_side is None:
            return None
        return values[0], values[1], *found_side

    def _side_written(self, write: int, read: int) -> tuple[Cursor, bool] | None:
        """The innermost ``if`` of the body a write at offset ``write`` is in and a read
        at ``read`` is not, and whether the write is in its ``then``; None when there is
        none, or the write is inside a loop or another branch within that side (then it
        is not the side's one value)."""
        assert self.body is not None
        around = [node for node in _walk(self.body) if node.kind == CursorKind.IF_STMT
                  and node.extent.start.offset <= write <= node.extent.end.offset
                  and not node.extent.start.offset <= read <= node.extent.end.offset]
        if not around:
            return None
        branch = max(around, key=lambda node: node.extent.start.offset)
        children = list(branch.get_children())
        if len(children) < 2:
            return None
        then = children[1].extent
        side_of = children[1] if then.start.offset <= write <= then.end.offset else (
            children[2] if len(children) > 2 else None)
        if side_of is None:
            return None
        low, high = side_of.extent.start.offset, side_of.extent.end.offset
        if any(low <= first <= write <= last <= high and (first, last) != (low, high)
               for first, last in self._regions):
            return None  # a loop or a branch inside the side: not its one value
        return branch, side_of == children[1]

    def member_choices(self, expr: Cursor, depth: int = 0
                       ) -> tuple[Cursor, Parts, Parts, Cursor, bool] | None:
        """The two values a member of this object that ``expr`` reads (itself, or
        through the locals it reads) may hold there, when the one write of it outside
        the class's constructors is this body's, in a side of an ``if`` the read is
        after and outside of (DOBOT's ``if (robotNumber > 1) { kRobotName =
        robotNodeName + "/"; }`` before ``kRobotName + "/dobot_bringup_ros2/srv/..."``):
        what it held before (its constructor's value, its initialiser, or the empty
        string a ``std::string`` is made with), known in full, and the side's: (the
        member, those two values, that ``if``, whether the side is its ``then``). None
        when not so, or more than one member is."""
        if self.body is None or self.sites is None or depth > MAX_DEPTH:
            return None
        found: list[tuple[Cursor, Parts, Parts, Cursor, bool]] = []
        seen: set[tuple[str, int]] = set()
        for at in self._members_read(expr, depth):
            decl = at.referenced
            held = key_of(decl)
            if held in seen:
                continue
            seen.add(held)
            choice = self._member_choice(decl, at, depth)
            if choice is not None:
                found.append(choice)
        return found[0] if len(found) == 1 else None

    def _members_read(self, expr: Cursor, depth: int) -> list[Cursor]:
        """The references to this object's members in ``expr`` and in the values of the
        locals it reads (as ``written_before`` gives them)."""
        out: list[Cursor] = []
        for node in _walk(expr):
            if node.kind == CursorKind.MEMBER_REF_EXPR and is_own_member(node):
                out.append(node)
            elif node.kind == CursorKind.DECL_REF_EXPR and depth < MAX_DEPTH and (
                    node.referenced is not None
                    and node.referenced.kind == CursorKind.VAR_DECL):
                value = self.variable(node.referenced) or self.written_before(
                    node.referenced, node, depth + 1)
                if value is not None:
                    out.extend(self._members_read(value, depth + 1))
        return out

    def _member_choice(self, decl: Cursor, at: Cursor, depth: int
                       ) -> tuple[Cursor, Parts, Parts, Cursor, bool] | None:
        assert self.body is not None and self.sites is not None
        _ = self.writes  # read from the body together
        here = self._members.get(key_of(decl))
        where = at.extent.start.offset
        if not here or len(here) != 1 or key_of(decl) in self._changed:
            return None
        offset, value = here[0]
        if offset > where or not self._may_skip(offset, where):
            return None
        body = self.body.extent
        writes = list(self.sites._writes_to(decl, (CursorKind.CONSTRUCTOR,
                                                  CursorKind.DESTRUCTOR)))
        if len(writes) != 1 or not (
                writes[0].at.extent.start.file is not None and body.start.file is not None
                and writes[0].at.extent.start.file.name == body.start.file.name
                and body.start.offset <= writes[0].at.extent.start.offset <= body.end.offset):
            return None  # another function writes it too: what it held is not known
        found_side = self._side_written(offset, where)
        if found_side is None:
            return None
        before = self._entry_value(decl, depth)
        side = self.string(value, depth + 1)
        if before is None or None in before or before == side:
            return None
        return decl, before, side, *found_side

    def _entry_value(self, decl: Cursor, depth: int) -> Parts | None:
        """What a member holds before the one function that writes it runs: what its
        class's constructor or initialiser gives it, else the empty string of a
        ``std::string`` made without a value; None when not known."""
        assert self.sites is not None and self.body is not None
        constructed = self.sites.member(decl, self.body)
        if constructed is not None and _within(self.body, constructed[1]):
            constructed = None  # this function, taken for an initialisation method
        if constructed is not None and constructed[0] is not None:
            return self.sites.scope(constructed[1]).string(constructed[0], depth + 1)
        value = initializer(decl)
        if value is not None:
            return Scope(None, self.macros, self.source, self.sites).string(value, depth + 1)
        if _STD_STRING.match(decl.type.get_canonical().spelling):
            return ("",)
        return None

    def branch_written(self, cursor: Cursor
                       ) -> tuple[Cursor, list[tuple[int, Cursor]]] | None:
        """The values a local variable may hold where ``cursor`` reads it when the
        writes that reach the read are one in each case of a ``switch`` (or each side
        of an ``if`` / ``else if`` / ``else`` chain) that runs before the read, every
        path through it writing the variable or leaving the function
        (ariac2021ws's ``switch (agv_id) { case AgvId::agv1: service_id = ...; break;
        ... case AgvId::any: throw ...; }``, then ``ros::service::call(service_id,
        msg)``): that statement, and each write's offset with the value it writes.
        None when a path leaves the variable as it was (an ``if`` without ``else``, a
        ``switch`` without ``default`` over a value that is not an enumeration whose
        every enumerator is a label), a write is not so placed (in a loop, after
        the statement, a reference handed to a call), or there are more than
        ``MAX_BRANCH_VALUES``."""
        found = self._local_reaching(cursor)
        if found is None or self.body is None:
            return None
        before, where = found
        last = max(before, key=lambda write: write[1])
        around = [node for node in _walk(self.body)
                  if node.kind in (CursorKind.IF_STMT, CursorKind.SWITCH_STMT)
                  and node.extent.start.offset <= last[0]
                  and last[1] <= node.extent.end.offset
                  and not node.extent.start.offset <= where <= node.extent.end.offset]
        if not around:
            return None
        statement = min(around, key=lambda node: node.extent.start.offset)
        low, high = statement.extent.start.offset, statement.extent.end.offset
        if self._may_skip(low, where):
            return None  # in a branch, loop or lambda the read is outside of
        placed = [(start, value) for start, end, value in before if start >= low]
        if any(start > high for start, _value in placed):
            return None  # written again after it
        ends = _path_writes(statement, placed)
        if ends is None or ends is _LEAVES or not 2 <= len(ends) <= MAX_BRANCH_VALUES:
            return None
        assert isinstance(ends, list)
        if sorted(ends, key=lambda w: w[0]) != sorted(placed, key=lambda w: w[0]):
            return None  # a write the paths do not account for
        return statement, ends

    def _may_skip(self, offset: int, where: int) -> bool:
        """Whether what starts at ``offset`` may not run before a read at ``where``: it
        is in a branch, loop or lambda that the read is outside of."""
        return any(first <= offset <= last and not first <= where <= last
                   for first, last in self._regions)

    def _agreed(self, before: list[tuple[int, int, Cursor | None]], where: int,
                depth: int) -> Cursor | None:
        """The value a read at ``where`` sees whichever of the writes ``before`` it
        reach it: the last write that always runs before the read, and every later one
        (each in a branch, loop or lambda the read is outside of) when their values
        are all known in full and the same text (costmap_2d's ``if
        (!nh.searchParam("footprint_topic", key)) key = "footprint_topic";``: the key is
        the one searched for either way). The first of them (the name a search found
        covers the one it started from); None when any differs, is not known, or no
        write always runs (a variable declared without a value: what it held first)."""
        writes = self._from_last_always(before, where)
        if writes is None:
            return None
        reaching = [value for _start, _end, value in writes]
        known = [value for value in reaching if value is not None]
        if len(known) < len(reaching):
            return None
        texts = [self.string(value, depth + 1) for value in known]
        if any(part is None for part in texts[0]) or any(t != texts[0] for t in texts[1:]):
            return None
        return known[0]

    def _from_last_always(self, before: list[tuple[int, int, Cursor | None]], where: int
                          ) -> list[tuple[int, int, Cursor | None]] | None:
        """The writes that may reach a read at ``where``, in order: the last of
        ``before`` that always runs before it and every later one (each in a branch,
        loop or lambda the read is outside of); None when none always runs."""
        ordered = sorted(before, key=lambda w: w[1])
        always = [i for i, (start, _end, _v) in enumerate(ordered)
                  if not self._may_skip(start, where)]
        return ordered[always[-1]:] if always else None

    def _in_lambda(self, first: int, last: int) -> bool:
        return (first, last) in self._lambdas

    def range_of(self, decl: Cursor) -> Cursor | None:
        """The range-based ``for`` of this body whose loop variable ``decl`` is (``for
        (std::string topic : topics_)``); its second child is the range it walks."""
        if self.body is None or decl.kind != CursorKind.VAR_DECL:
            return None
        key = key_of(decl)
        for node in _walk(self.body):
            if node.kind != CursorKind.CXX_FOR_RANGE_STMT:
                continue
            children = list(node.get_children())
            if len(children) >= 3 and children[0].kind == CursorKind.VAR_DECL and (
                key_of(children[0]) == key
            ):
                return node
        return None

    def words_loop(self, decl: Cursor) -> tuple[Cursor, Cursor] | None:
        """The ``while (stream >> decl)`` of this body that reads local ``decl`` word by
        word from a string stream made of a string, and that string's expression
        (costmap_2d's ``std::stringstream ss(sources); while (ss >> source)`` over its
        ``observation_sources``): ``decl`` is each word of it in turn."""
        if self.body is None or decl.kind != CursorKind.VAR_DECL:
            return None
        key = key_of(decl)
        for node in _walk(self.body):
            if node.kind != CursorKind.WHILE_STMT:
                continue
            test = next(iter(node.get_children()), None)
            shift = next((c for c in _walk(test) if c.kind == CursorKind.CALL_EXPR
                          and c.spelling == "operator>>"), None) if test is not None else None
            if shift is None:
                continue
            operands = [strip(c) for c in shift.get_children() if c.kind.is_expression()]
            named = [c.referenced for c in operands if c.kind == CursorKind.DECL_REF_EXPR
                     and c.referenced is not None
                     and c.referenced.kind == CursorKind.VAR_DECL]
            if len(named) != 2 or key_of(named[1]) != key:
                continue
            stream = named[0]
            if "stringstream" not in stream.type.spelling:
                continue
            made = initializer(stream)
            made = strip(made) if made is not None else None
            given = written_arguments(made) if (
                made is not None and made.kind == CursorKind.CALL_EXPR) else []
            if len(given) == 1:
                return node, given[0]
        return None

    def algorithm_range(self, decl: Cursor) -> tuple[Cursor, Cursor] | None:
        """(call, range) of the standard algorithm of this body that calls the lambda
        whose first parameter ``decl`` is with each element of a range, ``list.begin()``
        to ``list.end()`` (``std::all_of(names.begin(), names.end(), [&](std::string s)
        {...})``, raspimouse's lifecycle_node_manager): the range's object."""
        if self.body is None or decl.kind != CursorKind.PARM_DECL:
            return None
        key = key_of(decl)
        if key not in self._ranges:
            self._ranges[key] = self._algorithm_range(key)
        return self._ranges[key]

    def _algorithm_range(self, key: tuple[str, int]) -> tuple[Cursor, Cursor] | None:
        assert self.body is not None
        for node in _walk(self.body):
            if node.kind != CursorKind.CALL_EXPR or node.spelling not in _ELEMENT_ALGORITHMS:
                continue
            args = written_arguments(node)
            if len(args) != 3:
                continue
            function = strip(args[2])
            params = [c for c in function.get_children() if c.kind == CursorKind.PARM_DECL] \
                if function.kind == CursorKind.LAMBDA_EXPR else []
            if not params or key_of(params[0]) != key:
                continue
            ends = [_range_end(a) for a in args[:2]]
            if ends[0] is None or ends[1] is None or (ends[0][0], ends[1][0]) not in (
                    ("begin", "end"), ("cbegin", "cend")) or _named(ends[0][1]) is None or (
                    _named(ends[0][1]) != _named(ends[1][1])):
                return None
            return node, ends[0][1]
        return None

    def counted_loop(self, index: Cursor, container: Cursor) -> Cursor | None:
        """The ``for`` of this body that counts ``index`` (a variable it declares) from
        its start up to ``container.size()`` (``for (size_t i = 0; i != ids.size(); i++)``),
        when ``container`` names the variable or member that condition names: then
        ``container[index]`` is each element in turn."""
        if self.body is None or index.kind != CursorKind.VAR_DECL:
            return None
        key, named = key_of(index), _named(container)
        if named is None:
            return None
        for node in _walk(self.body):
            if node.kind != CursorKind.FOR_STMT:
                continue
            children = list(node.get_children())
            if len(children) < 4 or children[0].kind != CursorKind.DECL_STMT:
                continue
            declared = [c for c in children[0].get_children() if c.kind == CursorKind.VAR_DECL]
            if len(declared) != 1 or key_of(declared[0]) != key:
                continue
            start = initializer(declared[0])
            if start is None or strip(start).kind != CursorKind.INTEGER_LITERAL or [
                t.spelling for t in strip(start).get_tokens()] != ["0"]:
                return None
            test = children[1]
            sides = [c for c in test.get_children() if c.kind.is_expression()]
            if test.kind != CursorKind.BINARY_OPERATOR or len(sides) != 2 or (
                binary_operator(test, sides) not in ("<", "!=")
            ):
                return None
            counter, bound = strip(sides[0]), strip(sides[1])
            size = list(bound.get_children())
            if counter.kind != CursorKind.DECL_REF_EXPR or counter.referenced is None or (
                key_of(counter.referenced) != key or bound.kind != CursorKind.CALL_EXPR
                or bound.spelling != "size" or not size
                or size[0].kind != CursorKind.MEMBER_REF_EXPR
            ):
                return None
            objects = [c for c in size[0].get_children() if c.kind.is_expression()]
            return node if objects and _named(objects[0]) == named else None
        return None

    def method_calls(self, decl: Cursor, at: Cursor) -> list[tuple[Cursor, bool]]:
        """The calls of a method on local variable ``decl`` in this body before ``at``
        (``qos.transient_local();``), in order, each with whether it may not run before
        ``at`` (in a branch, loop or lambda that ``at`` is outside of)."""
        if self.body is None:
            return []
        _ = self.writes  # the regions are read with the writes
        key, where = key_of(decl), at.extent.start.offset
        found: list[tuple[int, Cursor, bool]] = []
        for node in _walk(self.body):
            if node.kind != CursorKind.CALL_EXPR:
                continue
            callee = next(iter(node.get_children()), None)
            if callee is None or callee.kind != CursorKind.MEMBER_REF_EXPR:
                continue
            target = first_operand(callee)
            offset = node.extent.start.offset
            if (target is None or target.kind != CursorKind.DECL_REF_EXPR
                    or target.referenced is None or key_of(target.referenced) != key
                    or offset >= where):
                continue
            maybe = any(start <= offset <= end and not start <= where <= end
                        for start, end in self._regions)
            found.append((offset, node, maybe))
        return [(node, maybe) for _offset, node, maybe in sorted(found, key=lambda f: f[0])]

    # -- values -----------------------------------------------------------------------

    def given_back(self, parm: Cursor) -> Cursor | None:
        """The value this body hands its caller through ``parm``, a parameter taken by
        non-const reference: the one expression it assigns it, when that assignment runs
        whenever the body runs on (in no branch, loop, handler or lambda) and the body
        passes ``parm`` to no call that may write it too. nav2's collision monitor:
        ``getParameters(cmd_vel_in_topic, cmd_vel_out_topic, state_topic)`` assigns each
        ``get_parameter("cmd_vel_out_topic").as_string()`` and the caller publishes on
        it."""
        ctype = parm.type
        if parm.kind != CursorKind.PARM_DECL or ctype.kind != TypeKind.LVALUEREFERENCE or (
                ctype.get_pointee().is_const_qualified()):
            return None
        key = key_of(parm)
        found = self.writes.get(key)
        if not found or len(found) != 1 or found[0] is None or key in self._passed:
            return None
        at = found[0].extent.start.offset
        if any(first <= at <= last for first, last in self._regions):
            return None
        return found[0]

    def passed_to(self, decl: Cursor, at: Cursor | None = None) -> tuple[Cursor, int] | None:
        """The last call ``decl`` was passed to by reference, and at which index; for a
        read ``at`` in this body, the last such call that ends before it (costmap_2d's
        ``nh.param(key, topic, ...)`` twice, each read before its own ``subscribe`` /
        ``advertise(topic, ...)``), when there is one."""
        key = key_of(decl)
        found = self.passed.get(key)
        calls = self._passings.get(key, [])
        if at is None or len(calls) < 2 or self.body is None:
            return found
        read = at.extent
        if not self.holds(read.start):
            return found
        before = [c for c in calls if c[0].extent.end.offset <= read.start.offset]
        return max(before, key=lambda c: c[0].extent.end.offset) if before else found

    def variable(self, decl: Cursor) -> Cursor | None:
        """The one expression variable ``decl`` holds, when there is exactly one."""
        if decl.kind not in (CursorKind.VAR_DECL, CursorKind.FIELD_DECL):
            return None
        writes = self.writes.get(key_of(decl))
        if writes is not None:
            return writes[0] if len(writes) == 1 else None
        outer = self._captured(decl)
        if outer is not None:
            return outer.variable(decl)
        if decl.type.is_const_qualified() or _string_constant(decl) or const_array(decl) \
                or _const_reference(decl):
            definition = decl.get_definition() or decl
            return initializer(definition) or _template_initializer(decl)
        if unwritten_global(decl):
            return initializer(decl.get_definition() or decl)
        return None

    def string(self, cursor: Cursor, depth: int = 0) -> Parts:
        if depth > MAX_DEPTH:
            return UNKNOWN
        cursor = strip(cursor)
        kind = cursor.kind
        if kind == CursorKind.STRING_LITERAL:
            text = literal(cursor.spelling)
            return UNKNOWN if text is None else (text,)
        if kind == CursorKind.CHARACTER_LITERAL:
            # ``ns + '/' + topic``: std::string's operator+ appends the one character
            # (libclang spells the literal's cursor empty: its one token)
            tokens = [t.spelling for t in cursor.get_tokens()]
            text = char_literal(tokens[0]) if len(tokens) == 1 else None
            return UNKNOWN if text is None else (text,)
        if kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
            decl = cursor.referenced
            if decl is None:  # a name in a template that clang could not bind
                return UNKNOWN
            if self.fixed and key_of(decl) in self.fixed:
                return self.fixed[key_of(decl)]
            if self.is_parameter(decl):
                return self.sites.agreed(  # type: ignore[union-attr]
                    decl, lambda arg, scope: scope.string(arg, depth + 1), UNKNOWN)
            if _ARGUMENTS[0] and decl.kind in (CursorKind.FIELD_DECL, CursorKind.VAR_DECL):
                option = option_held(cursor, decl, self.source)
                if option is not None:  # ``case 'r': name = optarg;`` of a getopt loop
                    return (ProgramOption(*option),)
            found = self.held(cursor, decl, depth)
            if found is None and self.sites is not None:
                elsewhere = self.sites.member_elsewhere(decl)
                if elsewhere is not None:  # what the files of its constructors give it
                    return (elsewhere,)
                self.sites.unset(decl)  # why the name is unknown (``CallSites.unset``)
            return UNKNOWN if found is None else found[1].string(found[0], depth + 1)
        if _ARGUMENTS[0] and (kind == CursorKind.ARRAY_SUBSCRIPT_EXPR or (
                kind == CursorKind.CALL_EXPR and cursor.spelling in _ELEMENT)):
            index = program_argument(cursor, self)
            if index is not None:
                return (ProgramArgument(index),)
        if kind == CursorKind.ARRAY_SUBSCRIPT_EXPR:
            return self._string_element(cursor, depth)
        if kind == CursorKind.CALL_EXPR:
            return self._string_call(cursor, depth)
        if kind == CursorKind.BINARY_OPERATOR:
            return self._string_sum(cursor, depth)
        if kind == CursorKind.CONDITIONAL_OPERATOR:
            return self._string_choice(cursor, depth)
        return UNKNOWN

    def _string_element(self, cursor: Cursor, depth: int) -> Parts:
        """``names[i]`` of a local array this body initialises with a list
        (``std::string angle_names[3] = {"roll", "pitch", "yaw"};``, orb_slam3_ros_wrapper's
        nodes) at an index known here: a literal, or a counting loop's variable at the
        turn being read (``CallFinder._emit_one`` reads the loop turn by turn when a name
        is made of it). Unknown when the body writes an element (``names[1] = ...``) or
        names the array otherwise than by an element (handed to a function that may fill
        it)."""
        parts = [c for c in cursor.get_children() if c.kind.is_expression()]
        if len(parts) != 2:
            return UNKNOWN
        base = strip(parts[0])
        decl = base.referenced if base.kind == CursorKind.DECL_REF_EXPR else None
        if decl is None or decl.kind != CursorKind.VAR_DECL or (
                decl.type.get_canonical().kind != TypeKind.CONSTANTARRAY) or not (
                self.holds(decl.extent.start)):
            return UNKNOWN
        items = initializer(decl)
        if items is None or items.kind != CursorKind.INIT_LIST_EXPR:
            return UNKNOWN
        index = self.integer(parts[1])
        elements = [c for c in items.get_children() if c.kind.is_expression()]
        if index is None or not 0 <= index < len(elements) or self._element_written(decl):
            return UNKNOWN
        return self.string(elements[index], depth + 1)

    def _element_written(self, decl: Cursor) -> bool:
        """Whether this body may change an element of the array ``decl`` after its
        declaration: an element assigned (``names[i] = x``, ``+=``), or the array named
        otherwise than by an element (passed whole, to a function that may write it)."""
        assert self.body is not None
        body = self.body.extent
        text = self.source.get(body.start.file.name) if body.start.file is not None else None
        if text is None:
            return True
        code = text[decl.extent.end.offset:body.end.offset]
        name = re.escape(decl.spelling.encode())
        for found in re.finditer(rb"(?<![\w.>:])" + name + rb"\b", code):
            before = code[max(0, found.start() - 8):found.start()].rstrip()
            if before.endswith(b">>") or (before.endswith(b"&") and not before.endswith(
                    b"&&")):
                return True  # ``fs["x"] >> names[i]``, ``&names[i]``
            rest = code[found.end():found.end() + 200]
            subscript = re.match(rb"\s*\[[^\]\[;]*\]", rest)
            if subscript is None:
                return True
            after = rest[subscript.end():].lstrip()
            if (after[:1] == b"=" and after[:2] != b"==") or after[:2] in (
                    b"+=", b"-=", b"++", b"--"):
                return True
        return False

    def _string_choice(self, cursor: Cursor, depth: int) -> Parts:
        """``test ? a : b``: the side the test picks when it is decided here (a boolean,
        or whether a string is empty: ``s.empty()``, ``!s.empty()``, ``s.length() > 0``,
        ``s.size() == 0``, ``s == ""``); a ``CHOICE`` part when the string is one other
        call sites pass (a placeholder), which ``links.choose`` decides per value; else
        unknown."""
        children = [c for c in cursor.get_children() if c.kind.is_expression()]
        if len(children) != 3:
            return UNKNOWN
        test, yes, no = children
        side = self.chosen.get(key_of(cursor)) if self.chosen else None
        if side is not None:
            return self.string(yes if side else no, depth + 1)
        if _ARGUMENTS[0]:
            index = program_argument(yes, self)
            if index is not None and index > 0 and _has_argument(test, yes, index, self):
                # ``argc > 1 ? argv[1] : ""`` (baxter's position_kinematics): the
                # argument where the program has it; where the instance has none, the
                # graph leaves the name unknown, not the other side
                return (ProgramArgument(index),)
        found = self._emptiness(test, depth)
        if found is None:
            truth = self.boolean(test)
            return UNKNOWN if truth is None else self.string(yes if truth else no, depth + 1)
        subject, when_empty = found
        empty = is_empty(subject)
        if empty is not None:
            return self.string(yes if empty == when_empty else no, depth + 1)
        if not all(part is not None and type(part) is str for part in subject) or not any(
                PLACEHOLDER in part for part in subject if part is not None):
            return UNKNOWN
        if_empty, if_not = (yes, no) if when_empty else (no, yes)
        return (CHOICE + "".join(subject)  # type: ignore[arg-type]
                + CHOICE_SEP + _choice_text(self.string(if_empty, depth + 1))
                + CHOICE_SEP + _choice_text(self.string(if_not, depth + 1)) + CHOICE_END,)

    def _emptiness(self, test: Cursor, depth: int) -> tuple[Parts, bool] | None:
        """A test of whether a string is empty (``emptiness_test``): the string's value
        and whether the test holds when it is empty."""
        found = emptiness_test(test)
        return None if found is None else (self.string(found[0], depth + 1), found[1])

    def _string_sum(self, cursor: Cursor, depth: int) -> Parts:
        """``a + b`` that the parse kept as an operator, not a call of ``operator+``:
        an operand's type depends on a template parameter (``this->behavior_name_ +
        ".acceleration_limit"`` in nav2's DriveOnHeading<ActionT>); a concatenation when
        one side is a string."""
        children = [c for c in cursor.get_children() if c.kind.is_expression()]
        if len(children) != 2:
            return UNKNOWN
        if binary_operator(cursor, children) != "+":
            return UNKNOWN
        left, right = self.string(children[0], depth + 1), self._appended(children[1], depth)
        if all(part is None for part in (*left, *right)):
            return UNKNOWN
        return left + right

    def _appended(self, cursor: Cursor, depth: int) -> Parts:
        """The value of a string appended to another: a name roscpp resolved and remapped
        (``NodeHandle::resolveName``, ``ros::names::resolve``: ``RemappedName``) is the
        piece the instance's remaps give it, not known here (image_view's stereo_view:
        ``stereo_ns + "/left/" + nh.resolveName("image")``, ``stereo/left/?``); one
        resolved without remapping (``resolveName(name, false)``, as written or held in
        a local) is a global name there, the node's namespace (not known here) before
        it (``_expanded``). A resolved name is taken as written only where it begins a
        call's name (``names_prefix``)."""
        value = self.string(cursor, depth + 1)
        if any(isinstance(part, RemappedName) for part in value):
            # a name roscpp resolved and remapped, appended to other text: the piece
            # the instance's remaps give it, not known here
            return tuple(None if isinstance(part, RemappedName) else part for part in value)
        held = strip(cursor)
        if held.kind == CursorKind.DECL_REF_EXPR and held.referenced is not None:
            held = strip(self.variable(held.referenced) or held)
        target = held.referenced if held.kind == CursorKind.CALL_EXPR else None
        if target is not None and written_arguments(held) and (
                _handle_resolve(target) or _ros_names(target, "resolve")):
            return _expanded(value)
        return value

    def held(self, cursor: Cursor, decl: Cursor, depth: int) -> tuple[Cursor, Scope] | None:
        """The expression the variable or member ``decl`` that ``cursor`` reads holds
        there, and the scope to read it in: its one value, the last assignment before the
        read, else (a member this function does not write) its constructor's value."""
        value = self.variable(decl)
        if value is None and cursor.kind == CursorKind.MEMBER_REF_EXPR and (
            decl.kind == CursorKind.FIELD_DECL
        ):
            value = self.assigned(decl, cursor)
            if value is None:
                overridden, value = self._overridden(decl, cursor, depth)
                if overridden:
                    return None if value is None else (value, self)
                if self._written_maybe(decl, cursor):
                    # what the constructor gave it, or this body's write in a branch
                    # before the read (``member_choices`` gives a call per value)
                    return None
        elif value is None and decl.kind == CursorKind.VAR_DECL:
            value = self.written_before(decl, cursor, depth)
        return (value, self) if value is not None else self.field(decl)

    def _made_topic(self, made: Cursor | None, depth: int) -> str | None:
        """The name, as written and known, that the publisher or subscription ``made``
        holds was created with: a variable, member or parameter (what every call of this
        file passes, when all agree) holding a node's ``create_publisher(name, ...)`` /
        ``create_subscription(name, ...)``."""
        from .handles import pointee  # (handles reads values)

        if made is None or depth > MAX_DEPTH:
            return None
        held = pointee(made)  # ``publisher->``: the shared pointer
        if held.kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
            decl = held.referenced
            if decl is None:
                return None
            if self.is_parameter(decl):
                return self.sites.agreed(  # type: ignore[union-attr]
                    decl, lambda arg, scope: scope._made_topic(arg, depth + 1), None)
            found = self.held(held, decl, depth)
            return None if found is None else found[1]._made_topic(found[0], depth + 1)
        if held.kind != CursorKind.CALL_EXPR:
            return None
        target = held.referenced
        args = written_arguments(held)
        if target is not None and target.kind == CursorKind.CONSTRUCTOR and len(args) == 1:
            return self._made_topic(args[0], depth + 1)  # a shared pointer converted
        if target is None or held.spelling not in _TOPIC_MAKERS or not args or (
                target.semantic_parent is None
                or qualified_name(target.semantic_parent) not in _NODE_NAME_OWNERS):
            return None
        name = self.string(args[0], depth + 1)
        return None if any(not _known_text(part) for part in name) else "".join(
            part for part in name if part is not None)

    def field(self, decl: Cursor, initial: bool = False) -> tuple[Cursor, Scope] | None:
        """A member this function does not write: the value its class's constructor
        gives it, and the scope to read that value in. ``initial``: the value it holds
        first (its default initialiser even where other functions write it later)."""
        if decl.kind != CursorKind.FIELD_DECL or self.sites is None or (
            key_of(decl) in self.writes or key_of(decl) in self._changed
        ):
            return None
        return self.sites.field(decl, self.body, initial)

    def _elsewhere(self, made: Cursor | None) -> str | None:
        """The placeholder of the parameter that holds the publisher or subscription
        ``made`` when the calls that give it a value are not this file's
        (``CallSites.given_elsewhere``)."""
        from .handles import pointee  # (handles reads values)

        if made is None or self.sites is None:
            return None
        held = pointee(made)
        decl = held.referenced if held.kind == CursorKind.DECL_REF_EXPR else None
        if decl is None or not self.is_parameter(decl):
            return None
        return self.sites.given_elsewhere(decl)

    def is_parameter(self, decl: Cursor) -> bool:
        """A parameter this function never assigns, whose callers may tell its value
        (not a lambda's that a standard algorithm calls with each element of a range:
        ``algorithm_range``, no call of the file passes it)."""
        return self.sites is not None and decl.kind == CursorKind.PARM_DECL and all(
            w is None for w in self.writes.get(key_of(decl), [])) and (
            self.algorithm_range(decl) is None)

    def _string_call(self, call: Cursor, depth: int) -> Parts:
        args = written_arguments(call)
        target = call.referenced
        if emptied(call):
            return ("",)  # what ``s.clear()`` leaves in ``s`` (a write of it: ``writes``)
        key = searched_key(call)
        if key is not None:  # the name it found (a write of its result: ``writes``)
            text = self.string(key, depth + 1)
            if not any(type(part) is str and part for part in text):
                return UNKNOWN
            # a key partly known (MoveIt's ``base_param_name +
            # "/kinematics_solver_timeout"``) is found as written, its unknown runs
            # ``?``: the result names the parameter searched for, never a value read
            key_text = render(text)
            if searched_from_node(call) and not key_text.startswith(("/", "~")):
                key_text = "~" + key_text  # from the node's private namespace up
            given = written_arguments(call)
            if len(given) == 3 and not key_text.startswith(("/", "~")):
                # ``ros::param::search(ns, key, result)`` from a global namespace known
                # in full: the key there (one a handle gives, ``n.getNamespace()``, is
                # the handle's own, as its searchParam's)
                space = self.string(given[0], depth + 1)
                if all(type(part) is str for part in space) and render(space).startswith("/"):
                    key_text = render(space).rstrip("/") + "/" + key_text
            return (SearchedName(key_text),)
        if call.spelling in ("operator+", "operator+=") and len(args) == 2:
            # (``a += b`` is read where a write of ``a`` names it: ``written_before``)
            return self.string(args[0], depth + 1) + self._appended(args[1], depth)
        appended = appended_to(call, self.source)
        if appended is not None:  # ``a.append(b)``, as ``a += b``
            return self.string(appended[0], depth + 1) + self._appended(appended[1], depth)
        if call.spelling in ('operator""s', 'operator""sv') and args and (
                strip(args[0]).kind == CursorKind.STRING_LITERAL):
            # std's string literal, ``"/change_state"s`` (ouster's lifecycle client)
            return self.string(args[0], depth + 1)
        if target is None:  # an implicit conversion wrapping the real expression
            unresolved = unresolved_operator(call)
            if unresolved is not None:  # ``a + b`` left to the template's instantiation
                symbol, left, right = unresolved
                if symbol != "+":
                    return UNKNOWN
                return self.string(left, depth + 1) + self.string(right, depth + 1)
            inner = operand(call)
            return self.string(inner, depth + 1) if inner is not None else UNKNOWN
        if permissive_conversion(call):
            # a permissive value (of a library the parse does not have) given where a
            # string is taken: the value it holds (``name + "/pose"``, the permissive
            # ``operator+`` of the library's value and the text: ``?/pose``)
            held = permissive_held(call)
            return self.string(held, depth + 1) if held is not None else UNKNOWN
        if not args and target.spelling == "getName" and target.semantic_parent is not None \
                and qualified_name(target.semantic_parent) in _ROS1_NAME_OWNERS:
            # ros::this_node::getName(): the node's own (private) name; a nodelet's
            # getName() is its own, which its private handle's namespace is too
            # (PX4-Avoidance's local planner reads getName() + "/pointcloud_topics");
            # followed by more of a segment it is not: ``OwnName``
            return (OWN_NAME,)
        if not args and target.spelling == "getNamespace" and target.semantic_parent is not None \
                and qualified_name(target.semantic_parent) == "ros::this_node":
            # ros::this_node::getNamespace(): the node's namespace (rpg_dvs_ros' DAVIS
            # driver advertises ``ns + "/events"``), known per instance
            return (NODE_NAMESPACE,)
        if not args and _ARGUMENTS[0] and target.spelling == "get_topic_name" and (
                target.semantic_parent is not None
                and qualified_name(target.semantic_parent) in _TOPIC_HOLDERS):
            # a publisher's or subscription's topic, resolved and remapped: the name the
            # code made it with, where that is known (``TopicOf``)
            made = self._made_topic(method_object(call), depth + 1)
            if made is None:
                # the topic of a publisher a parameter holds, given by calls this file
                # does not hold: the parameter's placeholder (``CallSites.given_elsewhere``)
                marker = self._elsewhere(method_object(call))
                return UNKNOWN if marker is None else (marker,)
            return (TopicOf(made),)
        if not args and _names_node(target):
            # an rclcpp node's get_name() (or its base interface's): the node's own name
            # (``get_name() + std::string("/manage_nodes")`` is ``<namespace>/<node>/
            # manage_nodes``, ``~/manage_nodes``: ``own_name``)
            return (NODE_BASE_NAME,) if target.spelling == "get_name" else (NODE_NAME,)
        if len(args) == 1 and target.spelling in ("move", "forward") and (
                _namespace_of(target) == "std"):
            # ``suffix_(std::move(suffix))``: the value moved (autoware_utils'
            # PublishedTimePublisher keeps its topic suffix so)
            return self.string(args[0], depth + 1)
        if args and _ros_names(target, "resolve") and not self._unremapped(args):
            return _remapped(self.string(args[0], depth + 1))
        if args and (_resolver(target) is not None or _ros_names(target, "resolve")
                     or _ros_names(target, "remap")):
            return self.string(args[0], depth + 1)
        if args and _expands(target):
            return _expanded(self.string(args[0], depth + 1))
        if len(args) == 1 and _ros_names(target, "clean"):
            return _cleaned(self.string(args[0], depth + 1))
        if args and _handle_resolve(target):
            resolved = self._handle_resolved(call, args[0], depth)
            return resolved if self._unremapped(args) else _remapped(resolved)
        if (target.spelling == "getCameraInfoTopic" and len(args) == 1
                and target.semantic_parent is not None
                and target.semantic_parent.spelling == "image_transport"):
            return camera_info_topic(self.string(args[0], depth + 1))
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
                stream = _string_stream(objects[0]) if objects else None
                if stream is not None:
                    return self._stream_text(stream, call, depth)
                if objects:
                    return self.string(objects[0], depth + 1)
        formatted = self._string_format(call, target, args, depth)
        if formatted is not None:
            return formatted
        if not args:
            found = self._returned(target, lambda scope, value: scope.string(value, depth + 1))
            if found is not None:
                return found
        elif target is not None:
            bound = self.given_return(target, args, depth)
            if bound is not None:
                return bound
        return UNKNOWN

    def _stream_events(self, decl: Cursor, at: Cursor, depth: int
                       ) -> list[tuple[Parts | None, list[Cursor]]] | None:
        """The writes (their text, or None for an emptying, and the operands written)
        that make what ``ss.str()`` at ``at`` gives of the local string stream ``decl``,
        made empty and written in this body with ``ss << a << b`` (youbot_driver_ros_interface's
        ``topicName.str(""); topicName << armTopic << "arm_controller/position_command";
        node.subscribe(topicName.str(), ...)``): the text of what was written since its
        last emptying (``ss.str("")``), each string and integer written as its value, any
        other value (a float, a manipulator's formatting) an unknown run. None (unknown
        as a whole) where a write may not run before ``at`` (a branch it is outside of), where
        ``at`` is in a loop (or lambda) that writes the stream without emptying it before
        ``at`` in the same turn, or writes it after ``at`` (the next turn reads that),
        where the stream is made with a text (later writes overwrite it from its start)
        or emptied with one, and where the body uses it otherwise (passed to a
        function)."""
        if self.body is None or any(
                child.kind.is_expression() and (strip(child).kind != CursorKind.CALL_EXPR
                                                or written_arguments(strip(child)))
                for child in decl.get_children()):
            return None
        _ = self.writes  # the regions are read with the writes
        key, where = key_of(decl), at.extent.start.offset
        start = decl.extent.start.offset
        uses: set[int] = set()  # the places the body names the stream
        known: set[int] = set()  # those that are a write, an emptying or a read of it
        inner: set[tuple[int, int]] = set()  # the ``<<`` of a chain already taken
        # (place, written, its operands), written None for an emptying
        events: list[tuple[int, Parts | None, list[Cursor]]] = []
        loops: list[tuple[int, int]] = []  # the loops and lambdas ``at`` is in, not decl
        for node in _walk(self.body):
            offset = node.extent.start.offset
            if node.kind in _REPEATED and offset <= where <= node.extent.end.offset and not (
                    offset <= start <= node.extent.end.offset):
                loops.append((offset, node.extent.end.offset))
            if offset < start:
                continue
            if node.kind == CursorKind.DECL_REF_EXPR and node.referenced is not None and (
                    key_of(node.referenced) == key):
                uses.add(offset)
            elif node.kind == CursorKind.CALL_EXPR and node.spelling == "operator<<":
                span = (offset, node.extent.end.offset)
                if span in inner:
                    continue
                operands: list[Cursor] = []
                chain = node
                while True:
                    args = written_arguments(chain)
                    if len(args) != 2:
                        break
                    operands.insert(0, args[1])
                    left = strip(args[0])
                    if left.kind == CursorKind.CALL_EXPR and left.spelling == "operator<<":
                        inner.add((left.extent.start.offset, left.extent.end.offset))
                        chain = left
                        continue
                    if left.kind == CursorKind.DECL_REF_EXPR and left.referenced is not None \
                            and key_of(left.referenced) == key:
                        known.add(left.extent.start.offset)
                        events.append((offset, self._streamed(operands, depth)
                                       if offset < where else (), operands))
                    break
            elif node.kind == CursorKind.CALL_EXPR and node.spelling in ("str", "clear"):
                callee = next(iter(node.get_children()), None)
                target = first_operand(callee) if callee is not None and (
                    callee.kind == CursorKind.MEMBER_REF_EXPR) else None
                target = strip(target) if target is not None else None
                if target is None or target.kind != CursorKind.DECL_REF_EXPR or (
                        target.referenced is None or key_of(target.referenced) != key):
                    continue
                known.add(target.extent.start.offset)
                args = written_arguments(node)
                if node.spelling == "str" and args:
                    if self.string(args[0], depth + 1) != ("",):
                        return None  # a text that later writes overwrite
                    events.append((offset, None, []))
        if uses - known:
            return None  # given away, or changed otherwise (``ss.precision(3)``)
        for first, last in loops:
            inside = [offset for offset, _written, _ops in events if first <= offset <= last]
            if any(offset > where for offset in inside):
                return None  # written after ``at`` in the loop: read in the next turn
            if inside and not any(first <= offset < where for offset, written, _ops in events
                                  if written is None):
                return None  # what earlier turns wrote is still there
        events = sorted((event for event in events if event[0] < where),
                        key=lambda event: event[0])
        if any(first <= offset <= last and not first <= where <= last
               for offset, _written, _ops in events for first, last in self._regions):
            return None  # a write or an emptying that may not run before ``at``
        return [(written, ops) for _offset, written, ops in events]

    def _stream_text(self, decl: Cursor, at: Cursor, depth: int) -> Parts:
        """What ``ss.str()`` at ``at`` gives of the local string stream ``decl``
        (``_stream_events``): the text written since its last emptying; UNKNOWN where
        that is not known."""
        events = self._stream_events(decl, at, depth)
        if events is None:
            return UNKNOWN
        parts: Parts = ()
        for written, _ops in events:
            parts = () if written is None else parts + written
        return parts if parts else ("",)

    def stream_operands(self, call: Cursor) -> list[Cursor] | None:
        """The values written, in order, since its last emptying, to the local string
        stream whose ``str()`` the call ``call`` is (pddl_problem_generator's ``ss << "/"
        << knowledge_base << "/domain/name"; name = ss.str();``); None for any other
        call, or a stream whose text is not known."""
        children = list(call.get_children()) if call.kind == CursorKind.CALL_EXPR and (
            call.spelling == "str" and not written_arguments(call)) else []
        if not children or children[0].kind != CursorKind.MEMBER_REF_EXPR:
            return None
        objects = list(children[0].get_children())
        stream = _string_stream(objects[0]) if objects else None
        events = self._stream_events(stream, call, 0) if stream is not None else None
        if events is None:
            return None
        found: list[Cursor] = []
        for written, ops in events:
            found = [] if written is None else found + ops
        return found

    def _streamed(self, operands: list[Cursor], depth: int) -> Parts:
        """The text of values written to a string stream: a string's, an integer's
        digits; an unknown run for any other (a float, a manipulator)."""
        parts: Parts = ()
        for operand_ in operands:
            kind = operand_.type.get_canonical().kind
            if kind in _INTEGER_KINDS:
                number = self.integer(operand_, depth + 1)
                parts += (None,) if number is None else (str(number),)
            elif _textual(operand_):
                parts += self.string(operand_, depth + 1)
            else:
                parts += (None,)
        return parts

    def _returned(self, target: Cursor, read: Callable[[Scope, Cursor], Value]) -> Value | None:
        """What a getter without parameters gives (``read`` of its one ``return``'s
        expression, in each body a call of it may run: read in that method, its members
        as its class's constructors set them), when every body agrees; else None."""
        if self.sites is None:
            return None
        values = {read(self.sites.scope(method), value)
                  for value, method in self.sites.returns(target) or ()}
        return values.pop() if len(values) == 1 else None

    def given_return(self, target: Cursor, args: list[Cursor], depth: int) -> Parts | None:
        """The text a call of a function or method with parameters gives, whose body is
        one ``return`` (``std::string topic(const std::string& leaf) { return "arm/" +
        leaf; }``): its expression read in that body with each string parameter taken
        to hold the text of this call's argument for it (read here), as the call runs
        it. None when not such a function (virtual, several statements, an argument
        for each parameter not written: defaults, a pack), or the expression does not
        read as text."""
        found = self.sites.returns(target, given=True) if self.sites is not None else None
        if found is None:
            return None
        ((value, body),) = found
        params = [c for c in body.get_children() if c.kind == CursorKind.PARM_DECL]
        if len(params) != len(args) or any(
                c.kind == CursorKind.PACK_EXPANSION_EXPR for c in args):
            return None
        assert self.sites is not None
        scope = self.sites.scope(body)
        bound = {key_of(param): self.string(arg, depth + 1)
                 for param, arg in zip(params, args, strict=True) if _textual(param)}
        before = {key: scope.fixed[key] for key in bound if key in scope.fixed}
        scope.fixed.update(bound)  # (a call of it inside: read with its own arguments)
        try:
            return scope.string(value, depth + 1)
        finally:
            for key in bound:
                if key in before:
                    scope.fixed[key] = before[key]
                else:
                    scope.fixed.pop(key, None)

    def _unremapped(self, args: list[Cursor]) -> bool:
        """Whether roscpp's ``resolve(name, remap)`` / ``resolveName(name, remap)`` is
        told not to remap (its second argument false)."""
        return len(args) > 1 and self.boolean(args[1]) is False

    def _handle_resolved(self, call: Cursor, name: Cursor, depth: int) -> Parts:
        """``handle.resolveName(name)``: ``name`` in the namespace of the handle
        (``~image`` on a private one, ``motors/image`` on one in ``motors``), which
        ``CallSites.handle_namespace`` tells; unknown where it is not known."""
        handle = method_object(call)
        find = None if self.sites is None else self.sites.handle_namespace
        namespace = UNKNOWN if handle is None or find is None else find(handle, self)
        return join_parts(namespace, self.string(name, depth + 1))

    def _string_format(self, call: Cursor, target: Cursor, args: list[Cursor],
                       depth: int) -> Parts | None:
        """A string a formatting function makes (``formats``): {fmt}'s and std's
        ``format``, ``snprintf`` / ``sprintf`` (the text they write into their array,
        read where the array is: ``_keep``), a ``boost::format`` with its ``%``
        arguments (``boost::str(f)``; ``f.str()`` is read as ``.str()`` is) and
        ``std::to_string``: the format's text, each argument's value where it is
        known; unknown when the format is not known text. None for any other call."""
        name, space = target.spelling, _namespace_of(target)
        if name == "format" and space in ("fmt", "std") and args:
            return self._fill(formats.brace_pieces, args[0], args[1:], depth)
        if name in _PRINTERS and space in ("", "std") and len(args) > _PRINTERS[name]:
            at = _PRINTERS[name]
            return self._fill(formats.printf_pieces, args[at], args[at + 1:], depth)
        if name == "str" and space == "boost" and len(args) == 1:
            return self.string(args[0], depth + 1)
        if name == "to_string" and space == "std" and len(args) == 1:
            number = self.integer(args[0], depth + 1) if _integral(args[0]) else None
            return UNKNOWN if number is None else (str(number),)
        if name == "operator%" and len(args) == 2 and _boost_format(call):
            given: list[Cursor] = []
            made: Cursor | None = call
            while made is not None and made.kind == CursorKind.CALL_EXPR and (
                made.spelling == "operator%" and len(written_arguments(made)) == 2
            ):
                left, right = written_arguments(made)
                given.insert(0, right)
                made = _constructed(left)
            if made is None or made.kind != CursorKind.CALL_EXPR or not _boost_format(made):
                return UNKNOWN
            text = written_arguments(made)
            if len(text) != 1:
                return UNKNOWN
            return self._fill(formats.boost_pieces, text[0], given, depth)
        return None

    def _fill(self, split: Callable[[str], list[formats.Piece] | None], text: Cursor,
              given: list[Cursor], depth: int) -> Parts:
        """The value of a format (split into pieces by ``split``) with its holes
        filled from ``given``; unknown when the format is not text known here."""
        written = self.string(text, depth + 1)
        if not all(type(part) is str for part in written):
            return UNKNOWN
        joined = "".join(written)  # type: ignore[arg-type]
        if any(mark in joined for mark in _MARKS):
            return UNKNOWN
        pieces = split(joined)
        if pieces is None:
            return UNKNOWN
        found: list[str | None] = []
        for piece in pieces:
            if isinstance(piece, str):
                found.append(piece)
            elif piece.index >= len(given):
                return UNKNOWN  # more holes than arguments: the call fails
            else:
                found.extend(self._hole(given[piece.index], piece.conversion, depth))
        return tuple(found)

    def _hole(self, arg: Cursor, conversion: str, depth: int) -> Parts:
        """What a format's hole writes for ``arg``: a string as it is, an integer in
        the base the conversion says, anything else (or not known) unknown."""
        if conversion == formats.OTHER:
            return UNKNOWN
        if _integral(arg):
            number = self.integer(arg, depth + 1)
            text = None if number is None else formats.integer_text(number, conversion)
            return UNKNOWN if text is None else (text,)
        if conversion == formats.TEXT and _textual(arg):
            return self.string(arg, depth + 1)
        return UNKNOWN

    def resolved(self, cursor: Cursor, depth: int = 0) -> bool:
        """Whether the name ``cursor`` holds is one a node interface resolved and remapped
        (``_RESOLVERS``, not ``only_expand``), through variables and string copies."""
        cursor = strip(cursor)
        if depth > MAX_DEPTH:
            return False
        if cursor.kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
            decl = cursor.referenced
            value = None if decl is None else self.variable(decl)
            if value is None and decl is not None:
                found = self.field(decl)
                return found is not None and found[1].resolved(found[0], depth + 1)
            return value is not None and self.resolved(value, depth + 1)
        if cursor.kind != CursorKind.CALL_EXPR:
            return False
        args, target = written_arguments(cursor), cursor.referenced
        if target is None or (target.kind == CursorKind.CONSTRUCTOR and len(args) == 1):
            inner = operand(cursor) if target is None else args[0]
            return inner is not None and self.resolved(inner, depth + 1)
        only_expand = _resolver(target)
        return only_expand is not None and bool(args) and (
            only_expand >= len(args) or self.boolean(args[only_expand]) is False)

    def names_prefix(self, cursor: Cursor, depth: int = 0) -> str | None:
        """The relative name ``ros::names::resolve`` (or a handle's ``resolveName``, in
        the handle's namespace) resolved at the start of the name ``cursor`` holds
        (imu_tools' ``ros::names::resolve("imu") + "/data"``: ``imu``),
        through variables, string copies and ``+``; None when it starts otherwise."""
        cursor = strip(cursor)
        if depth > MAX_DEPTH:
            return None
        if cursor.kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
            decl = cursor.referenced
            value = None if decl is None else self.variable(decl)
            if value is None and depth == 0:
                # a member or a variable written more than once: the name it holds,
                # when that begins with a name roscpp resolved and remapped
                # (face_detector's ``camera_ = nh_.resolveName("camera")``)
                parts = self.string(cursor)
                written = str(parts[0]) if parts and isinstance(
                    parts[0], RemappedName) else ""
                return None if not written or written.startswith(("/", "~")) else (
                    written.rstrip("/"))
            return None if value is None else self.names_prefix(value, depth + 1)
        if cursor.kind != CursorKind.CALL_EXPR:
            return None
        args, target = written_arguments(cursor), cursor.referenced
        if cursor.spelling == "operator+" and len(args) == 2:
            return self.names_prefix(args[0], depth + 1)
        if target is None or (target.kind == CursorKind.CONSTRUCTOR and len(args) == 1):
            inner = operand(cursor) if target is None else args[0]
            return None if inner is None else self.names_prefix(inner, depth + 1)
        if len(args) == 1 and _ros_names(target, "clean"):  # the same start, slashes cleaned
            return self.names_prefix(args[0], depth + 1)
        if args and _handle_resolve(target):  # a handle's: in the handle's namespace
            written = render(self.string(cursor, depth + 1))
        elif not args or not _ros_names(target, "resolve"):
            return None
        else:
            written = render(self.string(args[0], depth + 1))
        if not written or "?" in written or written.startswith(("/", "~")):
            return None
        return written.rstrip("/")

    def integer(self, cursor: Cursor, depth: int = 0) -> int | None:
        if depth > MAX_DEPTH:
            return None
        cursor = strip(cursor)
        if cursor.kind == CursorKind.INTEGER_LITERAL:
            token = self.token(cursor)
            return self._int_token(token) if token else None
        if cursor.kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
            decl = cursor.referenced
            if decl is None:
                return None
            turn = self._turn(decl)
            if turn is not None:
                return turn
            if self.is_parameter(decl):
                return self.sites.agreed(  # type: ignore[union-attr]
                    decl, lambda arg, scope: scope.integer(arg, depth + 1), None)
            value = self.variable(decl)
            if value is None:
                found = self.field(decl)
                return None if found is None else found[1].integer(found[0], depth + 1)
            return self.integer(value, depth + 1)
        if cursor.kind == CursorKind.CALL_EXPR and cursor.referenced is not None and (
                not written_arguments(cursor)):
            # a getter (``RangeSource::depth()``), as for a string
            return self._returned(cursor.referenced,
                                  lambda scope, value: scope.integer(value, depth + 1))
        if cursor.kind == CursorKind.BINARY_OPERATOR:  # ``i + 1`` of known integers
            sides = [c for c in cursor.get_children() if c.kind.is_expression()]
            if len(sides) != 2:
                return None
            operator = _ARITHMETIC.get(binary_operator(cursor, sides) or "")
            if operator is None:
                return None
            left = self.integer(sides[0], depth + 1)
            right = self.integer(sides[1], depth + 1) if left is not None else None
            return None if left is None or right is None else operator(left, right)
        return None

    def _turn(self, decl: Cursor) -> int | None:
        """The value of the counting loop's variable ``decl`` for the turn being read
        (``bound``); None for any other variable."""
        return self.bound.get(key_of(decl)) if self.bound else None

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
        return integer_literal(token)

    def number(self, cursor: Cursor, depth: int = 0) -> int | float | None:
        """A number written as a literal (an integer's as ``integer``, a floating one's
        text, ``2.5``, ``1e-3``, ``0.5f``), signed (``-0.1``), or held by a variable or
        member that holds one; None otherwise."""
        if depth > MAX_DEPTH:
            return None
        cursor = strip(cursor)
        kind = cursor.kind
        if kind == CursorKind.INTEGER_LITERAL:
            return self.integer(cursor)
        if kind == CursorKind.FLOATING_LITERAL:
            where = cursor.extent
            text = self.source.get(where.start.file.name) if where.start.file else None
            if text is None or where.end.file is None or (
                    where.end.file.name != where.start.file.name):
                return None
            written = text[where.start.offset:where.end.offset].decode("ascii", "replace")
            match = _FLOAT.fullmatch(written.strip())
            return float(match.group(1)) if match else None
        if kind == CursorKind.UNARY_OPERATOR:
            children = list(cursor.get_children())
            if len(children) != 1:
                return None
            where = cursor.location.file
            head = self.source.get(where.name, b"")[
                cursor.extent.start.offset:children[0].extent.start.offset].strip() if (
                where is not None) else b""
            value = self.number(children[0], depth + 1)
            if value is None or head not in (b"-", b"+"):
                return None
            return -value if head == b"-" else value
        if kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
            decl = cursor.referenced
            turn = None if decl is None else self._turn(decl)
            if turn is not None:
                return turn
            if decl is None or self.is_parameter(decl):
                return None
            value = self.variable(decl)
            if value is None:
                found = self.field(decl)
                return None if found is None else found[1].number(found[0], depth + 1)
            return self.number(value, depth + 1)
        return None

    def boolean(self, cursor: Cursor) -> bool | None:
        cursor = strip(cursor)
        if cursor.kind == CursorKind.CXX_BOOL_LITERAL_EXPR:
            token = self.token(cursor) or ""
            token = self.macros.get(token, token)
            return {"true": True, "false": False}.get(token)
        if cursor.kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) and (
            cursor.referenced is not None
        ):
            value = self.variable(cursor.referenced)
            if value is None:  # a member: the value its constructor gives it
                found = self.field(cursor.referenced)
                return None if found is None else found[1].boolean(found[0])
            return self.boolean(value)
        return None


# what rclcpp leaves of argv once it has taken its own arguments (``--ros-args ...``)
ARGUMENTS_LEFT = frozenset({"init_and_remove_ros_arguments", "remove_ros_arguments"})
_ELEMENT = frozenset({"at", "operator[]"})


def program_argument(expr: Cursor | None, scope: Scope) -> int | None:
    """K when ``expr`` is the process's K-th command-line argument: ``args.at(K)`` or
    ``args[K]`` of a local that ``rclcpp::init_and_remove_ros_arguments(argc, argv)``
    (or ``remove_ros_arguments``) initialises, or ``argv[K]`` of ``main``, through the
    conversions to a parameter value; None otherwise. ``argv[argc - N]`` is -N when
    ``main`` has called ``ros::init(argc, argv, ...)`` before, as a statement of its
    own body: roscpp then has taken the ``:=`` words (roslaunch's remappings,
    ``__name:=``, ``__log:=``, which it puts after the launch file's ``args``) off
    ``argv`` and counted them out of ``argc``; before it, the last word is roslaunch's."""
    node = expr
    for _depth in range(8):  # conversions and ParameterValue(...) around the element
        if node is None:
            return None
        if node.kind == CursorKind.CALL_EXPR and node.spelling in _ELEMENT:
            break
        if node.kind == CursorKind.ARRAY_SUBSCRIPT_EXPR:
            break
        inner = [c for c in node.get_children() if c.kind.is_expression()]
        if len(inner) != 1:
            return None
        node = inner[0]
    else:
        return None
    parts = [c for c in node.get_children() if c.kind.is_expression()]
    if len(parts) < 2:
        return None
    holder = strip(parts[0])
    if holder.kind == CursorKind.MEMBER_REF_EXPR:  # args.at: the object is its child
        objects = [c for c in holder.get_children() if c.kind.is_expression()]
        holder = strip(objects[0]) if objects else holder
    variable = holder.referenced if holder.kind == CursorKind.DECL_REF_EXPR else None
    if variable is None:
        return None
    if variable.kind == CursorKind.PARM_DECL:  # argv of main(argc, argv)
        function = variable.semantic_parent
        params = [c for c in function.get_children() if c.kind == CursorKind.PARM_DECL] \
            if function is not None and function.spelling == "main" else []
        if len(params) < 2 or params[1] != variable:
            return None
        index = scope.integer(parts[-1])
        if index is None:
            index = _from_end(parts[-1], params[0], function, node, scope)
            return index if index is not None and -1000 < index < 0 else None
        return index if isinstance(index, int) and not isinstance(index, bool) and (
            0 < index < 1000) else None
    index = scope.integer(parts[-1])
    if not isinstance(index, int) or isinstance(index, bool) or not 0 < index < 1000:
        return None
    made = initializer(variable) if variable.kind == CursorKind.VAR_DECL else None
    calls = [] if made is None else [
        c for c in made.walk_preorder() if c.kind == CursorKind.CALL_EXPR
        and c.spelling in ARGUMENTS_LEFT]
    return index if calls else None


def _has_argument(test: Cursor, element: Cursor, index: int, scope: Scope) -> bool:
    """Whether ``test`` holds only when ``main``'s ``argv`` has the element ``index``
    that ``element`` reads: ``argc > N`` or ``argc >= N + 1`` (``N < argc``, ``N + 1 <=
    argc``) with N at least ``index``, ``argc`` the first parameter of the ``main`` whose
    ``argv`` that is."""
    test = strip(test)
    sides = [c for c in test.get_children() if c.kind.is_expression()]
    if test.kind != CursorKind.BINARY_OPERATOR or len(sides) != 2:
        return False
    operator = binary_operator(test, sides)
    left, right = strip(sides[0]), strip(sides[1])
    flipped = {"<": ">", "<=": ">="}
    if operator in flipped:
        operator, left, right = flipped[operator], right, left
    if operator not in (">", ">=") or left.kind != CursorKind.DECL_REF_EXPR:
        return False
    bound = scope.integer(right)
    if not isinstance(bound, int) or isinstance(bound, bool):
        return False
    argc = left.referenced
    function = argc.semantic_parent if argc is not None else None
    if function is None or function.spelling != "main" or argc.kind != CursorKind.PARM_DECL:
        return False
    params = [c for c in function.get_children() if c.kind == CursorKind.PARM_DECL]
    if len(params) < 2 or params[0] != argc or not any(
            c.kind == CursorKind.DECL_REF_EXPR and c.referenced == params[1]
            for c in element.walk_preorder()):
        return False
    return bound >= index if operator == ">" else bound >= index + 1


def _from_end(index: Cursor, argc: Cursor, main: Cursor, read: Cursor,
              scope: Scope) -> int | None:
    """-N for an index ``argc - N`` read after ``main``'s own ``ros::init(argc, argv,
    ...)`` statement (``program_argument``); None otherwise."""
    index = strip(index)
    sides = [c for c in index.get_children() if c.kind.is_expression()]
    if index.kind != CursorKind.BINARY_OPERATOR or len(sides) != 2 or (
        binary_operator(index, sides) != "-"
    ):
        return None
    counted, less = strip(sides[0]), scope.integer(sides[1])
    if counted.kind != CursorKind.DECL_REF_EXPR or counted.referenced != argc or (
        not isinstance(less, int) or isinstance(less, bool) or less < 1
    ):
        return None
    init = ros_init(main)
    return -less if init is not None and init.extent.end.offset < read.extent.start.offset \
        else None


MAX_BRANCH_VALUES = 16  # values a local written in each case of a switch may hold
_LEAVES: list[tuple[int, Cursor]] = []  # a path that leaves the function (``_path_writes``)
_Ends = list[tuple[int, Cursor]] | None


def _path_writes(statement: Cursor, placed: list[tuple[int, Cursor | None]]) -> _Ends:
    """The writes of a variable (``placed``: each one's offset and value) that end the
    paths through ``statement`` which go on after it, one per path, when every such
    path writes it last with a known value; ``_LEAVES`` when every path leaves the
    function (``return``, ``throw``); None when a path leaves it unwritten, or a write
    is not plainly one statement of a block, a side or a case."""
    kind = statement.kind
    if kind == CursorKind.IF_STMT:
        children = list(statement.get_children())
        if len(children) != 3 or children[0].kind == CursorKind.DECL_STMT:
            return None  # no ``else``, or ``if (init; test)``
        sides = [_path_writes(side, placed) for side in children[1:]]
        if any(side is None for side in sides):
            return None
        going = [side for side in sides if side is not _LEAVES]
        return [w for side in going for w in side or ()] if going else _LEAVES
    if kind == CursorKind.SWITCH_STMT:
        return _switch_writes(statement, placed)
    return _block_writes([statement], placed, False)


def _block_writes(statements: list[Cursor], placed: list[tuple[int, Cursor | None]],
                  in_case: bool) -> _Ends:
    """``_path_writes`` of statements run in order (a block; a case of a switch up to
    its ``break`` when ``in_case``)."""
    current: _Ends = None
    for statement in statements:
        kind = statement.kind
        if kind == CursorKind.COMPOUND_STMT:
            statement_ends = _block_writes(list(statement.get_children()), placed, in_case)
            if statement_ends is not None:
                current = statement_ends
                if current is _LEAVES:
                    return current
                continue
            if _inside(statement, placed):
                return None
            continue
        if kind == CursorKind.BREAK_STMT and in_case:
            return current
        if in_case and _breaks_within(statement):
            return None  # ``if (c) break;``: a path out of the case before its writes
        if kind in (CursorKind.IF_STMT, CursorKind.SWITCH_STMT) and _inside(statement, placed):
            current = _path_writes(statement, placed)
            if current is None or current is _LEAVES:
                return current
            continue
        if _leaves(statement):
            return _LEAVES
        inside = _inside(statement, placed)
        if not inside:
            continue
        value = inside[0][1] if len(inside) == 1 else None
        if value is None or not (kind.is_expression() or kind == CursorKind.UNEXPOSED_EXPR):
            return None
        current = [(inside[0][0], value)]
    return current


def _inside(statement: Cursor, placed: list[tuple[int, Cursor | None]]
            ) -> list[tuple[int, Cursor | None]]:
    low, high = statement.extent.start.offset, statement.extent.end.offset
    return [write for write in placed if low <= write[0] <= high]


def _switch_writes(switch: Cursor, placed: list[tuple[int, Cursor | None]]) -> _Ends:
    """``_path_writes`` of a ``switch``: each case's statements up to its ``break``
    (a case that falls into the next one: None); complete with a ``default`` label or
    when its value is an enumeration whose every enumerator is a label."""
    children = list(switch.get_children())
    if len(children) < 2 or children[-1].kind != CursorKind.COMPOUND_STMT:
        return None
    groups: list[list[Cursor]] = []
    labels: list[Cursor] = []
    default = False
    for statement in children[-1].get_children():
        if statement.kind not in (CursorKind.CASE_STMT, CursorKind.DEFAULT_STMT):
            if not groups:
                return None  # a statement before the first label
            groups[-1].append(statement)
            continue
        groups.append([])
        while statement.kind in (CursorKind.CASE_STMT, CursorKind.DEFAULT_STMT):
            inner = list(statement.get_children())
            if statement.kind == CursorKind.DEFAULT_STMT:
                default = True
            elif inner:
                labels.append(inner[0])
            if not inner:
                break
            statement = inner[-1]
        if statement.kind not in (CursorKind.CASE_STMT, CursorKind.DEFAULT_STMT):
            groups[-1].append(statement)
    if not default and not _every_enumerator(children[-2], labels):
        return None
    out: list[tuple[int, Cursor]] = []
    for index, group in enumerate(groups):
        ends = _block_writes(group, placed, True)
        if ends is None:
            return None
        if ends is _LEAVES:
            continue
        if not _stops(group) and index < len(groups) - 1:
            return None  # falls into the next case
        out.extend(ends)
    return out or _LEAVES


def _stops(group: list[Cursor]) -> bool:
    """Whether the statements of a case end it with a ``break`` (``case 1: { ...;
    break; }`` too)."""
    if any(s.kind == CursorKind.BREAK_STMT for s in group):
        return True
    return bool(group) and group[-1].kind == CursorKind.COMPOUND_STMT and _stops(
        list(group[-1].get_children()))


def _breaks_within(statement: Cursor) -> bool:
    """Whether a ``break`` inside ``statement`` (not a block of its own) may leave the
    ``switch`` around it: one not in a loop or ``switch`` of its own."""
    if statement.kind == CursorKind.COMPOUND_STMT:
        return False  # (read statement by statement)
    stack = list(statement.get_children())
    while stack:
        node = stack.pop()
        if node.kind == CursorKind.BREAK_STMT:
            return True
        if node.kind not in _LOOPS_AND_SWITCH:
            stack.extend(node.get_children())
    return False


_LOOPS_AND_SWITCH = frozenset({CursorKind.FOR_STMT, CursorKind.CXX_FOR_RANGE_STMT,
                               CursorKind.WHILE_STMT, CursorKind.DO_STMT,
                               CursorKind.SWITCH_STMT, CursorKind.LAMBDA_EXPR})


def _every_enumerator(value: Cursor, labels: list[Cursor]) -> bool:
    """Whether the switch's value ``value`` is of an enumeration each of whose
    enumerators is one of ``labels``."""
    declared = strip(value).type.get_canonical().get_declaration()
    if declared is None or declared.kind != CursorKind.ENUM_DECL:
        return False
    enumerators = {c.enum_value for c in declared.get_children()
                   if c.kind == CursorKind.ENUM_CONSTANT_DECL}
    named = set()
    for label in labels:
        node = strip(label)
        target = node.referenced if node.kind == CursorKind.DECL_REF_EXPR else None
        if target is None or target.kind != CursorKind.ENUM_CONSTANT_DECL:
            return False
        named.add(target.enum_value)
    return bool(enumerators) and enumerators <= named


def _leaves(statement: Cursor) -> bool:
    """Whether ``statement`` always ends in a ``return`` (or ``throw``)."""
    if statement.kind == CursorKind.COMPOUND_STMT:
        inner = list(statement.get_children())
        return bool(inner) and _leaves(inner[-1])
    if statement.kind == CursorKind.RETURN_STMT:
        return True
    return strip(statement).kind == CursorKind.CXX_THROW_EXPR


_SCALARS = frozenset({TypeKind.BOOL, TypeKind.INT, TypeKind.UINT, TypeKind.LONG,
                      TypeKind.ULONG, TypeKind.SHORT, TypeKind.USHORT, TypeKind.DOUBLE,
                      TypeKind.FLOAT, TypeKind.LONGLONG, TypeKind.ULONGLONG})
_SOURCE_SUFFIXES = (".c", ".cc", ".cpp", ".cxx", ".cu", ".h", ".hh", ".hpp", ".hxx", ".cuh")
MAX_PACKAGE_SOURCES = 400  # files of a package looked through for a global's writes
_WRITTEN_AFTER = re.compile(r"\s*(?:(?:[-+*/%&|^]|<<|>>)?=(?!=)|\+\+|--)")
_WRITTEN_BEFORE = re.compile(r"(?:\+\+|--|(?<!&)&|>>|,|\[|\{)\s*$")
# a parenthesis that opens no call: a test's, or an expression's after an operator
_READ_CALL = re.compile(
    r"(?:\b(?:if|while|switch|return|sizeof|decltype)\s*|[-+*/%<>=!&|^?:(]\s*)\($")


def unwritten_global(decl: Cursor) -> bool:
    """Whether ``decl`` is a variable of a namespace (not ``const``: a constant is one
    already) of a number or ``bool``, given a literal, that no source of its package
    writes after: every use of its name there is read as a value (not assigned, stepped,
    taken the address of, read into, nor given to a call, which may take it by
    reference). A debug switch of a research node (A-LOAM's ``bool PUB_EACH_LINE =
    false``, tested before its per-line publishers) is then decided, as a ``const`` one."""
    if decl.kind != CursorKind.VAR_DECL or decl.type.kind not in _SCALARS:
        return False
    parent = decl.semantic_parent
    if parent is None or parent.kind not in (CursorKind.TRANSLATION_UNIT,
                                             CursorKind.NAMESPACE):
        return False
    definition = decl.get_definition()
    if definition is None or definition.location.file is None:
        return False
    value = initializer(definition)
    if value is None or strip(value).kind not in (
            CursorKind.CXX_BOOL_LITERAL_EXPR, CursorKind.INTEGER_LITERAL,
            CursorKind.FLOATING_LITERAL):
        return False
    path = os.path.abspath(definition.location.file.name)
    root = _package_root(os.path.dirname(path))
    if root is None:
        return False
    CONSULTED.add(root)
    key = (path, definition.spelling, definition.location.offset)
    if key not in _UNWRITTEN:
        _UNWRITTEN[key] = _unwritten(path, definition.spelling, definition.location.offset,
                                     root)
    return _UNWRITTEN[key]


# the package folders ``unwritten_global`` looked through for the unit being read: its
# result depends on their sources, which its cache entry lists (``package_sources``);
# and its answers, both forgotten when the next unit is read (``forget_globals``: a
# file may have changed since)
CONSULTED: set[str] = set()
_UNWRITTEN: dict[tuple[str, str, int], bool] = {}
_SOURCES: dict[str, tuple[str, ...]] = {}


def forget_globals() -> None:
    CONSULTED.clear()
    _UNWRITTEN.clear()
    _SOURCES.clear()


def _unwritten(path: str, name: str, offset: int, root: str) -> bool:
    from ...ctext import code_only

    sources = package_sources(root)
    if path not in sources:
        return False  # (a package too large to look through, or a file not in it)
    word = re.compile(r"(?<![\w.:>])" + re.escape(name) + r"\b")
    for source in sources:
        try:
            with open(source, encoding="utf-8", errors="replace") as handle:
                text = code_only(handle.read())
        except OSError:
            return False
        own = os.path.abspath(source) == os.path.abspath(path)
        for found in word.finditer(text):
            if own and found.start() == offset:
                continue  # the definition
            before = text[max(0, found.start() - 80):found.start()]
            if (_WRITTEN_AFTER.match(text, found.end()) or _WRITTEN_BEFORE.search(before)
                    or (before.rstrip().endswith("(")
                        and not _READ_CALL.search(before.rstrip()))
                    or text[found.end():found.end() + 1] == "("):
                return False
    return True


@functools.lru_cache(maxsize=64)
def _package_root(folder: str) -> str | None:
    """The nearest folder at or above ``folder`` with a package.xml."""
    while True:
        if os.path.isfile(os.path.join(folder, "package.xml")):
            return folder
        parent = os.path.dirname(folder)
        if parent == folder:
            return None
        folder = parent


def package_sources(root: str) -> tuple[str, ...]:
    """The C, C++ and CUDA files under a package's folder (not hidden, build or install
    ones); none when there are more than ``MAX_PACKAGE_SOURCES``."""
    if root not in _SOURCES:
        _SOURCES[root] = _package_sources(root)
    return _SOURCES[root]


def _package_sources(root: str) -> tuple[str, ...]:
    found: list[str] = []
    for path in package_files(root):
        if path.endswith(_SOURCE_SUFFIXES):
            found.append(os.path.abspath(path))
            if len(found) > MAX_PACKAGE_SOURCES:
                return ()
    return tuple(found)


def _template_initializer(decl: Cursor) -> Cursor | None:
    """The default member initialiser of a const member of a class template's
    specialisation, which the parse does not instantiate where nothing builds the class:
    the template's own member's (filters' ``FilterBase<T>::param_prefix_``, a base of a
    workspace filter)."""
    parent = decl.semantic_parent
    if decl.kind != CursorKind.FIELD_DECL or parent is None:
        return None
    template = conf.lib.clang_getSpecializedCursorTemplate(parent)
    if template is None or template.kind == CursorKind.NO_DECL_FOUND:
        return None
    owner = template.get_definition() or template
    field = next((c for c in owner.get_children()
                  if c.kind == CursorKind.FIELD_DECL and c.spelling == decl.spelling), None)
    return initializer(field) if field is not None else None


def _const_reference(decl: Cursor) -> bool:
    """A variable that is a reference to const (``const std::string &TOPIC = "/scan";``:
    f1tenth_ws' scan matching node): it is never rebound, and what it is bound to, a
    temporary its initialiser made or another variable, is read through it as a
    constant is."""
    ctype = decl.type
    return decl.kind == CursorKind.VAR_DECL and ctype.kind in (
        TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE) and (
        ctype.get_pointee().is_const_qualified())


def _string_constant(decl: Cursor) -> bool:
    """``static const char* kTopic = "x";`` outside functions: the usual way to write a
    name constant, whose pointer is not const but is not written either."""
    parent = decl.semantic_parent
    if parent is None or parent.kind not in (CursorKind.NAMESPACE, CursorKind.TRANSLATION_UNIT):
        return False
    ctype = decl.type.get_canonical()
    return ctype.kind == TypeKind.POINTER and ctype.get_pointee().is_const_qualified() and (
        ctype.get_pointee().get_canonical().kind in (TypeKind.CHAR_S, TypeKind.CHAR_U))


def _within(inner: Cursor, outer: Cursor) -> bool:
    """Whether ``inner``'s text is inside ``outer``'s, in the same file."""
    one, other = inner.extent, outer.extent
    return one.start.file is not None and other.start.file is not None and (
        one.start.file.name == other.start.file.name
        and other.start.offset <= one.start.offset <= one.end.offset <= other.end.offset)


def is_own_member(target: Cursor) -> bool:
    """A member of this object named as it is (``member_``, ``this->member_``)."""
    decl = target.referenced if target.kind == CursorKind.MEMBER_REF_EXPR else None
    return decl is not None and decl.kind == CursorKind.FIELD_DECL and all(
        strip(c).kind == CursorKind.CXX_THIS_EXPR for c in target.get_children())


def _namespace_kept(decl: Cursor, write: Write, source: dict[str, bytes],
                    depth: int = 0) -> bool:
    """Whether ``write``, a call that may change roscpp handle ``decl`` in place, keeps
    its namespace: a method of the handle (none changes it: only a construction or an
    assignment does, whole writes), or a function given it by non-const reference whose
    body (read here) neither assigns that parameter nor hands it on to a call that may
    (ros_deep_learning's ``__ros_declare_parameter(ros::NodeHandle& nh, name, value)``,
    which only reads through it: ``hasParam``, ``setParam``). Anything else may."""
    call = write.at
    if call.kind != CursorKind.CALL_EXPR or depth > MAX_CALLEE_DEPTH or not _is_node_handle(
            decl):
        return False
    target = call.referenced
    if target is None:
        return False
    if target.kind == CursorKind.CXX_METHOD and qualified_name(
            target.semantic_parent) == api.NODE_HANDLE:
        return True
    args = list(call.get_arguments())
    index = next((i for i, arg in enumerate(args)
                  if arg == write.target or strip(arg) == write.target), None)
    body = target.get_definition()
    if index is None or body is None:
        return False
    params = [c for c in body.get_children() if c.kind == CursorKind.PARM_DECL]
    if index >= len(params):
        return False
    parameter = key_of(params[index])
    for inner in writes_in(body, source):
        variable = inner.variable
        if variable is None or key_of(variable) != parameter:
            continue
        if inner.whole or not _namespace_kept(params[index], inner, source, depth + 1):
            return False
    return True


MAX_CALLEE_DEPTH = 3  # calls handing a handle on, each read for what it does with it


def _is_node_handle(decl: Cursor) -> bool:
    """A variable or parameter that is a roscpp ``ros::NodeHandle`` (or a reference to
    one)."""
    ctype = decl.type.get_canonical()
    if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        ctype = ctype.get_pointee().get_canonical()
    return ctype.kind == TypeKind.RECORD and qualified_name(
        ctype.get_declaration()) == api.NODE_HANDLE


def _plain_value(decl: Cursor) -> bool:
    """True for variables of a builtin or string type, the values we resolve."""
    ctype = decl.type.get_canonical()
    if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        ctype = ctype.get_pointee().get_canonical()
    return ctype.kind != TypeKind.RECORD or ctype.get_declaration().spelling == "basic_string"


# statements whose parts may not run, or run later, when the body runs through them
_BRANCHING = frozenset({
    CursorKind.IF_STMT, CursorKind.FOR_STMT, CursorKind.CXX_FOR_RANGE_STMT,
    CursorKind.WHILE_STMT, CursorKind.DO_STMT, CursorKind.SWITCH_STMT, CursorKind.CASE_STMT,
    CursorKind.DEFAULT_STMT, CursorKind.CXX_CATCH_STMT, CursorKind.LAMBDA_EXPR,
})


# statements whose body may run again, or later (a lambda, when it is called)
_REPEATED = frozenset({CursorKind.FOR_STMT, CursorKind.CXX_FOR_RANGE_STMT,
                       CursorKind.WHILE_STMT, CursorKind.DO_STMT, CursorKind.LAMBDA_EXPR})


_WHOLE_REGIONS = frozenset({CursorKind.CASE_STMT, CursorKind.DEFAULT_STMT,
                            CursorKind.CXX_CATCH_STMT, CursorKind.LAMBDA_EXPR})


# the integer operators ``integer`` reads (``to_string(i + 1)``)
_ARITHMETIC: dict[str, Callable[[int, int], int]] = {
    "+": lambda a, b: a + b, "-": lambda a, b: a - b, "*": lambda a, b: a * b}


def key_of(decl: Cursor) -> tuple[str, int]:
    """What tells declaration ``decl`` from the unit's others: its file and offset (a
    lambda and its ``operator()`` are one, a constructor and its template's too), and a
    variable's name, as every variable a macro's expansion declares is at the
    expansion's place (ros_deep_learning's ``ROS_CREATE_NODE(name)`` declares ``nh`` and
    ``private_nh`` at one offset: the two were one variable, written twice)."""
    where = decl.location
    place = where.key if type(where) is _Place else (
        where.file.name if where.file else "", where.offset)
    if decl.kind not in VARIABLES:
        return place
    facts = decl.__dict__
    found: tuple[str, int] | None = facts.get("_key")
    if found is None:
        found = facts["_key"] = (f"{place[0]}\0{decl.spelling}", place[1])
    return found


# the declarations of variables: locals, members and parameters
VARIABLES = frozenset({CursorKind.VAR_DECL, CursorKind.FIELD_DECL, CursorKind.PARM_DECL})


# the standard algorithms that call their last argument with each element of a range in
# turn (all of them, or up to the first that decides)
_ELEMENT_ALGORITHMS = frozenset(("all_of", "any_of", "none_of", "for_each", "find_if",
                                 "find_if_not", "count_if"))


def _range_end(expr: Cursor) -> tuple[str, Cursor] | None:
    """(``begin`` or ``end``, the object) of ``list.begin()`` / ``std::end(list)``."""
    expr = strip(expr)
    if expr.kind != CursorKind.CALL_EXPR:
        return None
    args = written_arguments(expr)
    if len(args) == 1 and not any(c.kind == CursorKind.MEMBER_REF_EXPR
                                  for c in expr.get_children()):
        return expr.spelling, args[0]  # std::begin(list)
    if args:
        return None
    member = next((c for c in expr.get_children() if c.kind == CursorKind.MEMBER_REF_EXPR),
                  None)
    objects = [c for c in member.get_children() if c.kind.is_expression()] if (
        member is not None) else []
    return (expr.spelling, objects[0]) if objects else None


def _named(expr: Cursor) -> tuple[tuple[str, int], ...] | None:
    """The variable or member chain an expression names (``params_.controller_ids``:
    the two declarations' places), None for any other expression."""
    found: list[tuple[str, int]] = []
    expr = strip(expr)
    while expr.kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
        decl = expr.referenced
        if decl is None:
            return None
        found.append(key_of(decl))
        inner = [c for c in expr.get_children() if c.kind.is_expression()]
        if expr.kind == CursorKind.DECL_REF_EXPR or not inner:
            return tuple(found)  # a variable, or a member of ``this``
        expr = strip(inner[0])
    return tuple(found) if found and expr.kind == CursorKind.CXX_THIS_EXPR else None


# the integer types whose value a stream writes as its digits (not bool, nor the
# character types)
_INTEGER_KINDS = frozenset({TypeKind.SHORT, TypeKind.USHORT, TypeKind.INT, TypeKind.UINT,
                            TypeKind.LONG, TypeKind.ULONG, TypeKind.LONGLONG,
                            TypeKind.ULONGLONG})
_STRING_STREAMS = frozenset({"stringstream", "ostringstream", "basic_stringstream",
                             "basic_ostringstream"})


def _string_stream(cursor: Cursor) -> Cursor | None:
    """The local variable ``cursor`` names when it is a standard string stream that can
    be written (``std::stringstream``, ``std::ostringstream``)."""
    cursor = strip(cursor)
    decl = cursor.referenced if cursor.kind == CursorKind.DECL_REF_EXPR else None
    if decl is None or decl.kind != CursorKind.VAR_DECL:
        return None
    declared = decl.type.get_canonical().get_declaration()
    if declared.spelling not in _STRING_STREAMS or _namespace_of(declared) != "std":
        return None
    return decl


def _walk(cursor: Cursor) -> Iterator[Cursor]:
    """The cursor, then the walk of each of its children from the last to the first (a
    unit's node keeps it: ``Node.walk_last_first``)."""
    if type(cursor) is Node:
        return cursor.walk_last_first()
    return _stack_walk(cursor)


def _stack_walk(cursor: Cursor) -> Iterator[Cursor]:
    stack = [cursor]
    while stack:
        node = stack.pop()
        yield node
        stack.extend(node.get_children())


def literal(spelling: str) -> str | None:
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


def char_literal(spelling: str) -> str | None:
    """The character of a plain C character literal as clang spells it (``'.'``,
    ``'\\n'``), or None (a wide, multi-character or numeric-escape literal)."""
    if len(spelling) < 3 or not spelling.startswith("'") or not spelling.endswith("'"):
        return None
    body = spelling[1:-1]
    if len(body) == 1 and body != "\\":
        return body
    if len(body) == 2 and body[0] == "\\" and body[1] in _ESCAPES:
        return _ESCAPES[body[1]]
    return None


# the C functions that print into an array, with the index of their format argument
_PRINTERS = {"snprintf": 2, "sprintf": 1}


def _printed(write: Write) -> bool:
    """A write of an array by ``snprintf`` / ``sprintf`` into it (its first argument)."""
    call, target = write.at, write.target
    if call.kind != CursorKind.CALL_EXPR or call.spelling not in _PRINTERS or (
        target.kind != CursorKind.DECL_REF_EXPR or call.referenced is None
        or _namespace_of(call.referenced) not in ("", "std")
    ):
        return False
    args = written_arguments(call)
    return len(args) > _PRINTERS[call.spelling] and strip(args[0]) == target
# the parts a formatted value cannot hold in its format: placeholders, choices
_MARKS = (PLACEHOLDER, SEPARATOR, CHOICE, CHOICE_SEP, CHOICE_END, BACKREF)
_INTEGRAL = frozenset({
    TypeKind.SCHAR, TypeKind.UCHAR, TypeKind.SHORT, TypeKind.USHORT, TypeKind.INT,
    TypeKind.UINT, TypeKind.LONG, TypeKind.ULONG, TypeKind.LONGLONG, TypeKind.ULONGLONG})
_CHARS = (TypeKind.CHAR_S, TypeKind.CHAR_U)


def _namespace_of(target: Cursor) -> str | None:
    """The outermost namespace ``target`` is declared in ("" at file scope; {fmt}'s
    inline ``fmt::v10`` is ``fmt``); None for a member of a class."""
    parent, found = target.semantic_parent, ""
    while parent is not None and parent.kind != CursorKind.TRANSLATION_UNIT:
        if parent.kind == CursorKind.NAMESPACE:
            found = parent.spelling
        elif parent.kind not in (CursorKind.LINKAGE_SPEC, CursorKind.UNEXPOSED_DECL):
            return None  # (C's functions are in ``extern "C"``)
        parent = parent.semantic_parent
    return found


def _value_type(arg: Cursor) -> Any:
    ctype = strip(arg).type.get_canonical()
    if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        ctype = ctype.get_pointee().get_canonical()
    return ctype


def _integral(arg: Cursor) -> bool:
    """An integer argument (not a character, a bool or an enum)."""
    return bool(_value_type(arg).kind in _INTEGRAL)


def _textual(arg: Cursor) -> bool:
    """A string argument: characters by pointer or array, ``std::string``, a view."""
    ctype = _value_type(arg)
    if ctype.kind == TypeKind.POINTER:
        return bool(ctype.get_pointee().get_canonical().kind in _CHARS)
    if ctype.kind in (TypeKind.CONSTANTARRAY, TypeKind.INCOMPLETEARRAY):
        return bool(ctype.element_type.get_canonical().kind in _CHARS)
    return ctype.kind == TypeKind.RECORD and ctype.get_declaration().spelling in (
        "basic_string", "basic_string_view", "string_view")


def _boost_format(call: Cursor) -> bool:
    """Whether ``call`` makes a ``boost::format``: its constructor, or its ``%``."""
    declaration = call.type.get_canonical()
    if declaration.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        declaration = declaration.get_pointee().get_canonical()
    made = declaration.get_declaration()
    return made.spelling == "format" and _namespace_of(made) == "boost"


def _constructed(expr: Cursor) -> Cursor | None:
    """``expr`` without the casts and temporaries around a construction or a call
    (``boost::format("%s/x")`` is a functional cast around its constructor)."""
    for _depth in range(8):
        expr = strip(expr)
        if expr.kind == CursorKind.CALL_EXPR:
            return expr
        inner = [c for c in expr.get_children() if c.kind.is_expression()]
        if len(inner) != 1:
            return None
        expr = inner[0]
    return None


# rclcpp's functions that give the node's own name (``get_name`` without its namespace,
# ``get_fully_qualified_name`` with), declared by a node class or its base interface
_ROS1_NAME_OWNERS = frozenset({"ros::this_node", "nodelet::Nodelet"})
_NODE_NAME_FUNCTIONS = frozenset({"get_name", "get_fully_qualified_name"})
_NODE_NAME_OWNERS = frozenset({*api.RCLCPP_NODES, "rclcpp::node_interfaces::NodeBaseInterface"})


# a node's methods that make a publisher or subscription of the name they are given first
_TOPIC_MAKERS = frozenset({"create_publisher", "create_subscription"})
_TOPIC_HOLDERS = frozenset({"rclcpp::PublisherBase", "rclcpp::SubscriptionBase"})


def _known_text(part: str | None) -> bool:
    return part is not None and type(part) is str and PLACEHOLDER not in part and (
        CHOICE not in part)


def _names_node(target: Cursor) -> bool:
    """Whether calling ``target`` gives the name of the node the code runs as."""
    return target.spelling in _NODE_NAME_FUNCTIONS and target.semantic_parent is not None and (
        qualified_name(target.semantic_parent) in _NODE_NAME_OWNERS)
