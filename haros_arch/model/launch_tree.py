"""How the launch files of a configuration make its nodes: the launch tree.

One type for ROS 1 and ROS 2. A ``LaunchItem`` is a launch file (reached by an include,
or the file the configuration names), a group (``<group>``, ``GroupAction``), a node, or
a part that a decided condition left out (``skipped``: what the other value would have
started). Each keeps the arguments it was given, with where their values came from, and
the remaps and parameters set in its scope. The loaders record it as they walk.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any, Literal

from .location import NOWHERE, Location

# where an argument's value came from: its declared default, a value fixed where it is
# declared, the file that included this one, the command line (or project file), or none
ArgOrigin = Literal["default", "value", "include", "command line", "unset"]
ItemKind = Literal["file", "group", "node", "include"]
# how an included file uses an argument its include passes (ROS 2): it declares it, reads
# it without declaring it, neither, or what was not seen of it may (``LaunchArg.use``)
ArgUse = Literal["", "declared", "read", "unused", "unknown"]
OPTIONAL: dict[str, Any] = {"optional": True}


@dataclass
class LaunchArg:
    name: str
    value: str | None  # final text, ``?`` for unknown parts; None when nothing set it
    origin: ArgOrigin = "default"
    location: Location = NOWHERE  # where that value was written
    # an argument a ROS 2 include passes: how the included file (and what it includes in
    # turn) uses it; "" for any other argument
    use: ArgUse = field(default="", metadata=OPTIONAL)
    unseen: str = field(default="", metadata=OPTIONAL)  # "unknown": the part not seen


@dataclass
class LaunchCondition:
    """An ``if``/``unless`` (``IfCondition``/``UnlessCondition``) on an item."""

    text: str  # as written
    statement: str = "if"
    values: dict[str, str | None] = field(default_factory=dict)  # arguments it reads
    holds: bool | None = None  # the part is kept (True), left out (False) or unknown


@dataclass
class LaunchItem:
    kind: ItemKind
    name: str  # file: its path; group: its namespace; node: its final full name
    location: Location = NOWHERE  # file: the include that reached it; else where written
    namespace: str = field(default="", metadata=OPTIONAL)  # in effect for its contents
    # node: package/executable; include: "action" for an action not interpreted
    detail: str = field(default="", metadata=OPTIONAL)
    condition: LaunchCondition | None = field(default=None, metadata=OPTIONAL)
    skipped: bool = field(default=False, metadata=OPTIONAL)  # left out by its condition
    args: list[LaunchArg] = field(default_factory=list, metadata=OPTIONAL)
    pushed: list[str] = field(default_factory=list, metadata=OPTIONAL)  # ROS 2 namespaces
    remaps: list[tuple[str, str]] = field(default_factory=list, metadata=OPTIONAL)
    params: list[str] = field(default_factory=list, metadata=OPTIONAL)  # names set here
    children: list[LaunchItem] = field(default_factory=list, metadata=OPTIONAL)

    def add(self, child: LaunchItem) -> LaunchItem:
        if len(self.children) < MAX_CHILDREN:
            self.children.append(child)
        return child

    def arg(self, name: str) -> LaunchArg | None:
        return next((a for a in self.args if a.name == name), None)

    def walk(self) -> list[LaunchItem]:
        """This item and every item under it, depth first (iterative: bounded stack)."""
        out: list[LaunchItem] = []
        stack = [self]
        while stack:
            item = stack.pop()
            out.append(item)
            stack.extend(reversed(item.children))
        return out


NEAR_NAMES = 6  # declared arguments a finding names beside the one passed


@dataclass(frozen=True)
class IncludeArg:
    """An argument a ROS 2 include passes (``launch_arguments``, ``<arg>`` of an
    ``<include>``), with how the included file, and the files it includes in turn, use
    it (``use``: "declared", "read", "unused", or "unknown" with the part not seen in
    ``unseen``) and the arguments the included file declares itself."""

    name: str
    value: str | None
    use: str
    unseen: str
    file: str  # the included file, as the launch tree names it
    declared: tuple[str, ...]
    location: Location  # the include

    @property
    def hint(self) -> str:
        """What the included file declares instead, the names near this one first."""
        from ..query.absence import distance

        near = [d for d in self.declared if d != self.name and (
            self.name in d or d in self.name or distance(self.name, d) <= 2)]
        if near:
            return f" (it declares {', '.join(near[:NEAR_NAMES])})"
        if not self.declared:
            return " (it declares no argument)"
        more = (f" and {len(self.declared) - NEAR_NAMES} more"
                if len(self.declared) > NEAR_NAMES else "")
        return f" (it declares {', '.join(self.declared[:NEAR_NAMES])}{more})"


def include_args(tree: Iterable[LaunchItem]) -> list[IncludeArg]:
    """The arguments the includes of ``tree`` pass, as ``LaunchArg.use`` recorded them."""
    found: list[IncludeArg] = []
    for root in tree:
        for item in root.walk():
            if item.kind != "file":
                continue
            declared = tuple(dict.fromkeys(a.name for a in item.args
                                           if a.use in ("", "declared")))
            found.extend(IncludeArg(a.name, a.value, a.use, a.unseen, item.name, declared,
                                    a.location) for a in item.args if a.use)
    return found


@dataclass(frozen=True)
class PackageUse:
    """A package a launch file names, where it is written: a node of it started
    (``kind`` "node": ``pkg=``, ``package=``, a component's package) or a file of it
    named (``kind`` "file": ``$(find pkg)``, ``$(find-pkg-share pkg)``,
    ``FindPackageShare``, ``get_package_share_directory``: an include, a parameter file,
    a robot description). ``package`` has ``?`` for parts not known statically;
    ``location.package`` is the launch file's own package (None outside the workspace's
    packages); ``test``: the launch file is one rostest or launch_testing runs (under the
    package's test/ or tests/ folder, a ``.test`` file) or the node is a ``<test>``."""

    package: str
    location: Location
    kind: str = "file"
    test: bool = False
    # a ROS 2 Python launch file's use under ``if 'G' in get_packages_with_prefixes():``
    # (or ``has_resource('packages', 'G')``): G, the package whose installation the file
    # checks before it uses this one, so it runs without them
    guard: str | None = field(default=None, metadata=OPTIONAL)
    # the launch configurations (comma-separated) the package's name is made of that
    # the launch file itself neither declares nor sets: their values are the choice of
    # the file that includes it, so which package this file uses is not its own
    chosen_by: str = field(default="", metadata=OPTIONAL)

    @property
    def user(self) -> str | None:
        return self.location.package

    @property
    def optional(self) -> bool:
        """Used only where the launch file found it (or the installed metapackage of
        the shipped table that brings it) installed: a run dependency it need not
        declare."""
        if self.guard is None:
            return False
        if self.guard == self.package:
            return True
        from ..models.metapackages import members  # the installed metapackages' table

        return self.package in members(self.guard, 2)


# ``'G' in get_packages_with_prefixes()`` (ament_index_python: every installed package)
# and ``has_resource('packages', 'G')``: a test of whether package G is installed
_IN_INSTALLED = re.compile(
    r"""\s*(['"])([A-Za-z_][\w.-]*)\1\s+in\s+(?:[\w.]+\.)?get_packages_with_prefixes"""
    r"""\(\s*\)\s*""")
_HAS_PACKAGE = re.compile(
    r"""\s*(?:[\w.]+\.)?has_resource\(\s*(['"])packages\1\s*,\s*(['"])([A-Za-z_][\w.-]*)"""
    r"""\2\s*\)\s*""")


def installed_check(texts: Iterable[str]) -> str | None:
    """The package whose installation one of ``texts`` (Python ``if`` tests a launch
    file is under, each maybe a conjunction with ``and``) checks, the innermost first."""
    for text in reversed(list(texts)):
        for part in reversed(text.split(" and ")):
            found = _IN_INSTALLED.fullmatch(part)
            if found is not None:
                return found.group(2)
            found = _HAS_PACKAGE.fullmatch(part)
            if found is not None:
                return found.group(3)
    return None


def use_from_data(data: Any) -> PackageUse | None:
    """The inverse of ``serialise.to_data`` for one package use."""
    if not isinstance(data, dict) or not isinstance(data.get("package"), str):
        return None
    guard = data.get("guard")
    chosen = data.get("chosen_by")
    return PackageUse(data["package"], _location(data.get("location")),
                      str(data.get("kind", "file")), bool(data.get("test", False)),
                      guard if isinstance(guard, str) else None,
                      chosen if isinstance(chosen, str) else "")


MAX_CHILDREN = 5_000
MAX_DEPTH = 256  # items nested deeper are not read back (includes nest 32 deep at most)


def _location(data: Any) -> Location:
    if not isinstance(data, dict):
        return NOWHERE
    return Location(data.get("package"), data.get("file"), int(data.get("line") or 0),
                    int(data.get("column") or 0))


def _use(data: Any) -> ArgUse:
    return data if data in ("declared", "read", "unused", "unknown") else ""


def item_from_data(data: Any, depth: int = 0) -> LaunchItem | None:
    """The inverse of ``serialise.to_data`` for one item; None if it is not one."""
    if not isinstance(data, dict) or depth > MAX_DEPTH:
        return None
    cond = data.get("condition")
    condition = LaunchCondition(
        str(cond.get("text", "")), str(cond.get("statement", "if")),
        dict(cond.get("values") or {}), cond.get("holds")) if isinstance(cond, dict) else None
    item = LaunchItem(
        data.get("kind", "file"), str(data.get("name", "")), _location(data.get("location")),
        str(data.get("namespace", "")), str(data.get("detail", "")), condition,
        bool(data.get("skipped", False)),
        [LaunchArg(str(a.get("name", "")), a.get("value"), a.get("origin", "default"),
                   _location(a.get("location")), _use(a.get("use")),
                   str(a.get("unseen") or "")) for a in data.get("args") or ()
         if isinstance(a, dict)],
        [str(p) for p in data.get("pushed") or ()],
        [(str(r[0]), str(r[1])) for r in data.get("remaps") or () if len(r) == 2],
        [str(p) for p in data.get("params") or ()])
    for child in data.get("children") or ():
        made = item_from_data(child, depth + 1)
        if made is not None:
            item.children.append(made)
    return item
