"""Source conditions decided per node instance, from its parameters and arguments.

A call under ``if (publish_acceleration_)`` exists in a configuration exactly when the
condition holds there. The condition is decided when every name it uses has a value
this instance gives it:

- a member variable (C++ ``x_`` or ``this->x_``, Python ``self.x``) that one parameter
  read stores into (``PrimitiveCall.variable``; of
  the same file, else of any file of the node), or a local of the condition's function
  written once by a parameter read (``Condition.parameters``): the value the configuration gives the
  parameter (the launch files', with no launch condition and no node setting it), else
  the read's default (a ROS 2 read without one: the node's declarations of the
  parameter); a value whose type is not the read's is not used (roscpp would keep the
  default, rclcpp would refuse it);
- a constant of the code (``Condition.constants``: a ``const`` integer or bool
  initialised by a literal) is its value;
- ``argc`` / ``argv`` of a condition in ``main`` (``Condition.program_args``) of a
  ROS 1 instance whose ``args`` are known: roslaunch starts it with its ``args`` words,
  its remappings, ``__name:=`` and ``__log:=``, and ``ros::init`` removes the ``:=``
  words; the condition is decided only when both views of ``argv`` give one answer,
  or by the one it sees when it is tested before or after main's ``ros::init``
  (``Condition.after_init``: republish's ``if (argc < 3)``, after it, with one word);
- the local of ``main`` that keeps what rclcpp leaves of the arguments
  (``Condition.args_left``: ``args.size()``, ``args.at(1) == "messages"``) of an
  instance whose ``args`` are known: its words outside ``--ros-args`` sections.

The C++ text is read by a small grammar (``||``, ``&&``, ``!``, comparisons,
parentheses, literals, names, ``argv[N]``, ``x.size()`` / ``x.empty()`` / ``x.at(N)``,
``std::string(..)``); anything else leaves it
undecided, as do names with no value. The expression is then computed by the one safe
evaluator (``haros_arch.evaluate``). A link whose condition is false does not exist in
this configuration: it is dropped, with a CONDITION_FALSE info that says which call and
why; conditions decided true are taken off the link (it is unconditional there);
undecided ones stay as they are.
"""

from __future__ import annotations

import functools
import re
import shlex
from collections.abc import Callable
from typing import Any

from .. import diagnostics as diag
from ..evaluate.python import KeyAttributes, evaluate, is_unknown
from ..launch.ros2.naming import split_arguments
from ..model.conditions import EACH_STATEMENT, PARAMETER_VALUE, Condition
from ..model.location import Location
from ..model.rosname import RosName, own_unknown, pattern_for
from ..model.runtime import Configuration, Link, NodeInstance, Parameter
from ..model.source import COUNTED, NUMBERED, WORDS
from ..model.values import UNKNOWN_MARK, Unknown

DECIDED_STATEMENTS = ("if", "else", "switch")
MAX_TEXT = 1000  # longer condition texts are left undecided
_TOKEN = re.compile(r"""\s*(?:
    (?P<string>"[^"\\\n]*"|'[^'\\\n]*')
  | (?P<number>\d+(?:\.\d+)?)(?![\w.])
  | (?P<name>this\s*->\s*[A-Za-z_]\w*|self\s*\.\s*[A-Za-z_]\w*
             |[A-Za-z_]\w*(?:\s*::\s*[A-Za-z_]\w*)*)
  | (?P<op>&&|\|\||==|!=|<=|>=|->|,|[!<>()\[\].])
)""", re.X)
_KEYWORDS = {"true": "True", "false": "False"}
_ALTERNATIVE = {"and": "&&", "or": "||", "not": "!"}
_CPP_WORDS = {"default", "case", "sizeof", "new", "delete", "nullptr", "NULL", "this",
              "static_cast", "dynamic_cast", "reinterpret_cast", "const_cast", "auto",
              "const", "int", "bool", "double", "float", "char", "long", "unsigned"}
_PYTHON_WORDS = {"True", "False", "None", "and", "or", "not", "in", "is", "if", "else",
                 "lambda", "for", "import", "def", "class", "return", "yield", "await"}


