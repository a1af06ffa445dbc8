"""roslaunch substitution args (``$(arg x)``, ``$(find pkg)``, ...) over partial values.

As roslaunch does: a whole attribute ``$(eval EXPR)`` is an expression (evaluated here
by our own safe interpreter, never by Python's ``eval``); otherwise ``$(...)`` commands
are collected by the same state machine, ``env``/``optenv``/``dirname``/``anon``/``arg``
are replaced first and ``find`` afterwards (so an argument whose value holds
``$(find pkg)`` is expanded too). A substitution whose value cannot be known (an
argument nobody set, an environment variable that is not in the configuration) gives an
``Unknown`` part; the text around it is kept.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from ...model.values import Part, Unknown, Value
from .. import expression
from ..model import found_nowhere, package_not_found
from .params import convert_value

VALID = ("find", "env", "optenv", "dirname", "anon", "arg")
# roslaunch passes ``{}`` as globals, so Python's builtins are all reachable from
# $(eval); ours are the safe subset of them, plus roslaunch's names and math.*
EVAL_BUILTINS: Mapping[str, Any] = {
    **expression.BUILTINS, **expression.MATH,
    "true": True, "false": False, "True": True, "False": False,
}

MAX_VALUE = 100_000  # characters of a substituted value (roslaunch has no bound)


class SubstitutionError(Exception):
    """A substitution that roslaunch would reject (wrong arity, unknown command)."""


class ArgUndefined(SubstitutionError):
    """``$(arg x)`` where ``x`` has no value in this scope (roslaunch's ArgException)."""

    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.name = name


@dataclass(frozen=True)
class Reason:
    """Why a part of a substituted value is not known: the detail said
    (``LAUNCH_UNKNOWN_VALUE``), and the package a ``$(find)`` did not find when that is
    why (a reader that does not need the package's folder drops it by the package)."""

    detail: str
    package: str | None = None


@dataclass
class Context:
    """What substitutions may read: arguments, environment, packages, the file."""

    args: Mapping[str, Value]
    environment: Mapping[str, str]
    find: Callable[[str], str | None]
    filename: str
    anon: dict[str, Unknown] = field(default_factory=dict)
    declared: Callable[[str], bool] = lambda name: False  # declared but without value
    unset: list[str] = field(default_factory=list)  # declared args without value that were used
    unknown: list[Reason] = field(default_factory=list)  # other reasons for unknown parts
    # why ``find`` found nothing, the rest of "package NAME ..." (Workspace.absence)
    absence: Callable[[str], str] = lambda name: "is not found"
    # the packages here whose names a package ``find`` did not find most likely misspells
    # (Workspace.misspelt), and the packages so named in a $(find)
    misspelt: Callable[[str], list[str]] = lambda name: []
    misspelt_packages: list[str] = field(default_factory=list)
    # the $(optenv NAME default) of a variable not set here that took a default: (NAME,
    # default), so that a file missing at a path holding it can say why
    defaults_taken: list[tuple[str, str]] = field(default_factory=list)


def collect(text: str) -> list[str]:
    """The ``$(...)`` bodies in ``text``, with roslaunch's state machine."""
    return _scan(text)[0]


def unclosed(text: str) -> str | None:
    """The text from a ``$(`` that is never closed to the end of ``text``, or None.

    roslaunch's state machine collects a body only at its ``)``: one still open at the
    end is no substitution, and the attribute keeps ``$(arg x`` as plain text (no error;
    a whole ``$(eval ...`` without its ``)`` is no expression either)."""
    if _whole_eval(text):  # one expression, never scanned (its parentheses nest)
        return None
    start = _scan(text)[1]
    return None if start is None else text[start:]


def _scan(text: str) -> tuple[list[str], int | None]:
    """The closed bodies, and where a ``$(`` still open at the end starts (or None)."""
    out, buff, state, start = [], "", "out", None
    for index, char in enumerate(text):
        if char == "$":
            if state in ("in", "lp"):
                raise SubstitutionError(f"dollar signs '$' cannot be inside of "
                                        f"substitution args: {text}")
            state = "dollar"
        elif char == "(":
            if state == "dollar":
                state, start = "lp", index - 1
            elif state != "out":
                raise SubstitutionError(f"invalid left parenthesis '(' in substitution "
                                        f"args: {text}")
        elif char == ")":
            if state == "in":
                out.append(buff)
                buff = ""
            state = "out"
        elif state == "dollar":
            state = "out"
        elif state == "lp":
            state = "in"
        if state == "in":
            buff += char
    return out, (start if state in ("lp", "in") else None)


def _whole_eval(text: str) -> bool:
    """roslaunch's test for an attribute that is one ``$(eval EXPR)``."""
    return text.startswith("$(eval ") and text.endswith(")")


def substitute(text: str, ctx: Context) -> Value:
    """Resolve every substitution in ``text`` as roslaunch does."""
    if not text or "$" not in text:
        return Value.of(text)
    if _whole_eval(text):
        return evaluate(text[7:-1], ctx)
    bodies = collect(text)
    for body in bodies:
        words = [w for w in body.split(" ") if w]
        if not words or words[0] not in VALID:
            raise SubstitutionError(f"unknown substitution command '{body}'; valid "
                                    f"commands are {', '.join(VALID)}")
    value = Value.of(text)
    for body in bodies:
        words = [w for w in body.split(" ") if w]
        if words[0] != "find":
            value = _replace(value, f"$({body})", _one(words[0], words[1:], body, ctx))
    for part in value.parts:  # second pass: $(find) over the text produced so far
        if isinstance(part, str):
            for body in collect(part):
                words = [w for w in body.split(" ") if w]
                if words and words[0] == "find":
                    value = _replace(value, f"$({body})", _one("find", words[1:], body, ctx))
    return value


def _size(value: Value) -> int:
    return sum(len(p) if isinstance(p, str) else 1 for p in value.parts)


def _replace(value: Value, old: str, new: Value) -> Value:
    # the size it would have, before it is made: $(arg) of $(arg) ... ("billion laughs")
    grown = sum(len(p) + p.count(old) * (_size(new) - len(old)) if isinstance(p, str) else 1
                for p in value.parts)
    if grown > MAX_VALUE:
        raise SubstitutionError(f"the value would be longer than {MAX_VALUE} characters")
    parts: list[str | Unknown | Value] = []
    for part in value.parts:
        if isinstance(part, str) and old in part:
            pieces = part.split(old)
            for index, piece in enumerate(pieces):
                if index:
                    parts.append(new)
                parts.append(piece)
        else:
            parts.append(part)
    return Value.of(*parts)


def _one(command: str, args: list[str], raw: str, ctx: Context) -> Value:
    if command == "arg":
        _arity(raw, args, 1)
        return _arg(args[0], ctx)
    if command == "env":
        _arity(raw, args, 1)
        if args[0] in ctx.environment:
            return Value.of(ctx.environment[args[0]])
        ctx.unknown.append(Reason(f"environment variable {args[0]} is not set"))
        return Value.unknown(f"env {args[0]}")
    if command == "optenv":
        if not args:
            raise SubstitutionError(f"$({raw}) needs a variable name")
        if args[0] not in ctx.environment and len(args) > 1:
            ctx.defaults_taken.append((args[0], " ".join(args[1:])))
        return Value.of(ctx.environment.get(args[0], " ".join(args[1:])))
    if command == "find":
        _arity(raw, args, 1)
        path = ctx.find(args[0])
        if path is None:
            if ctx.misspelt(args[0]):  # most likely a typo: the launch fails here
                ctx.misspelt_packages.append(args[0])
            else:  # installed on the robot, perhaps
                ctx.unknown.append(Reason(f"package {args[0]} {ctx.absence(args[0])}",
                                          args[0]))
            return package_not_found(args[0])
        return Value.of(path)
    if command == "anon":
        _arity(raw, args, 1)
        return _anon(args[0], ctx)
    if command == "dirname":
        return Value.of(os.path.dirname(os.path.abspath(ctx.filename)))
    raise SubstitutionError(f"unknown substitution command '{raw}'")


def _arg(name: str, ctx: Context) -> Value:
    if name in ctx.args:
        return ctx.args[name]
    if ctx.declared(name):
        ctx.unset.append(name)
        return Value.unknown(f"arg {name}")
    raise ArgUndefined(name)


def _anon(name: str, ctx: Context) -> Value:
    # roslaunch appends host, pid and a random number: unknown, but the same unknown
    # for every use of one name within the scope
    return Value.of(name + "_", ctx.anon.setdefault(name, Unknown(f"anon {name}")))


def _arity(raw: str, args: list[str], count: int) -> None:
    if len(args) != count:
        raise SubstitutionError(f"$({raw}) takes {count} argument(s), got {len(args)}")


def evaluate(text: str, ctx: Context) -> Value:
    """``$(eval text)``: our safe evaluator with roslaunch's names; str() of the result.
    A result not known only because a ``find()`` in it names a package that is neither
    in the workspace nor installed here is that package's folder not found, as a
    ``$(find pkg)`` outside an eval is (said once, where the find is): hebi's
    ``$(eval find('hebi_' + moveit_arm_type + '_moveit_config') + '/launch/...')``
    include is then a file of a package not here, not one the tool cannot read."""
    fed: list[Part] = []  # the unknown values handed to the expression

    def as_python(value: Value) -> object:
        if value.literal is None:
            fed.extend(part for part in value.parts if isinstance(part, Unknown))
            return expression.Unknown(f"{value.origins}", "unknown")
        return convert_value(value.literal, "auto")

    def arg(name: object) -> object:
        return as_python(_arg(str(name), ctx))

    def env(name: object) -> object:
        # roslaunch's ``_eval_env`` is the variable's text, as ``optenv``'s: only
        # ``arg()`` converts (OpenMower's ``env('HARDWARE_PLATFORM') == '1'`` holds for
        # ``1``; an ``int`` here made it false and left its nodes out)
        value = _one("env", [str(name)], f"env {name}", ctx)
        if value.literal is None:
            fed.extend(part for part in value.parts if isinstance(part, Unknown))
            return expression.Unknown(f"{value.origins}", "unknown")
        return value.literal

    def optenv(name: object, default: object = "") -> object:
        return ctx.environment.get(str(name), default)

    def find(name: object) -> object:
        return as_python(_one("find", [str(name)], f"find {name}", ctx))

    def anon(name: object) -> object:
        return as_python(_anon(str(name), ctx))

    def bare(name: str) -> object:
        if name in ctx.args:
            return as_python(ctx.args[name])
        if ctx.declared(name):
            ctx.unset.append(name)
            fed.append(Unknown(f"arg {name}"))
            return expression.Unknown(f"arg {name} has no value", "unknown")
        raise KeyError(name)

    def dirname() -> object:
        return os.path.dirname(os.path.abspath(ctx.filename))

    functions = {**EVAL_BUILTINS, "arg": arg, "env": env, "optenv": optenv, "find": find,
                 "anon": anon, "dirname": dirname}
    if "__" in text:  # roslaunch refuses these outright
        raise SubstitutionError("$(eval ...) may not contain double underscore expressions")
    result = expression.evaluate(text, bare, functions)
    if isinstance(result, expression.Unknown):
        if result.kind == "unknown":
            missing = Value.of(*dict.fromkeys(fed))
            if found_nowhere(missing):
                return missing
            ctx.unknown.append(Reason(f"$(eval {text}) depends on unknown values"))
            return Value.unknown(f"eval {text}")
        if result.kind in ("undefined", "error", "syntax"):
            raise SubstitutionError(f"$(eval {text}): {result.reason}")
        ctx.unknown.append(Reason(f"$(eval {text}) is not evaluated: {result.reason}"))
        return Value.unknown(f"eval {text}")
    return Value.of(str(result))
