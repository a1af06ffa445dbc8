"""The loader's scope, as roslaunch's ``LoaderContext``, and ROS name helpers.

Rules kept from roslaunch: a child scope (``<group>``, ``<node>``, ``<include>``) gets
a copy of the arguments, argument names, anonymous names and environment; remaps of a
child override the parent's with the same ``from``; the list of ``~params`` is shared
with the parent when the parent already has some (roslaunch's ``params or []``), and a
``<group>`` takes a copy of it; an ``<include>`` starts with only the arguments passed
to it and fresh anonymous names.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from typing import Any

from ...model.conditions import Condition
from ...model.launch_tree import LaunchItem
from ...model.location import NOWHERE, Location
from ...model.values import Unknown, Value
from .params import join

# the unknowns that stand for one value wherever they are used: a substitution of an
# argument or an environment variable (the command line's ``$(arg rig)`` is one value in
# every namespace made of it); an unknown computed otherwise ($(eval) over known values
# that may differ, a package not found) is not known to equal another of its spelling
_ONE_VALUE = re.compile(r"(?:arg|env) \S+")


def same_unknowns(one: tuple[Unknown, ...], other: tuple[Unknown, ...]) -> bool:
    """Whether two names of one spelling with the unknown parts ``one`` and ``other``
    (in order) are certainly one name: each pair of parts is one argument or
    environment variable not known here, so whatever value it has, both have it.
    Two nodes of ``/dvrk/$(arg master)/joint_state_publisher`` and
    ``/dvrk/$(arg slave)/joint_state_publisher`` collide only when the two arguments
    are given one value. An ``$(anon x)`` is one value in one file and another in each
    include of it: the same unknown object (``Scope.anon``)."""
    return len(one) == len(other) and all(
        a is b or (a == b and not a.causes and _ONE_VALUE.fullmatch(a.origin) is not None)
        for a, b in zip(one, other, strict=True))


def unknown_parts(value: Value | None) -> tuple[Unknown, ...]:
    """The unknown parts of ``value``, in order (none of None)."""
    return () if value is None else tuple(p for p in value.parts if isinstance(p, Unknown))


def canonical(name: str) -> str:
    """rosgraph's ``canonicalize_name``: no repeated or trailing slashes."""
    if not name or name == "/":
        return name
    inner = "/".join(x for x in name.split("/") if x)
    return "/" + inner if name.startswith("/") else inner


def global_ns(name: str) -> str:
    """rosgraph's ``make_global_ns`` (with roslaunch's ``//`` squeezing)."""
    if not name.startswith("/"):
        name = "/" + name
    if not name.endswith("/"):
        name += "/"
    return re.sub("//+", "/", name)


@dataclass
class PrivateParam:
    """A ``~param`` held by a scope until a node takes it."""

    name: str
    value: Any
    kind: str | None
    conditions: tuple[Condition, ...]
    location: Location = NOWHERE
    source: str = "value"
    command: str | None = None  # the command line of ``command=``