class _Grammar:
    """C++ condition text -> a fully parenthesised Python expression, or None."""

    def __init__(self, text: str) -> None:
        self.tokens: list[tuple[str, str]] = []
        self.names: set[str] = set()
        at = 0
        text = text.strip()
        while at < len(text):
            found = _TOKEN.match(text, at)
            if found is None or found.end() == at:
                raise ValueError(text[at:at + 20])
            kind = found.lastgroup or ""
            value = found.group(kind)
            if kind == "name":
                # a member: C++'s ``this->x``, Python's ``self.x``
                value = re.sub(r"\s+", "", value).removeprefix("this->").removeprefix("self.")
                if value in _ALTERNATIVE:
                    kind, value = "op", _ALTERNATIVE[value]
            self.tokens.append((kind, value))
            at = found.end()
        self.at = 0

    def parse(self) -> str:
        out = self._binary(0)
        if self.at != len(self.tokens):
            raise ValueError("trailing text")
        return out

    _LEVELS = (("||",), ("&&",), ("==", "!="), ("<", ">", "<=", ">="))
    _PYTHON = {"||": "or", "&&": "and"}

    def _peek(self) -> tuple[str, str]:
        return self._ahead(0)

    def _ahead(self, count: int) -> tuple[str, str]:
        at = self.at + count
        return self.tokens[at] if at < len(self.tokens) else ("", "")

    def _take(self, value: str) -> None:
        if self._peek() != ("op", value):
            raise ValueError(f"expected {value}")
        self.at += 1

    def _binary(self, level: int) -> str:
        if level == len(self._LEVELS):
            return self._unary()
        left = self._binary(level + 1)
        while self._peek()[0] == "op" and self._peek()[1] in self._LEVELS[level]:
            operator = self._peek()[1]
            self.at += 1
            right = self._binary(level + 1)
            left = f"({left} {self._PYTHON.get(operator, operator)} {right})"
        return left

    def _unary(self) -> str:
        if self._peek() == ("op", "!"):
            self.at += 1
            return f"(not {self._unary()})"
        return self._primary()

    def _primary(self) -> str:
        kind, value = self._peek()
        self.at += 1
        if kind in ("string", "number"):
            return value
        if (kind, value) == ("op", "("):
            inner = self._binary(0)
            self._take(")")
            return inner
        if kind != "name":
            raise ValueError(value)
        if value in _KEYWORDS:
            return _KEYWORDS[value]
        if value == "std::string":  # std::string(x): the text of x
            self._take("(")
            inner = self._binary(0)
            self._take(")")
            return inner
        if value == "get_parameter" and self._peek() == ("op", "("):
            return self._parameter()
        if value in _PRESENCE_FUNCTIONS and self._peek() == ("op", "("):
            return self._presence(_PRESENCE_FUNCTIONS[value])
        if value == "len" and self._peek() == ("op", "("):  # Python's len(x)
            self.at += 1
            inner = self._binary(0)
            self._take(")")
            return f"len({inner})"
        value = self._program_arguments(value)
        if self._peek() in (("op", "."), ("op", "->")):
            presence = self._handle_presence()
            if presence is not None:
                return presence
        if "::" in value or "__" in value or value in _PYTHON_WORDS or (
            value in _CPP_WORDS or self._peek() == ("op", "(")
        ):
            raise ValueError(value)  # a qualified name or a call: not read
        self.names.add(value)
        if self._peek() == ("op", ".") and self._ahead(1) == ("name", "value") and (
                self._ahead(2) != ("op", "(")):
            self.at += 2  # a Python parameter object's value (``PARAMETER_VALUE``)
            return f"{value}{PARAMETER_VALUE}"
        if self._peek() == ("op", "."):  # a container's size() / empty() / at(N)
            self.at += 1
            kind, method = self._peek()
            self.at += 1
            self._take("(")
            if kind == "name" and method in ("size", "length", "empty"):
                self._take(")")
                return f"len({value})" if method != "empty" else f"(len({value}) == 0)"
            if (kind, method) != ("name", "at"):
                raise ValueError(method)
            number = self._number()
            self._take(")")
            return f"{value}[{number}]"
        if self._peek() == ("op", "["):
            self.at += 1
            number = self._number()
            self._take("]")
            return f"{value}[{number}]"
        return value

    def _program_arguments(self, value: str) -> str:
        """Python's ``sys.argv`` and rospy's ``rospy.myargv()`` as names of their own
        (``PYTHON_ARGV``, ``PYTHON_MYARGV``); any other name as it is."""
        if value == "sys" and self._peek() == ("op", ".") and self._ahead(1) == (
                "name", "argv"):
            self.at += 2
            return PYTHON_ARGV
        if value == "rospy" and self._peek() == ("op", ".") and self._ahead(1) == (
                "name", "myargv") and self._ahead(2) == ("op", "(") and self._ahead(3) == (
                "op", ")"):
            self.at += 4
            return PYTHON_MYARGV
        return value

    def _number(self) -> str:
        """An index, as written: only a number is read."""
        kind, number = self._peek()
        if kind != "number":
            raise ValueError("index")
        self.at += 1
        return number

    def _handle_presence(self) -> str | None:
        """``nh.getParam("x", v)`` / ``nh_param->hasParam("x")`` (through members:
        ``pimpl_->nh.getParam``): whether roscpp finds the parameter; None (nothing
        taken) for any other member use."""
        start = self.at
        while self._peek() in (("op", "."), ("op", "->")):
            self.at += 1
            kind, method = self._peek()
            self.at += 1
            if kind != "name":
                break
            if method in _PRESENCE_METHODS and self._peek() == ("op", "("):
                return self._presence(_PRESENCE_METHODS[method])
        self.at = start
        return None

    def _presence(self, kind: str) -> str:
        """The call's parameter name (a string literal, first) as a name of its own;
        the other arguments (the variable getParam writes) are passed over."""
        self._take("(")
        literal, text = self._peek()
        self.at += 1
        if literal == "name" and self._peek() in (("op", ","), ("op", ")")):
            # a variable's name (``old_h.hasParam(name)``): the test the code makes
            # where it makes the call the condition guards (``presence_value``)
            text = f'"{VARIABLE_MARK}{text}"'
        elif literal != "string":
            raise ValueError("parameter name")
        depth = 0
        while depth or self._peek() != ("op", ")"):
            token = self._peek()
            if token == ("", ""):
                raise ValueError("unclosed call")
            depth += {("op", "("): 1, ("op", ")"): -1}.get(token, 0)
            self.at += 1
        self._take(")")
        name = _encoded(f"{PRESENCE_PREFIX}{kind}_", text)
        self.names.add(name)
        return name

    def _parameter(self) -> str:
        """rclcpp's ``get_parameter("name").as_bool()`` (``as_int``, ``as_double``,
        ``as_string``): the node's parameter, as a name of its own (``parameter_name``)."""
        self._take("(")
        kind, text = self._peek()
        self.at += 1
        if kind != "string":
            raise ValueError("parameter name")
        self._take(")")
        self._take(".")
        kind, method = self._peek()
        self.at += 1
        if kind != "name" or method not in _PARAMETER_VALUES:
            raise ValueError(method)
        self._take("(")
        self._take(")")
        name = _encoded(PARAMETER_PREFIX, text)
        self.names.add(name)
        return name


