"""Conditions under which an entity exists.

An entity's ``conditions`` is a tuple read as a conjunction; an empty tuple means the
entity exists unconditionally.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Literal

from .location import NOWHERE, Location
from .values import UNKNOWN_MARK

ConditionKind = Literal["launch", "source", "hint"]
# the statement of the loop over a list parameter whose elements name a call, one call
# per element (``PrimitiveCall.name_each``): where the graph knows the elements, each
# call it makes stands for one turn of the loop, which is then no condition of it
EACH_STATEMENT = "for each"
# the start of a ``Condition.elements`` field that says the name holds the value of the
# parameter its rest names with the element in place of its one ``?``: navigation2's
# collision monitor reads ``const std::string type = declare_or_get_parameter(
# polygon_name + ".type")`` and tests ``type == "circle"`` for each ``polygons`` in turn
ELEMENT_PARAMETER = "parameter:"
# the statements of an enclosing block that runs at least once, no condition of what it
# makes: a ``try`` block (it runs unless something before the call throws), the body
# of a ``do ... while`` (its first turn always runs; robot_localization subscribes each
# ``imuN`` in a ``do`` loop, under an ``if`` that is its condition) and a ROS 2 launch
# ``TimerAction`` (what it holds starts once its period has passed)
RUN_ONCE_STATEMENTS = frozenset({"try", "do", "timer"})
# a loop test that holds from the node's start until it shuts down: roscpp's
# ``ros::ok()`` / ``!ros::isShuttingDown()``, rclcpp's ``rclcpp::ok()``, rospy's
# ``not rospy.is_shutdown()``, rclpy's ``rclpy.ok()`` (one of them, or several joined by
# ``&&`` / ``and``). The first turn of ``while`` over it runs whenever the node does, so
# it is no condition of existing either (kinova_arm_driver builds its arm, which
# advertises every topic, in the body of ``while (ros::ok())``, to rebuild it after a
# failure); nor is a loop over a literal truth (``while True:``, ``while (true)``,
# ``while (1)``: rosboard subscribes in the body of ``while True:``, once per topic a
# browser asks for), nor an ``if`` over it
_RUNNING = re.compile(
    r"(?:True|true|1"
    r"|(?:::\s*)?(?:ros|rclcpp)\s*::\s*ok\s*\(\s*\)"
    r"|!\s*(?:::\s*)?ros\s*::\s*isShuttingDown\s*\(\s*\)"
    r"|not\s+rospy\s*\.\s*(?:core\s*\.\s*)?is_shutdown\s*\(\s*\)"
    r"|rclpy\s*\.\s*ok\s*\(\s*\))")
_AND = re.compile(r"&&|\band\b")
# a test that holds once the node is shutting down: the negation of one of ``_RUNNING``'s
# (``!ros::ok()``, ``ros::isShuttingDown()``, ``rospy.is_shutdown()``, ``not
# rclpy.ok()``). What follows ``if (!ros::ok()) break;`` in its block runs under its
# ``else`` (ros_whill opens its port in ``while (ros::ok())``, leaves the loop ``if
# (!ros::ok())`` and reads its speed profile after that): no condition of existing
_STOPPED = re.compile(
    r"(?:!\s*(?:::\s*)?(?:ros|rclcpp)\s*::\s*ok\s*\(\s*\)"
    r"|(?:::\s*)?ros\s*::\s*isShuttingDown\s*\(\s*\)"
    r"|rospy\s*\.\s*(?:core\s*\.\s*)?is_shutdown\s*\(\s*\)"
    r"|not\s+(?:rclpy\s*\.\s*ok|rclcpp\s*::\s*ok)\s*\(\s*\))")
_OR = re.compile(r"\|\||\bor\b")
# the end of a ``PrimitiveCall.variable`` that holds a parameter object, not its value:
# rclpy's ``self.origin_param = self.declare_parameter(..)``, read by a condition as
# ``self.origin_param.value``
PARAMETER_VALUE = ".value"


@dataclass(frozen=True)
class Condition:
    """One condition: ``text`` as written, where it comes from and the construct."""

    text: str
    kind: ConditionKind = "source"
    statement: str = "if"
    location: Location = field(default=NOWHERE)
    # a source condition in ``main``: its ``argc`` / ``argv`` are the program's own
    # arguments, which a launch file's ``args`` tell (graph.conditions decides it)
    program_args: bool = field(default=False, metadata={"optional": True})
    # the local of that ``main`` that holds what the client library leaves of them
    # (``auto args = rclcpp::init_and_remove_ros_arguments(argc, argv)``): its ``size()``
    # and ``at(N)`` are the arguments a launch file gives, the program's name first
    args_left: str | None = field(default=None, metadata={"optional": True})
    # the locals its text names that hold a parameter's value, read in the function
    # before it (``const auto type = declare_parameter<std::string>("vehicle_model_type");
    # if (type == "dynamics")``): (local, parameter), which the graph decides it by
    parameters: tuple[tuple[str, str], ...] | None = field(
        default=None, metadata={"optional": True})
    # a ROS 2 launch condition that compares one launch argument with strings, as the
    # launch reader evaluated it (``LaunchConfigurationEquals('hw', 'fake')``,
    # ``LaunchConfigurationNotEquals``, ``$(equals $(var hw) fake)``, ``PythonExpression(
    # ['"', hw, '"', " in ('actual', 'fake')"])``): (argument, the strings, holds when
    # the argument is one of them), which ``contradict`` reads like an ``$(eval)``'s
    compares: tuple[str, tuple[str, ...], bool] | None = field(
        default=None, metadata={"optional": True})
    # a ROS 2 Python launch file's test not known statically: which runs of the file's
    # tests it joins (counted per file: one ``if`` in a loop runs once per item, and its
    # two runs may come out otherwise though written alike); not compared
    runs: tuple[int, ...] = field(default=(), compare=False, metadata={"optional": True})
    # the names its text uses that are constants of the code, each with its value: a
    # ``const`` integer or bool initialised by a literal (neonavigation_common's ``const
    # int current_level = 1;`` in ``if (getCompat() != current_level)``), which the graph
    # decides it with; in a configuration's graph also the value a name of ``elements``
    # has in one turn of the loop over its list (``graph.build.element_calls``)
    constants: tuple[tuple[str, int | bool | float | str], ...] | None = field(
        default=None, metadata={"optional": True})
    # the names its text uses that hold each element of a list parameter in turn, or a
    # field of it: (name, the list parameter, the field as ``PrimitiveCall.name_each``
    # writes it). costmap_2d's ``copyParentParameters(pname, type, nh)`` copies the
    # parameters of each ``plugins[i]`` under ``if (plugin_type ==
    # "costmap_2d::StaticLayer")``, its ``type``: the graph, making one call per element
    # of that list (``graph.build.element_calls``), decides it with that element's value
    elements: tuple[tuple[str, str, str], ...] | None = field(
        default=None, metadata={"optional": True})
    # of a ``program_args`` condition of ROS 1 code: whether it is tested after main's
    # ``ros::init(argc, argv, ..)`` (True: ``argc`` / ``argv`` are what it leaves, the
    # ``:=`` words taken off), before it (False: as the program was started), or not
    # known (None: either)
    after_init: bool | None = field(default=None, metadata={"optional": True})

    def __str__(self) -> str:
        # (a ``try`` block has no text: ``try``, not ``try ()``)
        return f"{self.statement} ({self.text})" if self.text else self.statement


# ``$(eval x == 'a')``, ``$(eval arg('x') != "a")``, ``$(eval 'a' == x)``: a launch
# argument compared with a string
_EVAL = re.compile(r"\s*\$\(eval\s+(.+?)\s*\)\s*")
_COMPARED = re.compile(r"(.+?)\s*(==|!=)\s*(.+)")
# ``$(eval x in ['a', 'b'])``, ``$(eval arg('x') not in ('a', 'b'))``: one of strings
_MEMBER = re.compile(r"(.+?)\s+(in|not\s+in)\s*[\[(]\s*(.*?)\s*,?\s*[\])]")
_ARG = re.compile(r"""(?:arg\(\s*(['"])(\w+)\1\s*\)|([A-Za-z_]\w*))""")
_STRING = re.compile(r"""(['"])([^'"]*)\1""")


def _equality(condition: Condition) -> tuple[str, tuple[str, ...], bool] | None:
    """``(argument, strings, holds when it is one of them)`` for a launch condition that
    compares one argument with strings, else None."""
    if condition.statement not in ("if", "unless"):
        return None
    if condition.compares is not None:
        return condition.compares
    inner = _EVAL.fullmatch(condition.text)
    member = _MEMBER.fullmatch(inner.group(1)) if inner else None
    if member is not None:
        name_side, operator, items = member.groups()
        name = _ARG.fullmatch(name_side)
        strings = [_STRING.fullmatch(item.strip()) for item in items.split(",")]
        if name is None or name_side in ("True", "False") or not all(strings):
            return None
        inside = (operator == "in") == (condition.statement == "if")
        return (name.group(2) or name.group(3),
                tuple(m.group(2) for m in strings if m is not None), inside)
    compared = _COMPARED.fullmatch(inner.group(1)) if inner else None
    if compared is None:
        return None
    left, operator, right = compared.groups()
    for name_side, string_side in ((left, right), (right, left)):
        name, string = _ARG.fullmatch(name_side), _STRING.fullmatch(string_side)
        if name is not None and string is not None and name_side not in ("True", "False"):
            equal = (operator == "==") == (condition.statement == "if")
            return name.group(2) or name.group(3), (string.group(2),), equal
    return None


def _negated(text: str) -> str | None:
    """``X`` for ``not (X)`` (a Python launch file's ``else`` branch, as the interpreter
    writes it), when the parentheses enclose the whole rest; else None."""
    text = text.strip()
    if not (text.startswith("not (") and text.endswith(")")):
        return None
    depth = 0
    for index, char in enumerate(text[4:], 4):
        depth += {"(": 1, ")": -1}.get(char, 0)
        if depth == 0 and index != len(text) - 1:
            return None  # ``not (a) or (b)``
    return text[5:-1].strip()


def _polarity(condition: Condition) -> tuple[str, bool] | None:
    """``(text, holds when true)`` of an ``if`` / ``unless`` condition, ``not (X)``
    read as X false (again for each ``not``)."""
    if condition.statement not in ("if", "unless"):
        return None
    holds = condition.statement == "if"
    text = condition.text.strip()
    while (inner := _negated(text)) is not None:
        text, holds = inner, not holds
    return text, holds


def contradict(first: Condition, second: Condition) -> bool:
    """Whether two launch conditions cannot both hold: ``if`` and ``unless`` of one text
    (``if X`` and ``if not (X)``, a Python launch file's ``if`` / ``else``), or one
    argument compared with strings that cannot both match (``x == 'a'`` and ``x ==
    'b'``; ``x == 'a'`` and ``x != 'a'``; ``x in ('a', 'b')`` and ``x == 'c'``). Read as
    written: both are taken to read the
    argument of one scope."""
    one_side, other_side = _polarity(first), _polarity(second)
    if one_side is not None and other_side is not None and one_side[0] == other_side[0] \
            and one_side[1] != other_side[1] \
            and one_side[0] != UNKNOWN_MARK:  # a text not known is not one text
        return True
    one, other = _equality(first), _equality(second)
    if one is None or other is None or one[0] != other[0]:
        return False
    (_, strings, inside), (_, others, other_inside) = one, other
    if inside and other_inside:  # one of each: none in common
        return not set(strings) & set(others)
    if inside:  # one of these, none of those
        return set(strings) <= set(others)
    if other_inside:
        return set(others) <= set(strings)
    return False  # none of either: another string matches both


def exclusive(first: tuple[Condition, ...], second: tuple[Condition, ...]) -> bool:
    """Whether two conjunctions of conditions cannot both hold."""
    return any(contradict(a, b) for a in first for b in second)


# a ROS 2 launch event handler ``OnProcessExit(target_action=X, on_exit=[...])``: what it
# starts runs once the process X, made at that place of a launch file, has ended
_EXIT_EVENT = "on event OnProcessExit of the process at "


def exit_event(target: Location) -> str:
    """The text of the condition of what starts when the process made at ``target``
    ends."""
    return f"{_EXIT_EVENT}{target}"


def after_exit(conditions: tuple[Condition, ...], target: Location) -> bool:
    """Whether ``conditions`` start their entity only after the process made at
    ``target`` has ended (so the two never run together)."""
    return bool(target.file) and any(
        c.kind == "launch" and c.statement == "event" and c.text == exit_event(target)
        for c in conditions)


def same_conditions(first: tuple[Condition, ...], second: tuple[Condition, ...]) -> bool:
    """Whether two conjunctions are the same conditions (written alike, and a Python
    launch test's made by one run of it): the one holds exactly when the other does (a
    text not known is no condition's but its own)."""
    if any(c.text.strip() == UNKNOWN_MARK for c in (*first, *second)):
        return False
    return {(c.text.strip(), c.statement, c.runs) for c in first} == {
        (c.text.strip(), c.statement, c.runs) for c in second}


def undecided(conditions: tuple[Condition, ...]) -> tuple[Condition, ...]:
    """The conditions of a conjunction under which its entity may not exist. What an
    entity keeps is what the configuration could not decide (the graph takes off the
    conditions it decides true and drops the entity under one decided false); of these,
    a block that runs at least once is no condition of existing (``RUN_ONCE_STATEMENTS``,
    a ``while`` or ``if`` over the node's running or the ``else`` of its stopping:
    ``runs_while_node_runs``)."""
    return tuple(c for c in conditions
                 if c.statement not in RUN_ONCE_STATEMENTS and not runs_while_node_runs(c))


def runs_while_node_runs(condition: Condition) -> bool:
    """Whether ``condition`` holds as long as the node runs: a ``while`` loop or an ``if``
    of the code whose test does (``_RUNNING``; a loop's first turn runs whenever the node
    does), or the ``else`` of a test that holds only once it stops (``_STOPPED``)."""
    if condition.kind != "source":
        return False
    text = _unwrapped(condition.text)
    if condition.statement in ("while", "if"):
        return all(_RUNNING.fullmatch(_unwrapped(part)) is not None
                   for part in _AND.split(text))
    if condition.statement == "else":
        return all(_STOPPED.fullmatch(_unwrapped(part)) is not None
                   for part in _OR.split(text))
    return False


def _unwrapped(text: str) -> str:
    """``text`` without surrounding blanks and one pair of parentheses around it all."""
    text = text.strip()
    if text.startswith("(") and text.endswith(")") and text.count("(") == text.count(")"):
        text = text[1:-1].strip()
    return text