@dataclass
class Scope:
    ns: str  # global namespace with a trailing slash
    filename: str  # for $(dirname)
    path: str  # the file being read, for locations
    args: dict[str, Value] = field(default_factory=dict)
    arg_names: list[str] = field(default_factory=list)
    # the conditions each argument was declared under, once per declaration: roslaunch
    # declares an <arg> only where its if / unless holds, so two declarations of a name
    # under conditions that cannot both hold (unless="$(arg sim)" and if="$(arg sim)")
    # are one argument of either value; a name not here was declared unconditionally
    arg_conditions: dict[str, list[tuple[Condition, ...]]] = field(default_factory=dict)
    include_args: dict[str, Value] | None = None
    pass_all_args: bool = False
    remaps: tuple[tuple[str, str], ...] = ()
    # where each of ``remaps`` is written (its ``<remap>`` element), by its pair
    remap_places: tuple[tuple[tuple[str, str], Location], ...] = ()
    private: list[PrivateParam] = field(default_factory=list)
    env: list[tuple[str, str]] = field(default_factory=list)
    anon: dict[str, Unknown] = field(default_factory=dict)
    conditions: tuple[Condition, ...] = ()
    in_include: bool = False
    # while an <include>'s own <arg>s are read: the arguments the including file declares,
    # which their values may name (``include_args`` is set then)
    outer_arg_names: tuple[str, ...] = ()
    # the file gets every argument of the command line: the top-level file, and a file
    # such a file includes with pass_all_args (roslaunch passes its whole arg_dict, what
    # the command line gives too); an argument it declares without a value is the
    # command line's to give (LAUNCH_ARG_UNSET), not one the include forgot to pass
    command_line: bool = True
    # the files being read, outermost first, each with the arguments it was given
    stack: tuple[tuple[str, tuple[tuple[str, str | None], ...]], ...] = ()
    # the launch tree's file or group being read (shared by the scopes made from it)
    item: LaunchItem = field(default_factory=lambda: LaunchItem("file", ""))
    # the unknown parts of ``ns``, in order (each ``?`` of it): which values they are
    # (``same_unknowns``)
    ns_unknowns: tuple[Unknown, ...] = ()
    # the include, written in a workspace file, through which an installed package's own
    # launch file (read from its model, upstream) is read: what the workspace can change
    # about a problem said there (``Loader.report``); None in the workspace's files
    reached_from: Location | None = None

    @classmethod
    def root(cls, path: str, args: dict[str, Value], namespace: str = "/") -> Scope:
        return cls(global_ns(namespace or "/"), path, path, args=dict(args))

    def child(self, ns: str | None, unknowns: tuple[Unknown, ...] = ()) -> Scope:
        """A scope in namespace ``ns`` (relative to this one's unless global), whose
        unknown parts are ``unknowns``."""
        child_ns = (ns if ns.startswith("/") else join(self.ns, ns)) if ns else self.ns
        held = (unknowns if ns.startswith("/") else (*self.ns_unknowns, *unknowns)) if ns \
            else self.ns_unknowns
        return replace(
            self, ns=global_ns(child_ns), args=dict(self.args), arg_names=list(self.arg_names),
            arg_conditions={k: list(v) for k, v in self.arg_conditions.items()},
            pass_all_args=False, private=self.private if self.private else [],
            env=list(self.env), anon=dict(self.anon), ns_unknowns=held)

    def include_child(self, ns: str | None, filename: str,
                      unknowns: tuple[Unknown, ...] = ()) -> Scope:
        inner = self.child(ns, unknowns)
        inner.outer_arg_names = tuple(self.arg_names)
        inner.arg_names = []
        inner.arg_conditions = {}
        inner.filename = filename
        inner.include_args = {}
        return inner

    def enter_include(self) -> list[str]:
        """Swap in the arguments passed to an include; returns their names."""
        passed = self.include_args or {}
        self.arg_names = []
        self.arg_conditions = {}
        self.args = dict(passed)
        self.include_args = None
        self.outer_arg_names = ()
        self.command_line = self.command_line and self.pass_all_args
        self.anon = {}
        self.in_include = True
        return list(passed)

    def conditional(self, text: str, statement: str, where: Location) -> Scope:
        cond = Condition(text, "launch", statement, where)
        return replace(self, conditions=(*self.conditions, cond))

    def add_remap(self, pair: tuple[str, str], where: Location | None = None) -> None:
        self.remaps = (*(r for r in self.remaps if r[0] != pair[0]), pair)
        kept = tuple(p for p in self.remap_places if p[0][0] != pair[0])
        self.remap_places = (*kept, (pair, where)) if where is not None else kept

    def add_private(self, param: PrivateParam) -> None:
        for index in range(len(self.private) - 1, -1, -1):
            if self.private[index].name == param.name:
                del self.private[index]
        self.private.append(param)