# a Python program's ``sys.argv`` (every word it was started with: roslaunch's ``:=`` words
# too, as rospy leaves them there) and what ``rospy.myargv()`` leaves of it, anywhere in
# its code (fetchit_challenge's schunk_machine_server serves its action only ``if
# len(sys.argv) > 1``, and its launch file gives it ``args="simulated"``)
PYTHON_ARGV = "haros_sys_argv"
PYTHON_MYARGV = "haros_myargv"


# the typed values of an rclcpp Parameter a condition reads
_PARAMETER_VALUES = frozenset({"as_bool", "as_int", "as_double", "as_string"})
PARAMETER_PREFIX = "haros_parameter_"


# roscpp's tests of a parameter's presence: ``getParam`` (true when it is there and its
# value converts to the variable's type) and ``hasParam``, on a handle or ros::param;
# rospy's ``rospy.has_param``
_PRESENCE_METHODS = {"getParam": "get", "hasParam": "has", "getParamCached": "get",
                     "has_param": "has"}
_PRESENCE_FUNCTIONS = {"ros::param::get": "get", "ros::param::has": "has",
                       "ros::param::getCached": "get"}
PRESENCE_PREFIX = "haros_presence_"
# the start of a presence test's parameter written as a variable, not a literal
VARIABLE_MARK = "\x00"


def presence_name(name: str) -> tuple[str, str] | None:
    """(``get`` or ``has``, the parameter as written) a grammar name stands for
    (``nh.getParam("x", v)``), else None."""
    if not name.startswith(PRESENCE_PREFIX):
        return None
    kind, _, encoded = name[len(PRESENCE_PREFIX):].partition("_")
    written = _decoded(encoded)
    return None if written is None else (kind, written)


def _private_form(name: str) -> str:
    """A private name as calls are named, ``~x``: a local tested in a condition may hold
    the read of ``getName() + "/x"``, ``~/x`` (autorally's GPS node's ``mode``)."""
    return "~" + name[2:] if name.startswith("~/") else name


def parameter_name(name: str) -> str | None:
    """The parameter a grammar name stands for (``get_parameter("x")``), else None."""
    return _decoded(name[len(PARAMETER_PREFIX):]) if name.startswith(PARAMETER_PREFIX) \
        else None


def _encoded(prefix: str, literal: str) -> str:
    """A grammar name of its own for a string literal's text (``"x"``): the prefix, then
    the text in hex (any text makes a valid name)."""
    return prefix + literal[1:-1].encode().hex()


def _decoded(encoded: str) -> str | None:
    try:
        return bytes.fromhex(encoded).decode()
    except ValueError:
        return None


@functools.lru_cache(maxsize=4096)
def python_of(text: str) -> tuple[str, frozenset[str]] | None:
    """The Python expression a C++ condition text reads as, with the names it uses."""
    if len(text) > MAX_TEXT:
        return None
    try:
        grammar = _Grammar(text)
        return grammar.parse(), frozenset(grammar.names)
    except (ValueError, IndexError, RecursionError):
        return None


# the name a call that returns a parameter's value takes in a condition's text
# (``readable``): the grammar reads no call of the code's own
HELD_CALL = "haros_call_"


@functools.lru_cache(maxsize=4096)
def readable(condition: Condition) -> tuple[str, dict[str, str] | None]:
    """The condition's text with each call that returns a parameter's value
    (``Condition.parameters`` keyed by the call's text: ublox's ``getRosBoolean(node_,
    "nmea.set")``) written as a name of its own, and the locals and those names, each
    with the parameter whose value it holds."""
    held = dict(condition.parameters) if condition.parameters else None
    if not held:
        return condition.text, held
    text = condition.text
    names: dict[str, str] = {}
    calls = sorted((k for k in held if not k.isidentifier()), key=lambda k: (-len(k), k))
    for index, written in enumerate(calls):
        name = f"{HELD_CALL}{index}"
        # the whole call: not the end of another one's text (``x.f(a)`` for ``f(a)``)
        text, count = re.subn(r"(?<![\w.>:])" + re.escape(written), name, text)
        if count:
            names[name] = held[written]
    return text, {k: v for k, v in held.items() if k.isidentifier()} | names


