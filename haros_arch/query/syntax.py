"""The query AST: small frozen values, each with ``pos`` (its offset in the query text)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass(frozen=True)
class Expr:
    pos: int = field(default=0, compare=False, kw_only=True)


@dataclass(frozen=True)
class Literal(Expr):
    value: Any


@dataclass(frozen=True)
class Name(Expr):
    name: str


@dataclass(frozen=True)
class Attr(Expr):
    obj: Expr
    name: str


@dataclass(frozen=True)
class Call(Expr):
    func: Expr
    args: tuple[Expr, ...]


@dataclass(frozen=True)
class Index(Expr):
    obj: Expr
    key: Expr


@dataclass(frozen=True)
class ListOf(Expr):
    items: tuple[Expr, ...]


@dataclass(frozen=True)
class Arith(Expr):
    op: str  # + - * / %
    left: Expr
    right: Expr


@dataclass(frozen=True)
class Neg(Expr):
    operand: Expr


@dataclass(frozen=True)
class Compare(Expr):
    op: str  # == != < <= > >= in "not in"
    left: Expr
    right: Expr


@dataclass(frozen=True)
class SetCompare(Expr):
    op: str  # subset superset "proper subset" "proper superset" is "is not"
    left: Expr
    right: Expr


@dataclass(frozen=True)
class And(Expr):
    left: Expr
    right: Expr


@dataclass(frozen=True)
class Or(Expr):
    left: Expr
    right: Expr


@dataclass(frozen=True)
class Not(Expr):
    operand: Expr


@dataclass(frozen=True)
class Quantified(Expr):
    mode: str  # some | every
    var: str
    source: Expr
    condition: Expr


@dataclass(frozen=True)
class Step(Expr):
    name: str
    where: Expr | None = None


@dataclass(frozen=True)
class Path(Expr):
    steps: tuple[Step, ...]


@dataclass(frozen=True)
class SetOp(Expr):
    op: str  # | & -
    left: Expr
    right: Expr


@dataclass(frozen=True)
class Flwr(Expr):
    fors: tuple[tuple[str, Expr], ...]
    lets: tuple[tuple[str, Expr], ...]
    where: Expr | None
    returns: tuple[Expr, ...]
    keys: tuple[str, ...] | None  # named return values, else positional


def children(node: Expr) -> list[Expr]:
    """The sub-expressions of ``node`` (for walks that must not recurse)."""
    found: list[Expr] = []
    for value in vars(node).values():
        if isinstance(value, Expr):
            found.append(value)
        elif isinstance(value, tuple):
            for item in value:
                if isinstance(item, Expr):
                    found.append(item)
                elif isinstance(item, tuple):
                    found.extend(x for x in item if isinstance(x, Expr))
    return found


def free_names(node: Expr) -> set[str]:
    """Names a query reads from its context (an over-approximation: bound ones too)."""
    names: set[str] = set()
    stack = [node]
    while stack:
        item = stack.pop()
        if isinstance(item, Name):
            names.add(item.name)
        elif isinstance(item, Path) and item.steps:
            names.add(item.steps[0].name)
        stack.extend(children(item))
    return names


def depth(node: Expr) -> int:
    """The nesting depth of the tree, measured without recursion."""
    deepest = 0
    stack = [(node, 1)]
    while stack:
        item, level = stack.pop()
        deepest = max(deepest, level)
        stack.extend((child, level + 1) for child in children(item))
    return deepest
