"""Cost checks every evaluator of Python-like code we read makes before it makes a value.

The evaluators (ROS 1 ``$(eval)`` and ROS 2 ``PythonExpression`` in ``launch/expression.py``,
Python launch files in ``launch/ros2/python_*.py``) compute with Python's own operations;
a few of those make a value far larger than their inputs (``'{0:{1}}'.format('a', 10**10)``,
``'%*d' % (10**9, 1)``, ``','.join(big * n)``, ``x * x`` on huge integers, ``range(10**9)``,
``sum(lists, [])``, ``str()`` of a structure that shares itself). Each function here estimates
the size of the result from the inputs alone and raises ``OverBudget`` when it passes the
limit; ``format`` fields that reach an attribute (``'{0.__class__}'``) are refused too. Each
evaluator turns ``OverBudget`` into its own "limit" / "unsupported" unknown value.
"""

from __future__ import annotations

import _string  # the parser str.format itself uses
import re
import string
from collections.abc import Mapping, Sequence
from typing import Any

MAX_LENGTH = 1_000_000  # characters or items of any value made
MAX_INT_BITS = 4_096  # bits of any integer made


class OverBudget(Exception):
    """The value would pass a bound (``kind`` "limit") or the operation is refused
    (``kind`` "unsupported")."""

    def __init__(self, reason: str, kind: str = "limit") -> None:
        super().__init__(reason)
        self.reason, self.kind = reason, kind


def check_size(kind: str, estimated: int, limit: int = MAX_LENGTH) -> None:
    """Refuse to make a ``kind`` (a string, a list, ...) of ``estimated`` length."""
    if estimated > limit:
        raise OverBudget(f"{kind} longer than {limit}")


def check_bits(estimated: int, limit: int = MAX_INT_BITS) -> None:
    if estimated > limit:
        raise OverBudget(f"integer larger than {limit} bits")


def text_length(value: Any, limit: int = MAX_LENGTH) -> int:
    """An upper estimate of ``len(str(value))``, shared parts counted every time they are
    printed; stops counting once past ``limit`` (the work is bounded by it)."""
    total = 0
    stack = [value]
    while stack:
        item = stack.pop()
        if isinstance(item, (str, bytes)):
            total += len(item) + 3
        elif isinstance(item, bool) or item is None:
            total += 5
        elif isinstance(item, int):
            total += item.bit_length() // 3 + 2
        elif isinstance(item, Mapping):
            total += 2 + 2 * len(item)
            stack.extend(item.keys())
            stack.extend(item.values())
        elif isinstance(item, (list, tuple, set, frozenset)):
            total += 2 + 2 * len(item)
            stack.extend(item)
        else:
            total += 32
        if total > limit:
            return total
    return total


def item_count(value: Any, limit: int = MAX_LENGTH) -> int:
    """The items of a nested structure, shared parts counted each time they are reached
    (what walking it costs); stops counting once past ``limit``."""
    total = 0
    stack = [value]
    while stack and total <= limit:
        item = stack.pop()
        total += 1
        if isinstance(item, Mapping):
            stack.extend(item.keys())
            stack.extend(item.values())
        elif isinstance(item, (list, tuple, set, frozenset)):
            stack.extend(item)
    return total


def check_text(value: Any, limit: int = MAX_LENGTH) -> None:
    """Before ``str(value)``."""
    check_size("a string", text_length(value, limit), limit)


# -- str.format and % ------------------------------------------------------------------------

_NUMBERS = re.compile(r"\d+")


def _field_value(name: str, args: Sequence[Any], kwargs: Mapping[str, Any],
                 auto: list[int]) -> Any:
    first, rest = _string.formatter_field_name_split(name)
    for is_attribute, key in rest:
        if is_attribute:
            raise OverBudget(f"format field '{name}' reaches an attribute", "unsupported")
        if isinstance(key, str) and key.startswith("_"):
            raise OverBudget(f"format field '{name}' is refused", "unsupported")
    if first == "":
        first = auto[0]
        auto[0] += 1
    if isinstance(first, int):
        return args[first] if 0 <= first < len(args) else None
    return kwargs.get(first)