def decide(condition: Condition, values: Callable[[str], object],
           views: list[ProgramView] | None = None) -> bool | None:
    """True / False when ``condition`` is decided with the names' ``values`` (an
    ``Unknown`` for a name with none); None when it is not. ``views``: the program's
    arguments as the condition may see them (``program_views``)."""
    if condition.kind != "source" or condition.statement not in DECIDED_STATEMENTS:
        return None
    read = python_of(readable(condition)[0])
    if read is None:
        return None
    expression, names = read
    left = condition.args_left
    uses_argv = bool(names & {"argc", "argv"})
    uses_left = left is not None and left in names
    if (uses_argv or uses_left) and (not condition.program_args or not views):
        return None
    if views is not None and len(views) == 2 and condition.after_init is not None:
        # ROS 1 code tested on one side of its ``ros::init``: that side's ``argv`` alone
        views = views[1:] if condition.after_init else views[:1]
    # Python's arguments, the same list wherever the code reads them: ``sys.argv`` as
    # the program was started (no client library takes words off it), ``rospy.myargv()``
    # what rospy leaves
    python = bool(names & {PYTHON_ARGV, PYTHON_MYARGV})
    if python and (not views or (PYTHON_ARGV in names and views[0][0] is None)):
        return None  # not known (a ROS 2 instance's argv: launch_ros adds its words)
    started = views[0][0] if python and views else None
    constants = dict(condition.constants or ())
    answers = set()
    for argv, kept in (views if views and (uses_argv or uses_left or python)
                       else [(None, [])]):
        if uses_argv and argv is None:
            return None  # argc / argv themselves are not known (a ROS 2 instance's)

        def value(name: str, argv: list[str] | None = argv, kept: list[str] = kept
                  ) -> object:
            if (uses_left and name == left) or name == PYTHON_MYARGV:
                return kept
            if name == PYTHON_ARGV:
                return started
            if uses_argv and argv is not None and name == "argv":
                return argv
            if uses_argv and argv is not None and name == "argc":
                return len(argv)
            if name in constants:
                return constants[name]
            return values(name)
        result = evaluate(expression, value, {"len": len})
        if is_unknown(result) or not isinstance(result, (bool, int, float, str)):
            return None
        answers.add(bool(result))
    if len(answers) != 1:
        return None
    truth = answers.pop()
    return (not truth) if condition.statement == "else" else truth


# the program's ``argv`` as a condition may see it (None: not known), and what its client
# library leaves of it (the program's name first)
ProgramView = tuple[list[str] | None, list[str]]


def program_views(instance: NodeInstance) -> list[ProgramView] | None:
    """The ways an instance's code may see its arguments; None when they are not known.
    ROS 1: ``argv`` before and after ``ros::init`` (which takes the ``:=`` words: roslaunch
    starts the node with its ``args`` words, its remappings, ``__name:=`` and ``__log:=``);
    a condition is decided only when both give one answer. ROS 2: only what rclcpp leaves
    (``init_and_remove_ros_arguments``: the words outside ``--ros-args`` sections);
    ``argv`` holds the arguments launch_ros adds, which are not told here."""
    if UNKNOWN_MARK in instance.args or "$(" in instance.args:
        return None
    try:
        words = shlex.split(instance.args)
    except ValueError:
        return None
    program = instance.node.executable if instance.node is not None else "node"
    given = [program, *arguments_left(words, instance.ros_version)]
    if instance.ros_version != 1:
        return [(None, given)]
    remaps = len(instance.remaps) - (len(words) - len(given) + 1)
    before = [program, *words, *(["from:=to"] * max(remaps, 0)),
              f"__name:={instance.name.rpartition('/')[2]}", "__log:=log"]
    return [(before, given), (given, given)]


def program_argument(instance: NodeInstance, index: int) -> str | None:
    """The instance's ``index``-th command-line argument as its code sees it
    (``PrimitiveCall.program_arg`` / ``name_arg``): counted from the front, in every way
    the code may see its arguments (``program_views``: ROS 1's ``argv`` before and after
    ``ros::init``, which must agree); from the end (negative), in what the client library
    leaves, which the extractor tells only after it took its words. None when the
    arguments are not known or the instance has no such argument (never its program)."""
    views = program_views(instance)
    found = set()
    for argv, kept in views or ():
        seen = argv if argv is not None and index > 0 else kept
        if not -len(seen) < index < len(seen) or index == 0:
            return None
        found.add(seen[index])
    return found.pop() if len(found) == 1 else None


def program_option(instance: NodeInstance, flags: str,
                   default: str | None = None) -> str | None:
    """The value the instance's command line gives an option that argparse parses
    (``PrimitiveCall.name_option``: its flags, ``-l --limb``): ``--limb right``,
    ``--limb=right``, ``-l right`` or ``-lright``, the last one given, in the words the
    client library leaves (argparse reads ``rospy.myargv()`` or ``sys.argv``, whose
    roslaunch words are no option); ``default`` (argparse's, when the code's is known)
    when the arguments are known and do not give it; None when they are not known, or
    do not give it and no default is told."""
    views = program_views(instance)
    names = flags.split()
    found = set()
    for _, kept in views or ():
        value = None
        words = kept[1:]
        for at, word in enumerate(words):
            for flag in names:
                if word == flag and at + 1 < len(words):
                    value = words[at + 1]
                elif flag.startswith("--") and word.startswith(flag + "="):
                    value = word[len(flag) + 1:]
                elif not flag.startswith("--") and len(flag) == 2 and word.startswith(
                        flag) and len(word) > 2 and not word.startswith("--"):
                    value = word[2:]
        if value is None:
            value = default
        if value is None:
            return None
        found.add(value)
    return found.pop() if len(found) == 1 else None


# what ``getopt_option`` is told as the default to tell an option not given apart
NOT_GIVEN = "\0"


