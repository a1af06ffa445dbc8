"""roslaunch substitution args (``$(arg x)``, ``$(find pkg)``, ...) over partial values.

A substitution whose value cannot be known (an argument nobody set, an environment
variable that is not in the configuration) gives an ``Unknown`` part; the text around
it is kept.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from ...model.values import Unknown, Value

_SUBST = re.compile(r"\$\(([a-z_]+)((?:\s+[^()\s]+)*)\s*\)")


class SubstitutionError(Exception):
    """A substitution that roslaunch would reject (wrong arity, unknown command)."""


@dataclass
class Context:
    """What substitutions may read: arguments, environment, packages, the file."""

    args: Mapping[str, Value | None]
    environment: Mapping[str, str]
    find: Callable[[str], str | None]
    filename: str
    anon: dict[str, Unknown] = field(default_factory=dict)
    unset: list[str] = field(default_factory=list)  # names of unset args that were used
    unsupported: list[str] = field(default_factory=list)


def substitute(text: str, ctx: Context) -> Value:
    """Resolve every ``$(...)`` in ``text``, left to right as roslaunch does."""
    if text.lstrip().startswith("$(eval"):
        ctx.unsupported.append(text.strip())
        return Value.unknown(text.strip())
    parts: list[Value | str] = []
    pos = 0
    for match in _SUBST.finditer(text):
        parts.append(text[pos:match.start()])
        command, args = match.group(1), match.group(2).split()
        parts.append(_one(command, args, match.group(0), ctx))
        pos = match.end()
    parts.append(text[pos:])
    return Value.of(*parts)


def _one(command: str, args: list[str], raw: str, ctx: Context) -> Value:
    if command == "arg":
        _arity(raw, args, 1)
        if args[0] not in ctx.args:
            raise SubstitutionError(f"arg '{args[0]}' is not declared")
        value = ctx.args[args[0]]
        if value is None:
            ctx.unset.append(args[0])
            return Value.unknown(f"arg {args[0]}")
        return value
    if command in ("env", "optenv"):
        if command == "env":
            _arity(raw, args, 1)
        elif not args:
            raise SubstitutionError(f"{raw}: $(optenv) needs a variable name")
        if args[0] in ctx.environment:
            return Value.of(ctx.environment[args[0]])
        if command == "optenv":
            return Value.of(" ".join(args[1:]))
        return Value.unknown(f"env {args[0]}")
    if command == "find":
        _arity(raw, args, 1)
        path = ctx.find(args[0])
        return Value.of(path) if path is not None else Value.unknown(f"find {args[0]}")
    if command == "anon":
        _arity(raw, args, 1)
        # roslaunch appends host, pid and a random number: unknown, but the same
        # unknown for every use of one name within the file
        return Value.of(args[0] + "_", ctx.anon.setdefault(args[0], Unknown(raw)))
    if command == "dirname":
        _arity(raw, args, 0)
        return Value.of(os.path.dirname(ctx.filename))
    if command == "eval":
        ctx.unsupported.append(raw)
        return Value.unknown(raw)
    raise SubstitutionError(f"unknown substitution {raw}")


def _arity(raw: str, args: list[str], count: int) -> None:
    if len(args) != count:
        raise SubstitutionError(f"{raw} takes {count} argument(s), got {len(args)}")
