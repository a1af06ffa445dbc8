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


def unbound_names(node: Expr, found: dict[int, frozenset[str]] | None = None
                  ) -> frozenset[str]:
    """The names ``node`` reads that no binder inside it binds: a path step's ``self``, a
    quantifier's variable, a FLWR's ``for`` and ``let`` variables are bound in their
    bodies. ``found`` collects the answer for every sub-expression (by ``id``)."""
    found = {} if found is None else found
    known = found.get(id(node))
    if known is not None:
        return known

    def free(child: Expr | None) -> frozenset[str]:
        return frozenset() if child is None else unbound_names(child, found)

    names: set[str] = set()
    if isinstance(node, Name):
        names.add(node.name)
    elif isinstance(node, Path):
        names.add(node.steps[0].name)
        for step in node.steps:
            names |= free(step.where) - {"self"}
            found[id(step)] = free(step.where) - {"self"}
    elif isinstance(node, Quantified):
        names |= free(node.source) | (free(node.condition) - {node.var})
    elif isinstance(node, Flwr):
        bound: set[str] = set()
        for var, source in (*node.fors, *node.lets):
            names |= free(source) - bound
            bound.add(var)
        for part in (node.where, *node.returns):
            names |= free(part) - bound
    else:
        for child in children(node):
            names |= free(child)
    result = frozenset(names)
    found[id(node)] = result
    return result


def binders(node: Expr) -> set[str]:
    """Every name a binder anywhere in ``node`` binds (``self`` when a path filters)."""
    names: set[str] = set()
    stack = [node]
    while stack:
        item = stack.pop()
        if isinstance(item, Step) and item.where is not None:
            names.add("self")
        elif isinstance(item, Quantified):
            names.add(item.var)
        elif isinstance(item, Flwr):
            names.update(var for var, _ in (*item.fors, *item.lets))
        stack.extend(children(item))
    return names


def invariants(root: Expr, free: dict[int, frozenset[str]], bound: set[str]) -> set[int]:
    """The ``id``s of the largest sub-expressions below ``root`` that read no bound
    variable: their value is the same on every iteration of an enclosing filter,
    quantifier or FLWR, so an evaluation computes each once (``parameters[...]`` inside a
    ``for`` is not filtered again for every outer binding). ``free`` and ``bound``:
    ``unbound_names``'s answers for every sub-expression of ``root`` and
    ``binders(root)``."""
    hoisted: set[int] = set()
    stack = list(children(root))
    while stack:
        item = stack.pop()
        if not isinstance(item, Literal | Name | Step) and not (free[id(item)] & bound):
            hoisted.add(id(item))
            continue
        stack.extend(children(item))
    return hoisted