def getopt_option(instance: NodeInstance, flags: str, spec: str,
                  default: str | None = None) -> str | None:
    """The value the instance's command line gives an option that C's getopt /
    getopt_long parses (``PrimitiveCall.name_option``, ``-r --rosparam``, with the
    program's options ``spec``, ``PrimitiveCall.name_getopt``), read as getopt reads the
    words the client library leaves: ``-r X``, ``-rX``, ``-ur X`` (``u`` taking no
    argument), ``--rosparam X``, ``--rosparam=X`` and an unambiguous prefix of the long
    name (``--rosp X``), the last one given; ``--`` ends the options, and so does the
    first other word when the optstring begins with ``+``. ``default`` when the words
    are read and do not give it; None when they are not known, do not give it and no
    default is told, or hold what getopt's table here cannot tell: an option the
    program does not take, a long option with its table not read (``--?``); and for a
    ROS 2 instance, whose ``argv`` holds launch_ros' words too."""
    views = program_views(instance)
    names = flags.split()
    shorts = {name[1] for name in names if len(name) == 2 and name[0] == "-"}
    longs = {name[2:] for name in names if name.startswith("--")}
    optstring, *table = spec.split(" ")  # (an optstring may be empty: long options only)
    table = [entry for entry in table if entry]
    in_order = optstring.startswith("+")
    letters = optstring.lstrip("+-:")
    takes: dict[str, int] = {}  # option -> 0 none, 1 required, 2 optional argument
    for at, letter in enumerate(letters):
        if letter != ":":
            after = letters[at + 1:at + 3]
            takes[letter] = 2 if after == "::" else 1 if after[:1] == ":" else 0
    long_takes = {entry.rstrip(":"): len(entry) - len(entry.rstrip(":"))
                  for entry in table if entry != "--?"}
    found = set()
    for argv, kept in views or ():
        if argv is None:
            # ROS 2: getopt reads the ``--ros-args`` sections launch_ros adds too (``-r
            # a:=b``, ``-p``), which are not told here
            return None
        value = None
        words = kept[1:]
        at = 0
        while at < len(words):
            word = words[at]
            at += 1
            if word == "--":
                break
            if word.startswith("--"):
                if "--?" in table:
                    return None
                name, equals, given = word[2:].partition("=")
                matches = [n for n in long_takes if n == name] or [
                    n for n in long_takes if n.startswith(name)]
                if len(matches) != 1:
                    return None  # an option getopt rejects, or an ambiguous prefix
                kind = long_takes[matches[0]]
                argument: str | None = given if equals else None
                if kind == 1 and not equals:
                    if at >= len(words):
                        return None
                    argument, at = words[at], at + 1
                if matches[0] in longs and kind:
                    value = argument
                continue
            if not word.startswith("-") or word == "-":
                if in_order:
                    break
                continue  # GNU getopt moves the other words after the options
            for place, letter in enumerate(word[1:], 1):
                if letter not in takes or letter == ":":
                    return None  # an option the program does not take
                if not takes[letter]:
                    continue
                argument = word[place + 1:] or None
                if argument is None and takes[letter] == 1:
                    if at >= len(words):
                        return None
                    argument, at = words[at], at + 1
                if letter in shorts:
                    value = argument
                break
        if value is None:
            value = default
        if value is None:
            return None
        found.add(value)
    return found.pop() if len(found) == 1 else None


def arguments_left(words: list[str], ros_version: int) -> list[str]:
    """What a program's client library leaves of its arguments: roscpp's ``ros::init``
    takes every ``:=`` word (remaps, ``__name:=``), rclcpp every ``--ros-args ... --``
    section."""
    if ros_version == 1:
        return [w for w in words if ":=" not in w]
    return split_arguments(words)[0]


_TYPES: dict[str, tuple[type, ...]] = {"bool": (bool,), "int": (int,),
                                       "double": (int, float), "float": (int, float),
                                       "str": (str,)}


def _typed(value: Any, ctype: str | None, untyped: bool = False) -> object:
    """``value`` when it is of the read's type (an int is not a bool here); ``untyped``:
    a read with no type (None) takes any value of a YAML scalar's type, as rospy's
    ``get_param('~x')`` and rclpy's ``declare_parameter('x')`` with no default do."""
    if untyped and ctype is None and isinstance(value, (bool, int, float, str)):
        return value
    allowed = _TYPES.get(ctype or "")
    if allowed is None or not isinstance(value, allowed) or (
        bool not in allowed and isinstance(value, bool)
    ):
        return Unknown(f"a value of type {type(value).__name__} for a {ctype} read")
    return value


def _read_value(link: Link, untyped: bool = False,
                unseen: list[Parameter] | tuple[()] = ()) -> object:
    """The value a parameter read gets in this configuration (``untyped``: a read with
    no type takes the value as it is, ``_typed``); not its default where ``unseen``,
    the launch parameters of names not known statically, holds one that may be it (a
    parameter file not read: ROS 1 mavros' ``<rosparam command="load"
    file="$(find mavros)/launch/px4_config.yaml"/>`` where mavros is not installed here and
    its model holds no launch files may set ``landing_target/listen_lt``)."""
    call, param = link.call, link.resource
    if call is None or not isinstance(param, Parameter):
        return Unknown("not a parameter read")
    if param.is_unresolved and not own_unknown(link.node.name, param.name):
        # a name not known (``zone_name_ + ".visualize"``): whatever sets the real one
        return Unknown(f"the name {param.name} is not known")
    if param.set_by_launch:
        if param.launch_conditions or param.setters:
            return Unknown(f"{param.name} is set under a condition or by a node")
        return _typed(param.value, call.type, untyped)
    if param.setters:
        return Unknown(f"{param.name} is set by a node")
    for other in unseen:
        if other is not param and re.match(pattern_for(other.name), param.name):
            return Unknown(f"{param.name} may be set by the launch parameter "
                           f"{other.name}, not known statically")
    if call.has_default and call.default is not None:
        return _typed(call.default, call.type)
    return Unknown(f"{param.name} is not set and its default is not known")


