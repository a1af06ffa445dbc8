"""The versions of rclcpp and roscpp the stand-in headers announce: the distribution's.

ROS code picks API by its client library's version (``rclcpp/version.h``: ``#if
RCLCPP_VERSION_GTE(29, 0, 0)`` around navigation2's ``introspection_mode`` parameter,
which only Kilted's and later rclcpp read; roscpp's ``ros/common.h``: ``#if
ROS_VERSION_MINIMUM(1, 3, 0)``). The stand-ins follow Jazzy's and Noetic's API and
define the version macros only where they are not defined yet (``#ifndef``), so the
version reaches clang as ``-D`` flags: part of the language flags the precompiled
stand-ins are keyed by, and of each unit's cache key (a run for another distribution
parses again).

The distribution is the project file's ``distro:``, else ``ROS_DISTRO`` in the
environment (``pipeline``). When it is none of a library's table (none known, or one
of the other ROS), no flag is given for that library: the stand-ins announce its
``default``'s version. In a unit of that ROS the version is then not known, and the
code of every branch of a condition on it may run: a ROS call in a branch the parse
read is made under that branch's condition (``Branch.condition``), and when a branch
the parse left out holds a ROS call, the unit is parsed again with the version of
another release (``others``: a distribution's of the table, or one a condition names
that the table does not list; the newest first) and the calls of the branches that
parse reads are made under theirs (navigation2's
``introspection_mode`` parameter, declared under ``#if RCLCPP_VERSION_GTE(29, 0, 0)``,
is read under that condition, not certainly, nor never). A branch no parse read, or one
that parse left an error in, is ``CPP_VERSION_UNKNOWN`` at its first ROS call
(``unknown_version_calls``), which makes the node partial: on another release the code
makes a call nobody read.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from ...evaluate.python import evaluate
from ...model.conditions import Condition
from ...model.location import Location
from . import recall

# the parses of a unit with another version: one per branch left out of navigation2's
# four-branch chains (obstacle_layer.cpp:288-307: rolling's, 29.6's, kilted's, jazzy's)
MAX_OTHER_PARSES = 3


@dataclass(frozen=True)
class Library:
    """A client library whose version the stand-ins announce."""

    name: str
    ros: int  # the ROS of its code
    prefix: str  # of its MAJOR / MINOR / PATCH macros
    parenthesised: bool  # its header defines ``(28)``, not ``28``
    table: dict[str, tuple[int, int, int]]  # its version in each distribution
    default: str  # the distribution whose API the stand-ins follow
    macros: tuple[str, ...]  # what a condition on its version names
    string: str = ""  # the macro of its version as a string, if its header defines one

    def version(self, distro: str | None) -> tuple[int, int, int] | None:
        """Its version in ``distro``; None when that is no distribution of the table."""
        return self.table.get(distro.strip().lower()) if distro else None

    def flags(self, distro: str | None) -> list[str]:
        """The ``-D`` flags that announce its version in ``distro`` (none when the
        table has no such distribution: the stand-in announces ``default``'s)."""
        found = self.version(distro)
        return [] if found is None else self.announce(found)

    def announce(self, version: tuple[int, int, int]) -> list[str]:
        """The ``-D`` flags that announce ``version``: its MAJOR / MINOR / PATCH macros
        (and its string's, ``string``)."""
        parts = [f"({n})" if self.parenthesised else str(n) for n in version]
        found = [f"-D{self.prefix}_{name}={part}"
                 for name, part in zip(("MAJOR", "MINOR", "PATCH"), parts, strict=True)]
        if self.string:
            found.append(f'-D{self.string}="{".".join(map(str, version))}"')
        return found

    def describe(self, distro: str | None) -> str:
        """What the parse took its version to be, for a diagnostic."""
        found = self.version(distro)
        if found is not None:
            return f"{distro}'s ({self.name} {'.'.join(map(str, found))})"
        default = ".".join(map(str, self.table[self.default]))
        why = (f"{distro} is no ROS {self.ros} distribution of ours" if distro else
               f"no ROS {self.ros} distribution is known")
        return f"{self.default}'s ({self.name} {default}), as {why}"

    def others(self, conditions: Iterable[str] = ()) -> list[tuple[int, int, int]]:
        """The versions a unit is parsed again with, newest first (``Branch.taken``
        chooses): those of the table's distributions other than ``default``, and each
        version ``conditions`` name (``named``), a release the table does not list
        (navigation2's obstacle_layer.cpp:292 ``#elif RCLCPP_VERSION_GTE(29, 6, 0)``, a
        development version of rolling's between kilted's 29.5 and rolling's 30): the
        code's author built that branch with it."""
        own = self.table[self.default]
        found = {v for d, v in self.table.items() if d != self.default}
        for text in conditions:
            found |= {v for v in self.named(text) if v != own}
        return sorted(found, reverse=True)

    def named(self, text: str) -> set[tuple[int, int, int]]:
        """The versions condition ``text`` names: the least one of each test of the
        version against one (``RCLCPP_VERSION_GTE(29, 6, 0)``: 29.6.0) and, for each
        comparison of its MAJOR macro with a number N, N.0.0 and the next major's."""
        found = {(int(a), int(b), int(c)) for a, b, c in _AT_LEAST.findall(text)}
        for number in re.findall(rf"\b{self.prefix}_MAJOR\b\s*[<>=!]=?\s*\(?\s*(\d+)", text):
            found |= {(int(number), 0, 0), (int(number) + 1, 0, 0)}
        return found


# rclcpp's version in each ROS 2 distribution: the newest release of its branch listed by
# rclcpp's release repository (ros2-gbp/rclcpp-release, notes of 18 Nov 2025; iron and
# the older ones: their last release before the end of their support). Rolling moves on.
RCLCPP = Library(
    "rclcpp", 2, "RCLCPP_VERSION", True,
    {"foxy": (2, 4, 3), "galactic": (9, 2, 2), "humble": (16, 0, 16), "iron": (21, 0, 8),
     "jazzy": (28, 1, 14), "kilted": (29, 5, 5), "rolling": (30, 1, 3)},
    "jazzy",
    ("RCLCPP_VERSION_GTE", "RCLCPP_VERSION_MAJOR", "RCLCPP_VERSION_MINOR",
     "RCLCPP_VERSION_PATCH", "RCLCPP_VERSION_STR"), "RCLCPP_VERSION_STR")
# roscpp's (ros_comm's) version in each ROS 1 distribution: the package.xml of its
# branches (noetic-devel, melodic-devel, kinetic-devel of ros/ros_comm)
ROSCPP = Library(
    "roscpp", 1, "ROS_VERSION", False,
    {"kinetic": (1, 12, 17), "melodic": (1, 14, 13), "noetic": (1, 16, 0)},
    "noetic",
    ("ROS_VERSION_MINIMUM", "ROS_VERSION_GE", "ROS_VERSION_MAJOR", "ROS_VERSION_MINOR",
     "ROS_VERSION_PATCH"))
LIBRARIES = (RCLCPP, ROSCPP)


@dataclass(frozen=True)
class Branch:
    """A branch of an ``#if`` chain whose conditions name a version macro: its lines
    (from its directive to the chain's next one, both included) in one file."""

    first: int
    last: int
    statement: str  # its directive as written: ``#if``, ``#elif``, ``#else``
    text: str  # its condition; for an ``#else``, the chain's first on the version
    chain: frozenset[int]  # the chain's directive lines
    before: tuple[str, ...] = ()  # the conditions of the chain's directives before it

    def taken(self, library: Library, version: tuple[int, int, int]) -> bool | None:
        """Whether the preprocessor takes the branch when ``library`` is ``version``;
        None when a condition of the chain is more than the version (``holds``)."""
        earlier = [holds(text, library, version) for text in self.before]
        if any(e is True for e in earlier):
            return False
        own = True if self.statement == "#else" else holds(self.text, library, version)
        if own is False:
            return False
        return None if own is None or None in earlier else True

    def holds(self, line: int) -> bool:
        """Whether ``line`` is inside the branch (between its directives)."""
        return self.first < line < self.last

    def condition(self, location: Location) -> Condition:
        """The source condition a call made in the branch exists under: never decided
        (``graph.conditions`` decides no ``#`` statement), as the version is not known."""
        return Condition(self.text, "source", self.statement, location)


def branches(text: str, library: Library) -> list[Branch]:
    """The branches of each ``#if`` chain of ``text`` whose conditions name a version
    macro of ``library`` (``blocks_naming``), each with its own directive."""
    lines = text.splitlines()

    def directive(line: int) -> tuple[str, str]:
        match = recall.DIRECTIVE.match(lines[line - 1])
        if match is None:
            return "if", ""
        kind, rest = match.group(1), match.group(2).split("//", 1)[0].strip()
        if kind in ("ifdef", "ifndef"):  # as a condition: ``defined(X)``, ``!defined(X)``
            rest = f"{'!' if kind == 'ifndef' else ''}defined({rest})"
        return kind, rest

    found = []
    for first, last, condition, chain in blocks_naming(text, _names(library)):
        kind, own = directive(first)
        before = tuple(directive(line)[1] for line in sorted(chain) if line < first)
        found.append(Branch(first, last, f"#{kind}",
                            own if kind not in ("else", "endif") and own else condition,
                            chain, before))
    return found


# a test of the version against one, ``RCLCPP_VERSION_GTE(29, 0, 0)``,
# ``ROS_VERSION_MINIMUM(1, 13, 1)``
_AT_LEAST = re.compile(r"\b(?:RCLCPP_VERSION_GTE|ROS_VERSION_MINIMUM)\s*\(\s*(\d+)\s*,"
                       r"\s*(\d+)\s*,\s*(\d+)\s*\)")
_WORD = re.compile(r"[A-Za-z_]\w*")
_LOGIC = frozenset({"and", "or", "not", "True", "False"})


def holds(text: str, library: Library, version: tuple[int, int, int]) -> bool | None:
    """Whether the ``#if`` condition ``text`` holds when ``library`` is ``version``:
    read when it tests only the version (``_AT_LEAST``, its MAJOR / MINOR / PATCH
    macros, numbers, comparisons, ``&&``, ``||``, ``!``); None for anything more."""
    read = _AT_LEAST.sub(
        lambda m: " True " if version >= tuple(int(g) for g in m.groups()) else " False ",
        text)
    for part, number in zip(("MAJOR", "MINOR", "PATCH"), version, strict=True):
        read = re.sub(rf"\b{library.prefix}_{part}\b", str(number), read)
    read = re.sub(r"!(?!=)", " not ", read.replace("&&", " and ").replace("||", " or "))
    if any(word not in _LOGIC for word in _WORD.findall(read)):
        return None
    value = evaluate(read)
    return bool(value) if isinstance(value, (bool, int)) else None


def skipped_for(branch: Branch, skipped: list[tuple[int, int]]) -> bool:
    """Whether the parse skipped ``branch`` for its chain (``skipped``: the
    preprocessor's skipped line ranges of the file), not inside code skipped for
    another reason."""
    return any(start in branch.chain and start <= branch.first and branch.last <= end
               for start, end in skipped)


def flags(distro: str | None) -> list[str]:
    """The ``-D`` flags that make the stand-ins announce the client library of
    ``distro`` (none for a distribution we do not know)."""
    found: list[str] = []
    for library in LIBRARIES:
        found += library.flags(distro)
    return found


def name_pattern(library: Library) -> re.Pattern[str]:
    """What finds a version macro of ``library`` in a condition."""
    return _names(library)


def _names(library: Library) -> re.Pattern[str]:
    return re.compile(r"\b(?:" + "|".join(library.macros) + r")\b")


def version_blocks(text: str, library: Library
                   ) -> list[tuple[int, int, str, frozenset[int]]]:
    """(first line, last line, condition, the chain's directive lines) of each branch of
    each ``#if`` chain of ``text`` whose conditions name a version macro of ``library``."""
    return blocks_naming(text, _names(library))


def blocks_naming(text: str, names: re.Pattern[str]
                  ) -> list[tuple[int, int, str, frozenset[int]]]:
    """(first line, last line, condition, the chain's directive lines) of each branch of
    each ``#if`` chain of ``text`` whose conditions name a macro ``names`` finds: a
    branch runs from its directive to the chain's next one (1-based, both included)."""
    found: list[tuple[int, int, str, frozenset[int]]] = []
    # per open chain: its directive lines and the conditions that name such a macro
    stack: list[tuple[list[int], list[str]]] = []
    for number, line in enumerate(text.splitlines(), 1):
        match = recall.DIRECTIVE.match(line)
        if match is None:
            continue
        kind, rest = match.group(1), match.group(2).strip()
        if kind in ("if", "ifdef", "ifndef"):
            stack.append(([number], [rest] if names.search(rest) else []))
        elif not stack:
            continue  # a directive of an unbalanced file
        elif kind in ("elif", "else"):
            stack[-1][0].append(number)
            if kind == "elif" and names.search(rest):
                stack[-1][1].append(rest)
        else:  # endif
            marks, conditions = stack.pop()
            if conditions:
                marks.append(number)
                chain = frozenset(marks)
                found.extend((marks[i], marks[i + 1], conditions[0], chain)
                             for i in range(len(marks) - 1))
    return found


def unknown_version_calls(text: str, skipped: list[tuple[int, int]], library: Library
                          ) -> list[tuple[int, str, str]]:
    """(line, call text, condition) of the first ROS API call (``recall.call_sites``)
    of each branch of a condition on ``library``'s version that the parse skipped for that
    condition (``skipped``: the preprocessor's skipped line ranges of the file, each from
    the directive that began skipping; not a branch inside code skipped for another
    reason, ``#ifdef _WIN32`` around it)."""
    return skipped_calls(text, skipped, _names(library))


def skipped_calls(text: str, skipped: list[tuple[int, int]], names: re.Pattern[str]
                  ) -> list[tuple[int, str, str]]:
    """(line, call text, condition) of the first ROS API call of each branch of an
    ``#if`` chain whose conditions name a macro ``names`` finds, where the parse skipped
    that branch for that chain (``unknown_version_calls``)."""
    if not skipped:
        return []
    blocks = blocks_naming(text, names)
    if not blocks:
        return []
    sites = recall.call_sites(text)
    found: list[tuple[int, str, str]] = []
    for first, last, condition, chain in blocks:
        if not any(start in chain and start <= first and last <= end
                   for start, end in skipped):
            continue
        site = recall.first_site(sites, first, last)
        if site is not None:
            found.append((site.line, site.text, condition))
    return found
