"""String operations the evaluator understands: ``%`` and ``str.format``, ``join``."""

from __future__ import annotations

import ast

from ...evaluate import operations as ops
from ...evaluate import partial
from ...model.values import Unknown, Value
from .objects import Seq, text_of


def number(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def percent(template: Value, items: tuple[object, ...]) -> object:
    """``template % items``: exact when everything is known (the one evaluator), else the
    known parts kept (``evaluate.partial``)."""
    if not template.is_known:
        return Value.unknown("format")
    try:
        known = tuple(plain(item) for item in items)
    except LookupError:
        pass
    else:
        values = known if len(known) != 1 else known[0]
        try:
            return from_plain(ops.binary(ast.Mod, template.text, values))
        except ops.Refused as err:
            return Unknown(f"%: {err.reason}")
    try:
        return Value.of(*partial.percent_parts(template.text, items, text_of, _unknown))
    except ops.Refused as err:
        return Unknown(f"%: {err.reason}")


def _unknown(reason: str) -> Value:
    return Value.unknown(reason)


def plain(value: object) -> object:
    """A value of the reader as the Python value the one evaluator computes with; raises
    ``LookupError`` when some part is not known."""
    if isinstance(value, Value):
        if value.literal is None:
            raise LookupError("not known")
        return value.literal
    if isinstance(value, Seq):
        return [plain(item) for item in value.items]
    if isinstance(value, bool | int | float | None):
        return value
    raise LookupError("not known")


def from_plain(value: object) -> object:
    if isinstance(value, str):
        return Value.of(value)
    if isinstance(value, list | tuple):
        return Seq(tuple(from_plain(item) for item in value))
    if isinstance(value, bool | int | float | None):
        return value
    return Unknown(type(value).__name__)


def string_method(base: Value, method: str, args: list[object],
                  kwargs: dict[str, object] | None = None, spread: bool = False) -> object:
    """``base.method(*args, **kwargs)``: by the one evaluator when everything is known;
    ``format`` and ``join`` keep their known parts when some are not. ``spread``: the
    call also unpacks a mapping (``**values``), whose keys are not known here: a field
    that no keyword written names is then not known (not an error)."""
    kwargs = kwargs or {}
    try:
        known = [plain(a) for a in args]
        known_kwargs = {key: plain(value) for key, value in kwargs.items()}
        text = plain(base)
        if spread:
            raise LookupError("**")
    except LookupError:
        pass
    else:
        try:
            return from_plain(ops.call_method(text, method, known, known_kwargs))
        except ops.Refused as err:
            return Unknown(f"str.{method}: {err.reason}")
    try:
        if method == "format" and base.is_known:
            return Value.of(*partial.format_parts(base.text, args, kwargs, text_of, _unknown))
        if method == "join" and len(args) == 1 and isinstance(args[0], Seq) and not kwargs:
            return Value.of(*partial.join_parts(base, args[0].items, text_of))
    except ops.Refused as err:
        return Unknown(f"str.{method}: {err.reason}")
    return Unknown(f"str.{method}")