def _presence_value(config: Configuration, instance: NodeInstance, file: str | None,
                    kind: str, written: str, made: dict[str, Any],
                    at: Location | None = None, near: str | None = None) -> object:
    """Whether a ROS 1 ``getParam("x", v)`` / ``hasParam("x")`` in a condition finds the
    parameter, from the instance's tested read of it in that file (the call the
    condition makes, resolved like any read): True for hasParam of a parameter the
    launch sets with no condition (or sets under, a namespace), and for getParam when
    the value is of the read's type; False for one that nothing sets and nothing unseen
    could set; else unknown. A write of it under the condition itself (``at``: where the
    condition is) is made after the test, in its branch (costmap_2d's ``if
    (!nh.hasParam("plugins")) loadOldParameters(nh);``, which sets ``plugins``): no
    setting the test can see. Tests of the parameter in one file that disagree (the
    code of a class built twice, move_base's two costmaps) are those of the same object
    as the call the condition guards, ``near`` (its resource's name): the tested
    parameters that share the most of its namespace."""
    if instance.ros_version != 1:
        return Unknown("not a ROS 1 node")
    found = {id(link.resource): link for link in instance.links
             if link.kind == "read" and link.call is not None and link.call.tested
             and link.call.location.file == file and isinstance(link.resource, Parameter)
             and _own(link.call.name) == _own(written)
             and link.call.name.lstrip("~").endswith(written.lstrip("~"))}
    if not found:
        return Unknown(f"no read of {written} in {file}")
    # the reads of the name as the test writes it, where there are (a helper that
    # tests ``~x``, then ``x``: rospy's joint_state_publisher); else those of a handle
    # that puts its namespace before it (``private_nh.hasParam("x")``, read as ``~x``)
    exact = {key: link for key, link in found.items()
             if link.call is not None and link.call.name == written}
    found = exact or found
    present = {key: _present(config, link, kind, made, at) for key, link in found.items()}
    answers = set(present.values())
    if len(answers) > 1 and near is not None:
        shared = {key: _shared_namespace(link.resource.name, near)
                  for key, link in found.items()}
        best = max(shared.values())
        answers = {present[key] for key in found if shared[key] == best}
    if len(answers) != 1:
        return Unknown(f"the reads of {written} differ")
    return answers.pop()


def _presence_at(config: Configuration, instance: NodeInstance, kind: str,
                 variable: str, made: dict[str, Any], at: Location | None,
                 site: Location | None) -> object:
    """Whether ``hasParam(variable)`` / ``getParam(variable, v)`` finds its parameter,
    for a call that the test guards made at ``site``: the test is one of the node's
    tested reads made at that site and not under the test itself (costmap_2d's
    ``move_parameter(old_h, new_h, name)``, called once per name: ``if
    (!old_h.hasParam(name)) return;`` before the copy). Reads there that disagree
    leave it unknown."""
    unknown = Unknown(f"which parameter {variable} names")
    if instance.ros_version != 1 or site is None or at is None:
        return unknown
    found = [link for link in instance.links
             if link.kind == "read" and link.call is not None and link.call.tested
             and link.call.location == site and isinstance(link.resource, Parameter)
             and not any(c.location == at for c in link.conditions)]
    answers = {_present(config, link, kind, made, at) for link in found}
    if len(answers) != 1:
        return unknown
    return answers.pop()


def _shared_namespace(name: str, other: str) -> int:
    """How many leading namespace segments two names share."""
    count = 0
    for first, second in zip(name.split("/")[:-1], other.split("/"), strict=False):
        if first != second:
            break
        count += 1
    return count


def _own(name: str) -> str:
    return name.lstrip("~").rpartition("/")[2]


