"""Strings built from values a reader knows only in part: ``str.format``, ``%`` and ``join``.

The readers that keep partial values (the Python launch-file reader's substitutions, the
Python node reader's names with ``?`` parts) build a string from a known template and
arguments some of which are not known. These functions cut the result into its parts:
the template's literal text, and each argument where it lands, given to the caller's
``text(value)``; a field that cannot be filled statically (a format spec other than
``s`` or a conversion applied to a value, an index or attribute in a field name, a
missing argument) is the caller's ``unknown(reason)``. The caller joins the parts into
its own partial value. The result's size is estimated before any part is made
(``budget``); a field never reaches an attribute. When every value is known the caller
uses ``operations`` instead, which makes the exact string.
"""

from __future__ import annotations

import _string  # the parser str.format itself uses
import string
from collections.abc import Callable, Mapping, Sequence
from typing import Any, TypeVar

from . import budget

T = TypeVar("T")


def _size(value: Any) -> int:
    return len(value) if isinstance(value, str) else 1


def format_parts(template: str, args: Sequence[Any], kwargs: Mapping[str, Any],
                 text: Callable[[Any], T], unknown: Callable[[str], T],
                 limit: int = budget.MAX_LENGTH) -> list[str | T]:
    """``template.format(*args, **kwargs)`` as parts (``budget.OverBudget`` past ``limit``)."""
    try:
        fields = list(string.Formatter().parse(template))
    except ValueError:
        return [unknown("format")]  # str.format raises the same error
    parts: list[str | T] = []
    auto = 0
    total = 0
    for literal, name, spec, conversion in fields:
        if literal:
            parts.append(literal)
            total += len(literal)
        if name is None:
            continue
        try:
            first, rest = _string.formatter_field_name_split(name)
        except ValueError:
            parts.append(unknown("format"))
            continue
        if first == "":
            first, auto = auto, auto + 1
        if isinstance(first, int):
            found = args[first] if 0 <= first < len(args) else None
            present = 0 <= first < len(args)
        else:
            found, present = kwargs.get(first), first in kwargs
        # ``{:s}`` formats a string as it is (``{}``); any other spec pads or converts
        if not present or list(rest) or spec not in ("", "s") or conversion not in (None, "s"):
            parts.append(unknown("format"))
            continue
        total += _size(found)
        budget.check_size("a string", total, limit)
        parts.append(text(found))
    return parts


def percent_parts(template: str, values: Any, text: Callable[[Any], T],
                  unknown: Callable[[str], T],
                  limit: int = budget.MAX_LENGTH) -> list[str | T]:
    """``template % values`` as parts; a conversion with a width, a precision, a flag or a
    mapping key is unknown (its padding is not known without the value)."""
    items = list(values) if isinstance(values, tuple) else [values]
    parts: list[str | T] = []
    index = 0
    start = 0
    total = 0
    for match in budget.PERCENT.finditer(template):
        if match.start() > start:
            parts.append(template[start:match.start()])
            total += match.start() - start
        start = match.end()
        whole = match.group(0)
        if match.group(3) == "%" and whole == "%%":
            parts.append("%")
            total += 1
            continue
        plain = len(whole) == 2 and match.group(3) in "sdir"
        for part in (match.group(1), match.group(2)):
            if part == "*":
                index += 1  # the width comes from the values: not known as a width here
        if index >= len(items) or not plain:
            parts.append(unknown("format"))
            index += 1
            continue
        total += _size(items[index])
        budget.check_size("a string", total, limit)
        parts.append(text(items[index]))
        index += 1
    if start < len(template):
        parts.append(template[start:])
    return parts


def join_parts(separator: T, items: Sequence[Any], text: Callable[[Any], T],
               limit: int = budget.MAX_LENGTH) -> list[T]:
    """``separator.join(items)`` as parts: the separator between each two items."""
    parts: list[T] = []
    total = 0
    for position, item in enumerate(items):
        if position:
            parts.append(separator)
            total += _size(separator)
        total += _size(item)
        budget.check_size("a string", total, limit)
        parts.append(text(item))
    return parts
