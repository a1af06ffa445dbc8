"""Operations on known Python values, each charged by the size of what it would make.

Every evaluator of Python-like code we read (``$(eval)``, ``PythonExpression``, Python
launch files, setup.py, the Python node reader's constants) computes with these and only
these: binary and unary operators, comparisons, subscripts, the methods of ``str``,
``list``, ``dict`` and ``set`` on an allow-list, format specs, and the safe builtin tables
``BUILTINS`` / ``MATH``. Each checks the size of its result before making it (``budget``)
and raises ``Refused`` instead of a Python error: ``kind`` "limit" (a bound), "unsupported"
(outside the subset, never run) or "error" (Python itself would raise).
"""

from __future__ import annotations

import ast
import math
import operator
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from . import budget

Refused = budget.OverBudget


@dataclass(frozen=True)
class Limits:
    text: int = 10_000  # characters of source (an expression)
    nodes: int = 2_000  # AST nodes
    depth: int = 60  # AST nesting
    steps: int = 200_000  # evaluation steps, comprehension iterations included
    length: int = budget.MAX_LENGTH  # characters / items of any string or container built
    int_bits: int = budget.MAX_INT_BITS  # bits of any integer built


DEFAULT = Limits()
SIZED = (str, bytes, list, tuple, dict, set, frozenset)


def error_text(err: BaseException) -> str:
    """An error of Python's as a short reason; a ``KeyError`` never prints its key (the
    repr of a key shared a million times over is a string of that size)."""
    if isinstance(err, KeyError):
        return "KeyError: the key is not there"
    return f"{type(err).__name__}: {str(err)[:200]}"


def guarded(action: Callable[[], Any]) -> Any:
    """``action()``, with Python's own errors turned into ``Refused(..., "error")``."""
    try:
        return action()
    except Refused:
        raise
    except (ArithmeticError, TypeError, ValueError, LookupError, AttributeError) as err:
        raise Refused(error_text(err), "error") from None


def checked(value: Any, limits: Limits = DEFAULT) -> Any:
    """``value`` if it is within the size bounds (a value made by code we do not control)."""
    if isinstance(value, SIZED) and len(value) > limits.length:
        raise Refused(f"result longer than {limits.length}")
    if isinstance(value, int) and not isinstance(value, bool) \
            and value.bit_length() > limits.int_bits:
        raise Refused(f"integer larger than {limits.int_bits} bits")
    return value


# -- operators -------------------------------------------------------------------------------
BINARY: dict[type, Callable[[Any, Any], Any]] = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
    ast.Div: operator.truediv, ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod,
    ast.Pow: operator.pow, ast.BitAnd: operator.and_, ast.BitOr: operator.or_,
    ast.BitXor: operator.xor, ast.LShift: operator.lshift, ast.RShift: operator.rshift,
}
UNARY: dict[type, Callable[[Any], Any]] = {
    ast.UAdd: operator.pos, ast.USub: operator.neg, ast.Not: operator.not_,
    ast.Invert: operator.invert,
}
COMPARE: dict[type, Callable[[Any, Any], Any]] = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge, ast.In: lambda a, b: a in b,
    ast.NotIn: lambda a, b: a not in b, ast.Is: operator.is_, ast.IsNot: operator.is_not,
}
_INT_OPS: dict[type, str] = {ast.Mult: "*", ast.Pow: "**", ast.LShift: "<<"}


def _length(value: Any) -> int:
    return len(value) if isinstance(value, SIZED) else 1