def _present(config: Configuration, link: Link, kind: str, made: dict[str, Any],
             at: Location | None = None) -> object:
    param = link.resource
    assert isinstance(param, Parameter) and link.call is not None
    unknown = Unknown(f"whether {param.name} is set")
    before = [w for w in param.setters
              if at is None or not any(c.location == at for c in w.conditions)]
    prefix = param.name.rstrip("/") + "/"
    set_here = [p for p in config.parameters if p.set_by_launch and (
        p is param or p.name.startswith(prefix))]
    if kind == "has" and before and param.set_by_launch and not param.is_unresolved and not (
        param.launch_conditions or len(param.writers) != len(param.setters)
    ):
        # set by the launch file, and never deleted: the node's own writes of it only
        # give it another value (costmap_2d tests ``plugins`` again after its old
        # parameters' migration may have set it)
        return True
    if param.is_unresolved or before:
        return unknown
    if set_here:
        if any(p.launch_conditions or p.is_unresolved for p in set_here):
            return unknown
        if kind == "has":
            return True
        ctype = link.call.type or ""
        if param.set_by_launch and not [p for p in set_here if p is not param] and (
            param.value is not None and not is_unknown(param.value)
        ) and ((ctype == "dict" and not isinstance(param.value, dict)) or (
            ctype.endswith("[]") and not isinstance(param.value, list))):
            # roscpp's getParam fills a std::map from a dictionary only, a std::vector
            # from a list only (teleop_twist_joy's ``getParam("axis_linear", map)`` of
            # ``axis_linear: 1``)
            return False
        typed = _typed(param.value, link.call.type) if param.set_by_launch else unknown
        return unknown if is_unknown(typed) else True
    # nothing seen sets it: nothing unseen may either (a node of partial or unknown
    # interface, its own for a private parameter; a parameter with '?' that may be it;
    # a dynamic_reconfigure server above it, which writes its fields; an include the
    # launch stage could not read)
    from ..query.absence import Known, owner_of, reconfiguring

    # made once per decide_links, not the queries' cache: no candidates are found yet
    known = made.get("known") or made.setdefault("known", Known(config))
    owner = owner_of(config, param, known)
    if (owner is not None and not owner.is_complete) or (
        owner is None and config.incomplete_nodes
    ):
        return unknown
    if any(p.is_unresolved and re.match(pattern_for(p.name), param.name)
           for p in config.parameters):
        return unknown
    if reconfiguring(config, param, known):
        return unknown
    if any(item.kind == "include" and not item.skipped
           for tree in config.launch_tree for item in tree.walk()):
        return unknown
    return False


def _member_values(instance: NodeInstance, config: Configuration | None = None,
                   made: dict[str, Any] | None = None) -> Callable[..., object]:
    """A member's value, by name and the file of the condition using it."""
    reads: dict[tuple[str | None, str], list[Link]] = {}
    anywhere: dict[str, list[Link]] = {}  # by member, in whichever file of the node
    declared: dict[int, list[Link]] = {}  # parameter -> the instance's declarations of it
    for link in instance.links:
        if link.call is not None and link.call.variable and link.kind in ("read", "declare"):
            reads.setdefault((link.call.location.file, link.call.variable), []).append(link)
            anywhere.setdefault(link.call.variable, []).append(link)
        if link.call is not None and link.call.kind == "declare":
            declared.setdefault(id(link.resource), []).append(link)

    # Python reads: a parameter read with no type takes any value (C++: the type of the
    # variable it writes, which the parse may not know)
    dynamic = instance.node is not None and instance.node.language == "python"
    # the launch parameters of names not known statically (once per configuration)
    unseen: list[Parameter] = [] if config is None else (
        made["unseen"] if made is not None and "unseen" in made else [
            p for p in config.parameters if p.is_unresolved and p.set_by_launch])
    if made is not None and config is not None:
        made["unseen"] = unseen

    def value(name: str, *, file: str | None,
              held: dict[str, str] | None = None, at: Location | None = None,
              near: str | None = None, site: Location | None = None) -> object:
        # a read in the condition's own file, else in another file of the node: a base
        # class's header that reads what its subclasses test (pcl_ros' PCLNodelet::onInit
        # reads ~use_indices into use_indices_, filter.cpp tests it); reads that disagree
        # leave the member unknown. ``get_parameter("x")``, or a local of the condition's
        # function that holds the value of x (``Condition.parameters``): the node's
        # reads of x.
        presence = presence_name(name)
        if presence is not None:
            if config is None:
                return Unknown("no configuration")
            if presence[1].startswith(VARIABLE_MARK):
                return _presence_at(config, instance, presence[0], presence[1][1:],
                                    {} if made is None else made, at, site)
            return _presence_value(config, instance, file, *presence,
                                   {} if made is None else made, at, near)
        parameter = held.get(name) if held else None
        parameter = parameter if parameter is not None else parameter_name(name)
        if parameter is None and not (reads.get((file, name)) or anywhere.get(name)) and (
                reads.get((file, name + PARAMETER_VALUE))
                or anywhere.get(name + PARAMETER_VALUE)):
            # a member that holds the parameter object: its ``value`` is the parameter's
            held_value = value(name + PARAMETER_VALUE, file=file)
            return held_value if is_unknown(held_value) else KeyAttributes(
                {PARAMETER_VALUE.lstrip("."): held_value})
        found = reads.get((file, name)) or anywhere.get(name) if parameter is None else [
            link for link in instance.links if link.call is not None
            and link.kind in ("read", "declare")
            and _private_form(link.call.name) == _private_form(parameter)]
        if not found:
            return Unknown(f"{name} is not known to hold a parameter")
        # a ROS 2 read without a default gets what the node's declarations of that
        # parameter get (``declare_parameter("p", true); get_parameter("p", p_)``)
        found = [each for link in found for each in (
            declared.get(id(link.resource), [link]) if link.call is not None and (
                link.call.kind == "read" and not link.call.has_default) else [link])]
        values = [_read_value(link, dynamic, unseen) for link in found]
        # constants the code also assigns the member: one that differs leaves it unknown
        values += [_typed(value, link.call.type) for link in found
                   if link.call is not None for value in link.call.also or ()]
        first = values[0]
        if any(is_unknown(v) for v in values) or any(v != first for v in values[1:]):
            return next((v for v in values if is_unknown(v)),
                        Unknown(f"{name} holds parameters of different values"))
        return first
    return value


