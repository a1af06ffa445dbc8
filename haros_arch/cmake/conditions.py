"""CMake ``if()`` conditions in three-valued logic: True, False or None (unknown).

Follows CMake's precedence: parentheses, then unary tests (``EXISTS``, ``DEFINED``, ...),
then binary tests (``STREQUAL``, ``LESS``, ``MATCHES``, ``VERSION_*``, ``IN_LIST``), then
``NOT``, then ``AND``, then ``OR``. A variable we cannot know (one a ``find_package``
would set) makes the test unknown; ``AND`` / ``OR`` still decide when one side does.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Collection, Mapping

from .listops import RegexLimit, cmake_regex

# how what ``find_package(pkg)`` leaves in ``pkg_LIBRARIES`` (and catkin in
# ``catkin_LIBRARIES``) begins (``commands.PACKAGE_MARK``): a mark of the package, not
# the paths of its libraries that a build has there, so a test of the text of a value
# holding one is not decided (MoveIt's ``if("${catkin_LIBRARIES}" MATCHES
# "moveit_collision_detection_bullet")``: the bullet library, when moveit_core built it)
PACKAGE_MARK_START = "$<HAROS_PACKAGE:"

Truth = bool | None

_TRUE = {"1", "ON", "YES", "TRUE", "Y"}
_FALSE = {"0", "OFF", "NO", "FALSE", "N", "IGNORE", "NOTFOUND", ""}
TRUE_WORDS, FALSE_WORDS = frozenset(_TRUE), frozenset(_FALSE)
UNARY = ("EXISTS", "COMMAND", "DEFINED", "TARGET", "IS_DIRECTORY", "IS_ABSOLUTE",
         "POLICY", "TEST", "IS_SYMLINK")
BINARY = ("STREQUAL", "STRLESS", "STRGREATER", "STRLESS_EQUAL", "STRGREATER_EQUAL",
          "EQUAL", "LESS", "GREATER", "LESS_EQUAL", "GREATER_EQUAL", "MATCHES",
          "VERSION_EQUAL", "VERSION_LESS", "VERSION_GREATER", "VERSION_LESS_EQUAL",
          "VERSION_GREATER_EQUAL", "IN_LIST", "IS_NEWER_THAN", "PATH_EQUAL")


# what ``find_package(X)`` sets at configure time (``X_FOUND``, ``X_VERSION``, ...): not
# known here unless the reading set it, read bare (``if(X_FOUND)``) or through a reference
# (``"${X_VERSION}" VERSION_GREATER 1.0``, which the test gets as ``UNKNOWN_MARK``)
FOUND_BY_PACKAGE = re.compile(
    r"([A-Za-z_][A-Za-z0-9_]*)_(FOUND|DIR|LIBRARIES|INCLUDE_DIRS|VERSION)")
# an argument of a test whose value is not known (a generator expression's form, which
# no text CMake reads has)
UNKNOWN_MARK = "$<HAROS_UNKNOWN>"


class Evaluator:
    def __init__(self, variables: Mapping[str, str], targets: Mapping[str, object],
                 base: str, known_commands: Callable[[str], bool] = lambda _: False,
                 assigned: Collection[str] = (),
                 environment: Mapping[str, str] | None = None,
                 in_absent_submodule: Callable[[str], bool] = lambda _: False) -> None:
        self.variables = variables
        self.targets = targets
        self.base = base
        self.known_commands = known_commands
        # names the package's own files set somewhere: when unset now, they are unset
        self.assigned = assigned
        # the environment the build runs in, as far as the reading knows it (a project's
        # ``distro:`` gives ROS_VERSION): a setting it has is defined; one it lacks may
        # still be given to the build
        self.environment = environment or {}
        # whether a path lies in a git submodule the tree lacks (declared in a
        # .gitmodules, its folder empty): a build from a full checkout has it
        self.in_absent_submodule = in_absent_submodule

    def evaluate(self, args: list[str]) -> Truth:
        tokens = self._groups(list(args))
        return self._or(tokens)

    # Parentheses first: each group becomes one already-evaluated token.
    def _groups(self, args: list[str]) -> list[str | Truth]:
        out: list[str | Truth] = []
        stack: list[list[str | Truth]] = []
        for arg in args:
            if arg == "(":
                stack.append(out)
                out = []
            elif arg == ")" and stack:
                value = self._or(out)
                out = stack.pop()
                out.append(value)
            else:
                out.append(arg)
        return out

    def _or(self, tokens: list[str | Truth]) -> Truth:
        parts = _split(tokens, "OR")
        values = [self._and(p) for p in parts]
        if any(v is True for v in values):
            return True
        return None if any(v is None for v in values) else False

    def _and(self, tokens: list[str | Truth]) -> Truth:
        parts = _split(tokens, "AND")
        values = [self._not(p) for p in parts]
        if any(v is False for v in values):
            return False
        return None if any(v is None for v in values) else True

    def _not(self, tokens: list[str | Truth]) -> Truth:
        if tokens[:1] == ["NOT"]:
            value = self._not(tokens[1:])
            return None if value is None else not value
        return self._test(tokens)

    def _test(self, tokens: list[str | Truth]) -> Truth:
        if len(tokens) == 1:
            token = tokens[0]
            return token if not isinstance(token, str) else self._truth(token)
        if len(tokens) == 2 and tokens[0] in UNARY and isinstance(tokens[1], str):
            return self._unary(str(tokens[0]), tokens[1])
        if len(tokens) == 3 and tokens[1] in BINARY:
            left, right = tokens[0], tokens[2]
            if isinstance(left, str) and isinstance(right, str):
                return self._binary(left, str(tokens[1]), right)
        return None

    def _value(self, text: str) -> str | None:
        """A binary operand: a variable's value if it names one, else the text."""
        if UNKNOWN_MARK in text:
            return None
        if text in self.variables:
            return self.variables[text]
        if FOUND_BY_PACKAGE.fullmatch(text):
            return None  # set by find_package at configure time
        return text

    def _truth(self, text: str) -> Truth:
        if UNKNOWN_MARK in text:
            return None
        upper = text.upper()
        if upper in _TRUE or (_is_number(text) and float(text) != 0):
            return True
        if upper in _FALSE or upper.endswith("-NOTFOUND") or _is_number(text):
            return False
        if text in self.variables:
            value = self.variables[text].upper()
            return not (value in _FALSE or value.endswith("-NOTFOUND"))
        if text in self.assigned:
            return False
        return None  # a variable we do not know: an environment or cache setting

    def _unary(self, op: str, arg: str) -> Truth:
        if UNKNOWN_MARK in arg:
            return None
        if op == "DEFINED":
            if arg.startswith("ENV{") and arg.endswith("}"):
                return True if arg[4:-1] in self.environment else None
            if arg in self.variables:
                return True
            return False if arg in self.assigned else None
        if op == "TARGET":
            return True if arg in self.targets else None
        if op in ("EXISTS", "IS_DIRECTORY"):
            path = arg if os.path.isabs(arg) else None
            if path is None or not path.startswith(self.base):
                return None  # outside the package: depends on the machine
            if not os.path.exists(path) and self.in_absent_submodule(path):
                # in a git submodule not checked out here (mrover-ros2's ``if (EXISTS
                # ${MROVER_EMBEDDED_ROOT_DIR})``, a folder of its submodule esw/fw): the
                # build of a full checkout finds it, so the test is not decided
                return None
            return os.path.isdir(path) if op == "IS_DIRECTORY" else os.path.exists(path)
        if op == "IS_ABSOLUTE":
            return os.path.isabs(arg)
        if op == "COMMAND":
            return True if self.known_commands(arg) else None
        return None

    def _binary(self, left_text: str, op: str, right_text: str) -> Truth:
        left, right = self._value(left_text), self._value(right_text)
        if op == "IN_LIST":
            items = self.variables.get(right_text) if UNKNOWN_MARK not in right_text else None
            if left is None or items is None:
                return None
            return left in items.split(";")
        if left is None or right is None:
            return None
        if PACKAGE_MARK_START in left or PACKAGE_MARK_START in right:
            return None
        if op == "STREQUAL":
            return left == right
        if op.startswith("STR"):
            return _compare(op[3:], left, right)
        if op == "MATCHES":
            pattern = cmake_regex(right)
            if pattern is None:
                return None
            try:
                return pattern.search(left) is not None
            except RegexLimit:  # too slow to tell: unknown, as any undecided condition
                return None
        if op.startswith("VERSION_"):
            return _compare(op[8:], _version(left), _version(right))
        if op in ("EQUAL", "LESS", "GREATER", "LESS_EQUAL", "GREATER_EQUAL"):
            if not (_is_number(left) and _is_number(right)):
                return False
            return _compare(op, float(left), float(right))
        return None


def _split(tokens: list[str | Truth], word: str) -> list[list[str | Truth]]:
    parts: list[list[str | Truth]] = [[]]
    for token in tokens:
        if token == word:
            parts.append([])
        else:
            parts[-1].append(token)
    return parts


def _is_number(text: str) -> bool:
    return re.fullmatch(r"[-+]?\d+(\.\d+)?", text) is not None


def _version(text: str) -> tuple[int, ...]:
    return tuple(int(p) for p in re.findall(r"\d+", text)[:4])


def _compare(op: str, left: object, right: object) -> bool:
    a, b = left, right
    return {
        "EQUAL": a == b, "LESS": a < b, "GREATER": a > b,  # type: ignore[operator]
        "LESS_EQUAL": a <= b, "GREATER_EQUAL": a >= b,  # type: ignore[operator]
    }[op]