def format_length(template: str, args: Sequence[Any], kwargs: Mapping[str, Any],
                  limit: int = MAX_LENGTH) -> int:
    """An upper estimate of ``len(template.format(*args, **kwargs))``; refuses attribute
    fields and widths or precisions (given or taken from an argument) above ``limit``."""
    auto = [0]
    total = 0
    try:
        fields = list(string.Formatter().parse(template))
    except ValueError:
        return len(template)  # format() raises the same error: nothing is made
    for literal, name, spec, _conversion in fields:
        total += len(literal)
        if name is None:
            continue
        value = _field_value(name, args, kwargs, auto)
        resolved = []
        try:
            inner = list(string.Formatter().parse(spec or ""))
        except ValueError:
            inner = []
        for text, inner_name, _s, _c in inner:
            resolved.append(text)
            if inner_name is not None:
                resolved.append(str(_field_value(inner_name, args, kwargs, auto))[:40])
        for number in _NUMBERS.findall("".join(resolved)):
            if len(number) > 7 or int(number) > limit:
                raise OverBudget(f"format width or precision above {limit}")
            total += int(number)
        total += text_length(value, limit)
        check_size("a string", total, limit)
    return total


PERCENT = re.compile(r"%(?:\([^)]*\))?[-#0 +]*(\*|\d+)?(?:\.(\*|\d+))?[hlL]?(.)", re.S)


def percent_length(template: str, values: Any, limit: int = MAX_LENGTH) -> int:
    """An upper estimate of ``len(template % values)``; ``*`` widths read from the values."""
    items = list(values) if isinstance(values, tuple) else [values]
    total = len(template)
    index = 0
    for match in PERCENT.finditer(template):
        if match.group(3) == "%":
            continue
        for part in (match.group(1), match.group(2)):
            if part == "*":
                width = items[index] if index < len(items) else 0
                index += 1
            else:
                width = int(part) if part and len(part) < 9 else (limit + 1 if part else 0)
            if isinstance(width, int) and not isinstance(width, bool) and abs(width) > limit:
                raise OverBudget(f"%-format width or precision above {limit}")
            total += abs(width) if isinstance(width, int) else 0
        if isinstance(values, Mapping):
            total += text_length(values, limit)
        elif index < len(items):
            total += text_length(items[index], limit)
            index += 1
        check_size("a string", total, limit)
    return total


# -- other str methods, integers, builtins ---------------------------------------------------

def str_method_length(owner: str, name: str, args: Sequence[Any],
                      kwargs: Mapping[str, Any] | None = None,
                      limit: int = MAX_LENGTH) -> int:
    """Before ``owner.name(*args)``: the result's estimated length (checked)."""
    estimate = len(owner)
    if name == "format":
        estimate = format_length(owner, args, kwargs or {}, limit)
    elif name in ("zfill", "center", "ljust", "rjust") and args and isinstance(args[0], int):
        estimate = max(len(owner), args[0])
    elif name == "expandtabs":
        size = args[0] if args and isinstance(args[0], int) else 8
        estimate = len(owner) + owner.count("\t") * max(size, 0)
    elif name == "replace" and len(args) >= 2 and isinstance(args[0], str) \
            and isinstance(args[1], str):
        hits = owner.count(args[0]) if args[0] else len(owner) + 1
        estimate = len(owner) + hits * max(len(args[1]) - len(args[0]), 0)
    elif name == "join" and args and isinstance(args[0], (list, tuple, str, set, dict)):
        items = args[0]
        estimate = len(owner) * max(len(items) - 1, 0)
        for item in items:
            estimate += len(item) if isinstance(item, str) else 1
            if estimate > limit:
                break
    check_size("a string", estimate, limit)
    return estimate


def int_result_bits(op: str, left: Any, right: Any) -> int:
    """Estimated bits of ``left op right`` for integers (0 when not integers)."""
    if not (isinstance(left, int) and isinstance(right, int)):
        return 0
    if op == "*":
        return left.bit_length() + right.bit_length()
    if op == "**":
        if right <= 0 or abs(left) <= 1:
            return 1
        return left.bit_length() * min(right, MAX_INT_BITS * 64)
    if op == "<<":
        return left.bit_length() + max(min(right, MAX_INT_BITS * 64), 0)
    return max(left.bit_length(), right.bit_length()) + 1


def check_int_op(op: str, left: Any, right: Any, bits: int = MAX_INT_BITS) -> None:
    check_bits(int_result_bits(op, left, right), bits)


def range_length(args: Sequence[Any]) -> int:
    try:
        return len(range(*args))
    except (TypeError, ValueError, OverflowError):
        return 0


def sum_length(items: Any, start: Any = 0, limit: int = MAX_LENGTH) -> None:
    """Before ``sum(items, start)`` with a list, tuple or string start: the concatenation."""
    if not isinstance(start, (list, tuple, str)):
        return
    total = len(start)
    for item in items if isinstance(items, (list, tuple)) else ():
        total += len(item) if isinstance(item, (list, tuple, str)) else 1
        check_size("a list", total, limit)
