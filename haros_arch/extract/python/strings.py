"""String operations the evaluator understands: ``%`` and ``str.format``, ``join``."""

from __future__ import annotations

from ...evaluate import operations as ops
from ...model.values import Unknown, Value
from .objects import Seq, text_of


def number(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def percent(template: Value, items: tuple[object, ...]) -> Value:
    if not template.is_known:
        return Value.unknown("format")
    text = template.text
    parts: list[Value | str] = []
    i = j = 0
    while i < len(text):
        if text[i] == "%" and i + 1 < len(text):
            if text[i + 1] == "%":
                parts.append("%")
            elif j < len(items):
                parts.append(text_of(items[j]))
                j += 1
            else:
                parts.append(Value.unknown("format"))
            i += 2
            while parts and i <= len(text) and text[i - 1] not in "sdifrx%" and i < len(text):
                i += 1
            continue
        parts.append(text[i])
        i += 1
    return Value.of(*parts)


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


def string_method(base: Value, method: str, args: list[object]) -> object:
    """``base.method(*args)``: by the one evaluator when everything is known; ``format``
    and ``join`` keep their known parts when some are not."""
    try:
        known = [plain(a) for a in args]
        text = plain(base)
    except LookupError:
        pass
    else:
        try:
            return from_plain(ops.call_method(text, method, known))
        except ops.Refused as err:
            return Unknown(f"str.{method}: {err.reason}")
    if method == "format" and base.is_known:
        text = base.text
        out: list[Value | str] = []
        auto = 0
        i = 0
        while i < len(text):
            if text.startswith("{{", i) or text.startswith("}}", i):
                out.append(text[i])
                i += 2
                continue
            if text[i] == "{":
                end = text.find("}", i)
                if end < 0:
                    break
                field_name = text[i + 1:end].split(":")[0].split("!")[0]
                index = -1
                if not field_name:
                    index, auto = auto, auto + 1
                elif field_name.isdigit():
                    index = int(field_name)
                out.append(text_of(args[index]) if 0 <= index < len(args)
                           else Value.unknown("format"))
                i = end + 1
                continue
            out.append(text[i])
            i += 1
        return Value.of(*out)
    if method == "join" and len(args) == 1 and isinstance(args[0], Seq):
        joined: list[Value | str] = []
        for k, item in enumerate(args[0].items):
            if k:
                joined.append(base)
            joined.append(text_of(item))
        return Value.of(*joined)
    return Unknown(f"str.{method}")
