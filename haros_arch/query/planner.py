"""The FLWR planner: split ``where`` into conjuncts, push each down to the first ``for``
level where its variables are bound, and turn ``a == b`` between a new variable and
earlier ones into a hash join.

The plan keeps pyflwor's result order: bindings come out in the order of the cartesian
product of the ``for`` sources, as nested loops would give them.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from . import syntax as s


@dataclass
class Level:
    """One ``for`` variable: where its values come from and what is checked there."""

    var: str
    source: s.Expr
    correlated: bool  # the source reads earlier variables: evaluate per binding
    filters: list[s.Expr] = field(default_factory=list)
    probe: s.Expr | None = None  # hash join: evaluated over earlier variables
    build: s.Expr | None = None  # ... and over this variable, on each source value
    join: s.Compare | None = None  # the conjunct the join replaces


@dataclass
class Plan:
    levels: list[Level]
    residual: list[s.Expr]  # checked after the lets, in the written order


def conjuncts(expr: s.Expr | None) -> list[s.Expr]:
    if expr is None:
        return []
    out: list[s.Expr] = []
    stack = [expr]
    while stack:
        item = stack.pop()
        if isinstance(item, s.And):
            stack.extend((item.right, item.left))
        else:
            out.append(item)
    return out


def plan(flwr: s.Flwr) -> Plan:
    names = [var for var, _ in flwr.fors]
    lets = {var for var, _ in flwr.lets}
    levels = []
    for i, (var, source) in enumerate(flwr.fors):
        earlier = set(names[:i])
        levels.append(Level(var, source, bool(s.free_names(source) & (earlier | {var}))))
    residual: list[s.Expr] = []
    for conjunct in conjuncts(flwr.where):
        used = s.free_names(conjunct)
        if used & lets or not levels:
            residual.append(conjunct)
            continue
        at = max((names.index(v) for v in used if v in names), default=0)
        levels[at].filters.append(conjunct)
    for i, level in enumerate(levels):
        if i == 0 or level.correlated:
            continue
        earlier = set(names[:i])
        for conjunct in level.filters:
            if not (isinstance(conjunct, s.Compare) and conjunct.op == "=="):
                continue
            sides = (conjunct.left, conjunct.right)
            for mine, theirs in (sides, sides[::-1]):
                mine_vars = s.free_names(mine) & set(names)
                their_vars = s.free_names(theirs) & set(names)
                if mine_vars == {level.var} and their_vars and their_vars <= earlier \
                        and "self" not in s.free_names(mine):
                    level.probe, level.build, level.join = theirs, mine, conjunct
                    break
            if level.join is not None:
                level.filters.remove(conjunct)
                break
    return Plan(levels, residual)
