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
``default``'s version, and in a unit of that ROS a ROS call in a block that a condition
on the version leaves out is ``CPP_VERSION_UNKNOWN`` (``unknown_version_calls``), which
makes the node partial: on another release the code makes that call.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from . import recall


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

    def version(self, distro: str | None) -> tuple[int, int, int] | None:
        """Its version in ``distro``; None when that is no distribution of the table."""
        return self.table.get(distro.strip().lower()) if distro else None

    def flags(self, distro: str | None) -> list[str]:
        """The ``-D`` flags that announce its version in ``distro`` (none when the
        table has no such distribution: the stand-in announces ``default``'s)."""
        found = self.version(distro)
        if found is None:
            return []
        parts = [f"({n})" if self.parenthesised else str(n) for n in found]
        return [f"-D{self.prefix}_{name}={part}"
                for name, part in zip(("MAJOR", "MINOR", "PATCH"), parts, strict=True)]

    def describe(self, distro: str | None) -> str:
        """What the parse took its version to be, for a diagnostic."""
        found = self.version(distro)
        if found is not None:
            return f"{distro}'s ({self.name} {'.'.join(map(str, found))})"
        default = ".".join(map(str, self.table[self.default]))
        why = (f"{distro} is no ROS {self.ros} distribution of ours" if distro else
               f"no ROS {self.ros} distribution is known")
        return f"{self.default}'s ({self.name} {default}), as {why}"


# rclcpp's version in each ROS 2 distribution: the newest release of its branch listed by
# rclcpp's release repository (ros2-gbp/rclcpp-release, notes of 18 Nov 2025; iron and
# the older ones: their last release before the end of their support). Rolling moves on.
RCLCPP = Library(
    "rclcpp", 2, "RCLCPP_VERSION", True,
    {"foxy": (2, 4, 3), "galactic": (9, 2, 2), "humble": (16, 0, 16), "iron": (21, 0, 8),
     "jazzy": (28, 1, 14), "kilted": (29, 5, 5), "rolling": (30, 1, 3)},
    "jazzy",
    ("RCLCPP_VERSION_GTE", "RCLCPP_VERSION_MAJOR", "RCLCPP_VERSION_MINOR",
     "RCLCPP_VERSION_PATCH", "RCLCPP_VERSION_STR"))
# roscpp's (ros_comm's) version in each ROS 1 distribution: the package.xml of its
# branches (noetic-devel, melodic-devel, kinetic-devel of ros/ros_comm)
ROSCPP = Library(
    "roscpp", 1, "ROS_VERSION", False,
    {"kinetic": (1, 12, 17), "melodic": (1, 14, 13), "noetic": (1, 16, 0)},
    "noetic",
    ("ROS_VERSION_MINIMUM", "ROS_VERSION_GE", "ROS_VERSION_MAJOR", "ROS_VERSION_MINOR",
     "ROS_VERSION_PATCH"))
LIBRARIES = (RCLCPP, ROSCPP)


def flags(distro: str | None) -> list[str]:
    """The ``-D`` flags that make the stand-ins announce the client library of
    ``distro`` (none for a distribution we do not know)."""
    found: list[str] = []
    for library in LIBRARIES:
        found += library.flags(distro)
    major, minor, patch = RCLCPP.version(distro) or (None, None, None)
    if major is not None:
        found.append(f'-DRCLCPP_VERSION_STR="{major}.{minor}.{patch}"')
    return found


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