def binary(op: type, left: Any, right: Any, limits: Limits = DEFAULT) -> Any:
    """``left op right`` (``op`` an ``ast.operator`` class) on known values."""
    function = BINARY.get(op)
    if function is None:
        raise Refused(f"operator {op.__name__} is not supported", "unsupported")
    if op is ast.Add and isinstance(left, SIZED) and isinstance(right, SIZED):
        budget.check_size("a value", len(left) + len(right), limits.length)
    elif op is ast.Mult:
        for seq, count in ((left, right), (right, left)):
            if isinstance(seq, (str, list, tuple, bytes)) and isinstance(count, int):
                budget.check_size("a value", len(seq) * max(count, 0), limits.length)
    elif op is ast.Pow and isinstance(left, (int, float)) and isinstance(right, (int, float)) \
            and not (isinstance(left, int) and isinstance(right, int)) and abs(right) > 10_000:
        raise Refused("exponent too large")
    elif op is ast.Mod and isinstance(left, str):
        budget.percent_length(left, right, limits.length)
    symbol = _INT_OPS.get(op)
    if symbol is not None and not isinstance(left, bool) and not isinstance(right, bool):
        budget.check_int_op(symbol, left, right, limits.int_bits)
    return checked(guarded(lambda: function(left, right)), limits)


def unary(op: type, value: Any) -> Any:
    function = UNARY.get(op)
    if function is None:
        raise Refused(f"operator {op.__name__} is not supported", "unsupported")
    return guarded(lambda: function(value))


def compare_cost(left: Any, right: Any, limits: Limits = DEFAULT) -> int:
    """The steps a comparison takes: ``==`` on two lists walks both (shared parts counted
    each time they are reached)."""
    if isinstance(left, SIZED) and isinstance(right, SIZED):
        bound = limits.steps
        return min(budget.text_length(left, bound), budget.text_length(right, bound))
    return 1


def compare(op: type, left: Any, right: Any) -> Any:
    function = COMPARE.get(op)
    if function is None:
        raise Refused(f"comparison {op.__name__} is not supported", "unsupported")
    return guarded(lambda: function(left, right))


def subscript(value: Any, index: Any) -> Any:
    if not isinstance(value, (str, list, tuple, dict, bytes)):
        raise Refused(f"{type(value).__name__} is not subscriptable", "error")
    return guarded(lambda: value[index])


_CONVERSIONS: dict[int, Callable[[object], str]] = {115: str, 114: repr, 97: ascii}


def format_value(value: Any, spec: Any, conversion: int = -1,
                 limits: Limits = DEFAULT) -> str:
    """An f-string field ``{value!conversion:spec}``, its width and precision bounded."""
    spec = str(spec)
    field = "{0:" + spec.replace("{", "{{").replace("}", "}}") + "}"
    budget.format_length(field, [value], {}, limits.length)
    convert = _CONVERSIONS.get(conversion)
    if convert is not None:
        budget.check_text(value, limits.length)
        value = convert(value)
    return guarded(lambda: format(value, spec))


# -- methods ---------------------------------------------------------------------------------
STR_METHODS = frozenset((
    "lower", "upper", "strip", "lstrip", "rstrip", "startswith", "endswith", "replace",
    "split", "rsplit", "join", "format", "find", "rfind", "index", "rindex", "count",
    "capitalize", "title", "swapcase", "isdigit", "isalpha", "isalnum", "isspace",
    "islower", "isupper", "isnumeric", "isdecimal", "splitlines", "partition",
    "rpartition", "zfill", "center", "ljust", "rjust", "casefold", "removeprefix",
    "removesuffix", "expandtabs",
))
LIST_METHODS = frozenset(("index", "count"))
LIST_MUTATORS = frozenset(("append", "extend", "insert"))  # where the caller allows them
DICT_METHODS = frozenset(("get", "keys", "values", "items", "copy"))
SET_METHODS = frozenset(("intersection", "union", "difference", "symmetric_difference",
                         "issubset", "issuperset", "isdisjoint"))  # none changes the set


def allowed_methods(owner: Any, mutate: bool = False) -> frozenset[str]:
    if isinstance(owner, str):
        return STR_METHODS
    if isinstance(owner, list) and mutate:
        return LIST_METHODS | LIST_MUTATORS
    if isinstance(owner, (list, tuple)):
        return LIST_METHODS
    if isinstance(owner, dict):
        return DICT_METHODS
    if isinstance(owner, (set, frozenset)):
        return SET_METHODS
    return frozenset()