def decide_links(config: Configuration) -> None:
    """Take off each link the source conditions this configuration decides: a link
    under a false one is dropped (CONDITION_FALSE says so), a true one is removed."""
    dropped: list[Link] = []
    falses: list[tuple[Link, Condition]] = []
    made: dict[str, Any] = {}
    for instance in config.nodes:
        members = _member_values(instance, config, made)
        views = program_views(instance)
        for link in list(instance.links):
            kept: list[Condition] = []
            false: Condition | None = None
            for condition in link.conditions:
                answer = decide(condition, functools.partial(
                    members, file=condition.location.file, held=readable(condition)[1],
                    at=condition.location, near=link.rosname.full,
                    site=link.call.location if link.call is not None else None), views)
                if answer is False:
                    false = condition
                    break
                if answer is None:
                    kept.append(condition)
            if false is None:
                false = _list_unset(config, instance, link, made)
            if false is not None:
                dropped.append(link)
                falses.append((link, false))
            elif len(kept) != len(link.conditions):
                link.conditions = tuple(kept)
        # a call made in one turn of a loop over a list and not in another (graph.build.
        # element_calls) is there: no word of the turns that do not make it
        gone = {id(link) for link, _ in falses}
        made_here = {(k.location, k.kind, k.rosname.full) for k in instance.links
                     if id(k) not in gone} if falses else set()
        for link, false in falses:
            if (link.location, link.kind, link.rosname.full) in made_here:
                continue
            made_here.add((link.location, link.kind, link.rosname.full))  # said once
            where = f"{false.location.file}:{false.location.line}"
            config.diagnostics.append(diag.make(
                "CONDITION_FALSE", link.location, node=instance.name, kind=link.kind,
                name=link.rosname.full, condition=str(false), where=where))
        _unsaid_unset(config, instance, [link for link, _ in falses], gone)
        falses.clear()
    if dropped:
        drop_links(config, dropped)


def _unsaid_unset(config: Configuration, instance: NodeInstance, links: list[Link],
                  gone: set[int]) -> None:
    """Take back what ``graph.build`` said of a name a call takes from a parameter the
    configuration does not set (NAME_PARAM_UNSET), where the call does not exist there
    (``links``, under a false condition) and no other link of the node made there keeps
    a '?': joint_state_publisher subscribes per element of ``source_list`` only when
    ``~source_list`` is not set, and a launch file that sets ``~source_list`` sets no
    ``source_list``, which names nothing then."""
    left = {(k.location, k.kind) for k in instance.links
            if id(k) not in gone and k.rosname.is_unresolved}
    taken = {(link.location, link.kind) for link in links
             if link.call is not None and link.call.name_param is not None
             and link.rosname.is_unresolved} - left
    if not taken:
        return
    config.diagnostics[:] = [d for d in config.diagnostics if not (
        d.code == "NAME_PARAM_UNSET" and any(
            d.location == where and d.message.startswith(
                f"{instance.name}: the name of this {kind} ") for where, kind in taken))]


def _list_unset(config: Configuration, instance: NodeInstance, link: Link,
                made: dict[str, Any]) -> Condition | None:
    """The loop over a ROS 1 list parameter that makes ``link`` (a call named by each of
    its elements, ``PrimitiveCall.name_each``, left with ``?`` by ``graph.build.
    element_calls``), as a condition that does not hold, when the list is not set:
    every read the node makes of it has no default (roscpp's ``getParam`` fails, so
    the code's loop runs no turn or the value it walks throws: twist_mux's
    ``xh::fetchParam(nh_priv, "locks", ...)`` throws and its caller catches it) and
    nothing seen sets it nor may unseen (``_present``). None otherwise."""
    call = link.call
    if instance.ros_version != 1 or call is None or call.name_each is None or (
        call.name_param is None or call.name_each in (NUMBERED, WORDS)
        or call.name_each.startswith(COUNTED)
        or UNKNOWN_MARK in call.name_param or not link.rosname.is_unresolved
    ):
        return None
    full = RosName.make(call.name_param, instance.namespace, instance.name).full
    reads = [k for k in instance.links if k.kind == "read" and k.call is not None
             and isinstance(k.resource, Parameter) and k.resource.name == full]
    if not reads or any(k.call is not None and k.call.has_default for k in reads):
        return None
    if any(_present(config, k, "get", made) is not False for k in reads):
        return None
    where = reads[0].location
    return Condition(f"each element of {call.name_param}, which nothing sets",
                     statement=EACH_STATEMENT, location=where)


def drop_links(config: Configuration, links: list[Link]) -> None:
    """Take ``links`` out of the configuration, and the resources left with none (a
    parameter the launch sets stays)."""
    gone = set(map(id, links))
    config.links[:] = [k for k in config.links if id(k) not in gone]
    emptied = set()
    for link in links:
        link.node.links[:] = [k for k in link.node.links if id(k) not in gone]
        link.resource.links[:] = [k for k in link.resource.links if id(k) not in gone]
        if not link.resource.links and not (
            isinstance(link.resource, Parameter) and link.resource.set_by_launch
        ):
            emptied.add(id(link.resource))
    collections: tuple[list[Any], ...] = (config.topics, config.services, config.actions,
                                          config.parameters)
    for collection in collections:
        collection[:] = [r for r in collection if id(r) not in emptied]
