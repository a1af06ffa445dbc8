"""String operations the evaluator understands: ``%`` and ``str.format``, ``join``."""

from __future__ import annotations

import ast
from typing import Any

from ...model.values import Value
from .objects import Opaque, Seq, text_of


def number(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def arith(op: ast.operator, left: Any, right: Any) -> object:
    if isinstance(op, ast.Mult):
        return left * right if abs(left) < 1e6 and abs(right) < 1e6 else Opaque("big")
    if isinstance(op, ast.Sub):
        return left - right
    return left / right


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


def string_method(base: Value, method: str, args: list[object]) -> object:
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
    return Opaque(f"str.{method}")