def walk_cost(value: Any, limits: Limits = DEFAULT) -> int:
    """The steps a function that walks ``value`` may take: a container by its nested
    size, shared parts each time (``[[[1] * 300] * 300] * 300`` is 27 million items)."""
    if isinstance(value, (list, tuple, dict, set, frozenset)):
        return budget.item_count(value, limits.steps)
    return 1 + (len(value) // 64 if isinstance(value, (str, bytes)) else 0)


def make_cost(value: Any) -> int:
    """The steps making ``value`` took: its items, or its characters / 64."""
    if isinstance(value, (list, tuple, dict, set, frozenset)):
        return len(value)
    return len(value) // 64 if isinstance(value, (str, bytes)) else 0


def method_cost(owner: Any, args: list[Any], limits: Limits = DEFAULT) -> int:
    """The steps a method call takes: its owner and arguments walked."""
    return walk_cost(owner, limits) + sum(walk_cost(a, limits) for a in args)


def call_method(owner: Any, name: str, args: list[Any], kwargs: Mapping[str, Any] | None = None,
                limits: Limits = DEFAULT, mutate: bool = False) -> Any:
    """``owner.name(*args, **kwargs)`` for an allowed method of a known value."""
    kwargs = dict(kwargs or {})
    if name.startswith("_"):
        raise Refused(f"attribute '{name}' is forbidden", "unsupported")
    if name not in allowed_methods(owner, mutate):
        raise Refused(f"method {type(owner).__name__}.{name} is not supported", "unsupported")
    if isinstance(owner, str):
        budget.str_method_length(owner, name, args, kwargs, limits.length)
    elif name in ("extend", "append", "insert"):
        budget.check_size("a list", len(owner) + (_length(args[0]) if args else 0),
                          limits.length)
    bound = getattr(owner, name)
    result = guarded(lambda: bound(*args, **kwargs))
    if name in ("keys", "values", "items"):
        result = list(result)
    return checked(result, limits)


# -- safe function tables --------------------------------------------------------------------
def _bounded_round(value: Any, digits: Any = None) -> Any:
    if digits is not None and abs(int(digits)) > 400:
        raise ValueError("round() digits out of range")
    return round(value) if digits is None else round(value, digits)


def _str(*args: Any) -> str:
    if args:
        budget.check_text(args[0])
    return str(*args)


def _repr(*args: Any) -> str:
    if args:
        budget.check_text(args[0])
    return repr(*args)


def _int(*args: Any) -> int:
    if args and isinstance(args[0], float) and not math.isfinite(args[0]):
        raise ValueError("cannot convert an infinite or NaN float to an integer")
    return int(*args)


def _range(*args: Any) -> list[int]:
    budget.check_size("a list", budget.range_length(args))
    return list(range(*args))


def _sum(items: Any, *start: Any) -> Any:
    if start:
        budget.sum_length(items, start[0])
    return sum(items, *start)


BUILTINS: Mapping[str, Callable[..., Any]] = {
    "len": len, "int": _int, "float": float, "str": _str, "bool": bool, "abs": abs,
    "min": min, "max": max, "round": _bounded_round, "list": list, "tuple": tuple,
    "dict": dict, "sorted": sorted, "sum": _sum, "any": any, "all": all,
    "set": set, "reversed": lambda x: list(reversed(x)),
    "range": _range,
}

# bounded builtins a reader offers beyond ``BUILTINS`` (``repr``: Python launch files)
BOUNDED: Mapping[str, Callable[..., Any]] = {"repr": _repr}

MATH: Mapping[str, Any] = {
    **{name: getattr(math, name) for name in (
        "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh",
        "sqrt", "exp", "log", "log10", "log2", "floor", "ceil", "fabs", "radians",
        "degrees", "hypot", "pow", "fmod", "isnan", "isinf", "trunc", "copysign")},
    "pi": math.pi, "e": math.e, "tau": math.tau, "inf": math.inf, "nan": math.nan,
}


def call_builtin(function: Callable[..., Any], args: list[Any],
                 kwargs: Mapping[str, Any] | None = None, limits: Limits = DEFAULT) -> Any:
    """A function of a safe table, its result size-checked."""
    return checked(guarded(lambda: function(*args, **(kwargs or {}))), limits)
