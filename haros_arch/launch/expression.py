"""A safe evaluator for the Python expressions launch files embed.

roslaunch's ``$(eval ...)`` and ROS 2's ``PythonExpression`` hand a string to Python's
``eval``. We never do that: the text is parsed with :mod:`ast` and interpreted here over
a small, bounded subset — literals, arithmetic, comparisons, ``and``/``or``/``not``,
conditional expressions, indexing and slicing, list/tuple/dict/set literals, bounded
comprehensions, string and container methods from an allow-list, and functions the
caller provides. Anything else (attribute access other than allowed methods, dunders,
unknown functions, lambdas, ...) is not run: it yields an :class:`Unknown` that says why.

The API is one call::

    evaluate(text, names, functions) -> object | Unknown

``names(name)`` resolves a bare name (return a value, return an ``Unknown`` when the
value exists but cannot be known statically, or raise ``KeyError`` when it is not
defined). ``functions`` maps a name to a Python callable that receives the evaluated
positional arguments; it may return an ``Unknown``. ``BUILTINS`` and ``MATH`` are
ready-made, safe function tables. A name is looked up in ``functions`` first, then
through ``names`` (as roslaunch does).

Work is bounded: source length, AST node count and depth, evaluation steps, the length
of strings and containers built, integer size and exponents.
"""

from __future__ import annotations

import ast
import math
import operator
import re
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typing import Any, Literal

from ..evaluate import budget, syntax

__all__ = ["BUILTINS", "MATH", "Limits", "Unknown", "evaluate", "is_unknown"]

UnknownKind = Literal["unknown", "unsupported", "undefined", "error", "syntax", "limit"]


@dataclass(frozen=True)
class Unknown:
    """The result of an expression that cannot be evaluated statically.

    ``kind`` says why: ``unknown`` (it depends on a value nobody knows, e.g. an unset
    argument), ``unsupported`` (a construct outside the safe subset, never run),
    ``undefined`` (a name that is not defined), ``error`` (Python would raise, e.g.
    division by zero), ``syntax`` (not a Python expression), ``limit`` (a work bound
    was reached).
    """

    reason: str
    kind: UnknownKind = "unknown"

    def __str__(self) -> str:
        return "?"


def is_unknown(value: object) -> bool:
    return isinstance(value, Unknown)


@dataclass(frozen=True)
class Limits:
    text: int = 10_000  # characters of source
    nodes: int = 2_000  # AST nodes
    depth: int = 60  # AST nesting
    steps: int = 200_000  # evaluation steps, comprehension iterations included
    length: int = 1_000_000  # characters / items of any string or container built
    int_bits: int = 4_096  # bits of any integer built


class _Stop(Exception):
    """Evaluation cannot go on; carries the Unknown to return."""

    def __init__(self, unknown: Unknown) -> None:
        super().__init__(unknown.reason)
        self.unknown = unknown


def _clamp_len(value: object, limits: Limits) -> object:
    if isinstance(value, (str, bytes, list, tuple, dict, set, frozenset)) \
            and len(value) > limits.length:
        raise _Stop(Unknown(f"result longer than {limits.length}", "limit"))
    if isinstance(value, int) and not isinstance(value, bool) \
            and value.bit_length() > limits.int_bits:
        raise _Stop(Unknown(f"integer larger than {limits.int_bits} bits", "limit"))
    return value


_FORMAT_WIDTH = re.compile(r"\d{5,}")


def _check_format(template: str) -> None:
    """Refuse format strings with huge widths or precisions (``'{:999999999}'``)."""
    if _FORMAT_WIDTH.search(template):
        raise _Stop(Unknown("format width or precision too large", "limit"))


# -- safe function tables ----------------------------------------------------------------

def _bounded_round(value: Any, digits: Any = None) -> Any:
    if digits is not None and abs(int(digits)) > 400:
        raise ValueError("round() digits out of range")
    return round(value) if digits is None else round(value, digits)


def _str(*args: Any) -> str:
    if args:
        budget.check_text(args[0])
    return str(*args)


def _range(*args: Any) -> list[int]:
    budget.check_size("a list", budget.range_length(args))
    return list(range(*args))


def _sum(items: Any, *start: Any) -> Any:
    if start:
        budget.sum_length(items, start[0])
    return sum(items, *start)


BUILTINS: Mapping[str, Callable[..., Any]] = {
    "len": len, "int": int, "float": float, "str": _str, "bool": bool, "abs": abs,
    "min": min, "max": max, "round": _bounded_round, "list": list, "tuple": tuple,
    "dict": dict, "sorted": sorted, "sum": _sum, "any": any, "all": all,
    "set": set, "reversed": lambda x: list(reversed(x)),
    "range": _range,
}

MATH: Mapping[str, Any] = {
    **{name: getattr(math, name) for name in (
        "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh",
        "sqrt", "exp", "log", "log10", "log2", "floor", "ceil", "fabs", "radians",
        "degrees", "hypot", "pow", "fmod", "isnan", "isinf", "trunc", "copysign")},
    "pi": math.pi, "e": math.e, "tau": math.tau, "inf": math.inf, "nan": math.nan,
}

_STR_METHODS = frozenset((
    "lower", "upper", "strip", "lstrip", "rstrip", "startswith", "endswith", "replace",
    "split", "rsplit", "join", "format", "find", "rfind", "index", "rindex", "count",
    "capitalize", "title", "swapcase", "isdigit", "isalpha", "isalnum", "isspace",
    "islower", "isupper", "isnumeric", "isdecimal", "splitlines", "partition",
    "rpartition", "zfill", "center", "ljust", "rjust", "casefold", "removeprefix",
    "removesuffix",
))
_LIST_METHODS = frozenset(("index", "count"))
_DICT_METHODS = frozenset(("get", "keys", "values", "items"))
_SET_METHODS = frozenset(("intersection", "union", "difference", "symmetric_difference",
                          "issubset", "issuperset", "isdisjoint"))  # none changes the set
_PADDING = frozenset(("zfill", "center", "ljust", "rjust"))

_BINARY: dict[type, Callable[[Any, Any], Any]] = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
    ast.Div: operator.truediv, ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod,
    ast.Pow: operator.pow, ast.BitAnd: operator.and_, ast.BitOr: operator.or_,
    ast.BitXor: operator.xor, ast.LShift: operator.lshift, ast.RShift: operator.rshift,
}
_UNARY: dict[type, Callable[[Any], Any]] = {
    ast.UAdd: operator.pos, ast.USub: operator.neg, ast.Not: operator.not_,
    ast.Invert: operator.invert,
}
_COMPARE: dict[type, Callable[[Any, Any], Any]] = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge, ast.In: lambda a, b: a in b,
    ast.NotIn: lambda a, b: a not in b, ast.Is: operator.is_, ast.IsNot: operator.is_not,
}

_SIZED = (str, bytes, list, tuple, dict, set, frozenset)
_INT_OPS: dict[type, str] = {ast.Mult: "*", ast.Pow: "**", ast.LShift: "<<"}

_CONVERSIONS: dict[int, Callable[[object], str]] = {115: str, 114: repr, 97: ascii}


@dataclass(frozen=True)
class _Function:
    name: str
    call: Callable[..., Any]


class _Interpreter:
    def __init__(self, names: Callable[[str], object] | None,
                 functions: Mapping[str, Any], limits: Limits) -> None:
        self.names = names
        self.functions = functions
        self.limits = limits
        self.steps = 0
        self.scopes: list[dict[str, object]] = []

    def step(self, count: int = 1) -> None:
        self.steps += count
        if self.steps > self.limits.steps:
            raise _Stop(Unknown(f"more than {self.limits.steps} evaluation steps", "limit"))

    def eval(self, node: ast.AST) -> Any:
        self.step()
        handler = getattr(self, "eval_" + type(node).__name__, None)
        if handler is None:
            raise _Stop(Unknown(f"{type(node).__name__} is not supported", "unsupported"))
        return _clamp_len(handler(node), self.limits)

    # -- leaves ------------------------------------------------------------------------
    def eval_Expression(self, node: ast.Expression) -> Any:
        return self.eval(node.body)

    def eval_Constant(self, node: ast.Constant) -> Any:
        if node.value is Ellipsis:
            raise _Stop(Unknown("... is not supported", "unsupported"))
        return node.value

    def eval_Name(self, node: ast.Name) -> Any:
        if "__" in node.id:
            raise _Stop(Unknown(f"name '{node.id}' is forbidden", "unsupported"))
        for scope in reversed(self.scopes):
            if node.id in scope:
                return scope[node.id]
        if node.id in self.functions:
            found = self.functions[node.id]
            return _Function(node.id, found) if callable(found) else found
        if self.names is None:
            raise _Stop(Unknown(f"name '{node.id}' is not defined", "undefined"))
        try:
            return self.names(node.id)
        except KeyError:
            raise _Stop(Unknown(f"name '{node.id}' is not defined", "undefined")) from None

    # -- containers ----------------------------------------------------------------------
    def eval_List(self, node: ast.List) -> Any:
        return [self.eval(e) for e in node.elts]

    def eval_Tuple(self, node: ast.Tuple) -> Any:
        return tuple(self.eval(e) for e in node.elts)

    def eval_Set(self, node: ast.Set) -> Any:
        items = [self.eval(e) for e in node.elts]
        self.known(*items)
        return self.guard(lambda: set(items))

    def eval_Dict(self, node: ast.Dict) -> Any:
        if any(k is None for k in node.keys):
            raise _Stop(Unknown("** in a dict literal is not supported", "unsupported"))
        keys = [self.eval(k) for k in node.keys if k is not None]
        values = [self.eval(v) for v in node.values]
        self.known(*keys)
        return self.guard(lambda: dict(zip(keys, values, strict=True)))

    def eval_JoinedStr(self, node: ast.JoinedStr) -> Any:
        pieces = [str(self.eval(v)) if not isinstance(v, ast.FormattedValue)
                  else self.eval(v) for v in node.values]
        self.known(*pieces)
        return "".join(str(p) for p in pieces)

    def eval_FormattedValue(self, node: ast.FormattedValue) -> Any:
        value = self.eval(node.value)
        spec = self.eval(node.format_spec) if node.format_spec is not None else ""
        self.known(value, spec)
        _check_format(str(spec))
        field = "{0:" + str(spec).replace("{", "{{").replace("}", "}}") + "}"
        self.guard(lambda: budget.format_length(field, [value], {}, self.limits.length))
        conversion = _CONVERSIONS.get(node.conversion)
        if conversion is not None:
            value = conversion(value)
        return self.guard(lambda: format(value, str(spec)))

    # -- operators -----------------------------------------------------------------------
    def eval_BoolOp(self, node: ast.BoolOp) -> Any:
        is_and = isinstance(node.op, ast.And)
        pending: Unknown | None = None
        result: object = None
        for operand in node.values:
            result = self.eval(operand)
            if isinstance(result, Unknown):
                pending = pending or result
                continue
            if bool(result) != is_and:  # short-circuits: decided whatever came before
                return result if pending is None else pending
        return pending if pending is not None else result

    def eval_UnaryOp(self, node: ast.UnaryOp) -> Any:
        value = self.eval(node.operand)
        self.known(value)
        return self.guard(lambda: _UNARY[type(node.op)](value))

    def eval_BinOp(self, node: ast.BinOp) -> Any:
        left, right = self.eval(node.left), self.eval(node.right)
        self.known(left, right)
        op = type(node.op)
        self.check_size(op, left, right)
        if op is ast.Mod and isinstance(left, str):
            _check_format(left)
            self.guard(lambda: budget.percent_length(left, right, self.limits.length))
        return self.guard(lambda: _BINARY[op](left, right))

    def check_size(self, op: type, left: Any, right: Any) -> None:
        """Refuse operations whose result would exceed the bounds, before doing them."""
        limits = self.limits
        if op is ast.Mult:
            for seq, count in ((left, right), (right, left)):
                if isinstance(seq, (str, list, tuple, bytes)) and isinstance(count, int) \
                        and len(seq) * max(count, 0) > limits.length:
                    raise _Stop(Unknown(f"result longer than {limits.length}", "limit"))
        elif op is ast.Pow and isinstance(left, int) and isinstance(right, int):
            if right > 0 and abs(left) > 1 and \
                    left.bit_length() * right > limits.int_bits:
                raise _Stop(Unknown(f"integer larger than {limits.int_bits} bits", "limit"))
        elif op is ast.Pow and isinstance(left, (int, float)) \
                and isinstance(right, (int, float)) and abs(right) > 10_000:
            raise _Stop(Unknown("exponent too large", "limit"))
        elif op is ast.LShift and isinstance(right, int) and right > limits.int_bits:
            raise _Stop(Unknown(f"integer larger than {limits.int_bits} bits", "limit"))
        symbol = _INT_OPS.get(op)
        if symbol is not None and not isinstance(left, bool) and not isinstance(right, bool):
            self.guard(lambda: budget.check_int_op(symbol, left, right, limits.int_bits))

    def eval_Compare(self, node: ast.Compare) -> Any:
        left = self.eval(node.left)
        for op, comparator in zip(node.ops, node.comparators, strict=True):
            right = self.eval(comparator)
            self.known(left, right)
            if isinstance(left, _SIZED) and isinstance(right, _SIZED):  # == walks both
                bound = self.limits.steps
                self.step(min(budget.text_length(left, bound), budget.text_length(right, bound)))
            compare = _COMPARE[type(op)]
            outcome = self.guard(lambda: compare(left, right))  # noqa: B023 (called at once)
            if not outcome:
                return False
            left = right
        return True

    def eval_IfExp(self, node: ast.IfExp) -> Any:
        test = self.eval(node.test)
        if isinstance(test, Unknown):
            body, orelse = self.eval(node.body), self.eval(node.orelse)
            same = not isinstance(body, Unknown) and type(body) is type(orelse) \
                and body == orelse
            return body if same else test
        return self.eval(node.body if test else node.orelse)

    def eval_Subscript(self, node: ast.Subscript) -> Any:
        value = self.eval(node.value)
        index = self.eval(node.slice)
        self.known(value, index)
        if not isinstance(value, (str, list, tuple, dict, bytes)):
            raise _Stop(Unknown(f"{type(value).__name__} is not subscriptable", "error"))
        return self.guard(lambda: value[index])

    def eval_Slice(self, node: ast.Slice) -> Any:
        parts = [self.eval(p) if p is not None else None
                 for p in (node.lower, node.upper, node.step)]
        self.known(*parts)
        return slice(*parts)

    # -- calls -----------------------------------------------------------------------------
    def eval_Call(self, node: ast.Call) -> Any:
        if node.keywords and isinstance(node.func, ast.Name):
            raise _Stop(Unknown("keyword arguments are not supported", "unsupported"))
        if any(isinstance(a, ast.Starred) for a in node.args):
            raise _Stop(Unknown("*arguments are not supported", "unsupported"))
        if isinstance(node.func, ast.Attribute):
            return self.method(node)
        if isinstance(node.func, ast.Name) and node.func.id not in self.functions \
                and not any(node.func.id in scope for scope in self.scopes):
            raise _Stop(Unknown(f"'{node.func.id}' is not a known function", "unsupported"))
        target = self.eval(node.func)
        if not isinstance(target, _Function):
            if isinstance(target, Unknown):
                return target
            name = getattr(node.func, "id", type(node.func).__name__)
            raise _Stop(Unknown(f"'{name}' is not a known function", "unsupported"))
        args = [self.eval(a) for a in node.args]
        for arg in args:
            self.step(len(arg) if isinstance(arg, (str, list, tuple, dict, set)) else 1)
        self.known(*args)
        result = self.guard(lambda: target.call(*args))
        return result

    def method(self, node: ast.Call) -> object:
        func = node.func
        assert isinstance(func, ast.Attribute)
        name = func.attr
        if name.startswith("_"):
            raise _Stop(Unknown(f"attribute '{name}' is forbidden", "unsupported"))
        owner = self.eval(func.value)
        args = [self.eval(a) for a in node.args]
        kwargs = {k.arg: self.eval(k.value) for k in node.keywords if k.arg is not None}
        if len(kwargs) != len(node.keywords):
            raise _Stop(Unknown("**keywords are not supported", "unsupported"))
        self.known(owner, *args, *kwargs.values())
        if isinstance(owner, str):
            allowed = _STR_METHODS
        elif isinstance(owner, (list, tuple)):
            allowed = _LIST_METHODS
        elif isinstance(owner, dict):
            allowed = _DICT_METHODS
        elif isinstance(owner, (set, frozenset)):
            allowed = _SET_METHODS
        else:
            allowed = frozenset()
        if name not in allowed:
            raise _Stop(Unknown(f"method {type(owner).__name__}.{name} is not supported",
                                "unsupported"))
        self.step(len(owner) if isinstance(owner, (str, list, tuple, dict, set, frozenset))
                  else 1)
        if isinstance(owner, (set, frozenset)):  # the result is no larger than its inputs
            self.step(sum(len(a) if isinstance(a, (str, list, tuple, dict, set, frozenset))
                          else 1 for a in args))
        if isinstance(owner, str):
            self.check_string_method(owner, name, args)
            self.guard(lambda: budget.str_method_length(owner, name, args, kwargs,
                                                        self.limits.length))
        bound = getattr(owner, name)
        result = self.guard(lambda: bound(*args, **kwargs))
        if name in ("keys", "values", "items"):
            result = list(result)
        return result

    def check_string_method(self, owner: str, name: str, args: list[Any]) -> None:
        length = self.limits.length
        if name == "format":
            _check_format(owner)
        elif name in _PADDING and args and isinstance(args[0], int) and args[0] > length:
            raise _Stop(Unknown(f"result longer than {length}", "limit"))
        elif name == "replace" and len(args) >= 2 and isinstance(args[0], str) \
                and isinstance(args[1], str):
            hits = owner.count(args[0]) if args[0] else len(owner) + 1
            if len(owner) + hits * max(len(args[1]) - len(args[0]), 0) > length:
                raise _Stop(Unknown(f"result longer than {length}", "limit"))
        elif name == "join" and args and isinstance(args[0], (list, tuple)) \
                and len(owner) * len(args[0]) > length:
            raise _Stop(Unknown(f"result longer than {length}", "limit"))

    # -- comprehensions --------------------------------------------------------------------
    def comprehension(self, generators: list[ast.comprehension],
                      emit: Callable[[], None]) -> None:
        def loop(index: int) -> None:
            if index == len(generators):
                emit()
                return
            gen = generators[index]
            if gen.is_async:
                raise _Stop(Unknown("async comprehensions are not supported", "unsupported"))
            iterable = self.eval(gen.iter)
            self.known(iterable)
            if not isinstance(iterable, (str, list, tuple, dict, set, frozenset)):
                raise _Stop(Unknown(f"cannot iterate over {type(iterable).__name__}",
                                    "unsupported"))
            for item in list(iterable):
                self.step()
                self.bind(gen.target, item)
                if all(self.truth(self.eval(cond)) for cond in gen.ifs):
                    loop(index + 1)

        self.scopes.append({})
        try:
            loop(0)
        finally:
            self.scopes.pop()

    def bind(self, target: ast.AST, item: object) -> None:
        if isinstance(target, ast.Name):
            self.scopes[-1][target.id] = item
        elif isinstance(target, (ast.Tuple, ast.List)) and isinstance(item, (tuple, list)) \
                and len(item) == len(target.elts):
            for sub, value in zip(target.elts, item, strict=True):
                self.bind(sub, value)
        else:
            raise _Stop(Unknown("unsupported comprehension target", "unsupported"))

    def truth(self, value: object) -> bool:
        self.known(value)
        return bool(value)

    def eval_ListComp(self, node: ast.ListComp | ast.GeneratorExp | ast.SetComp) -> Any:
        out: list[object] = []
        self.comprehension(node.generators, lambda: self.append(out, self.eval(node.elt)))
        return out

    eval_GeneratorExp = eval_ListComp  # a generator passed to a function: a list will do

    def eval_SetComp(self, node: ast.SetComp) -> Any:
        items = self.eval_ListComp(node)
        return self.guard(lambda: set(items))

    def eval_DictComp(self, node: ast.DictComp) -> Any:
        out: list[Any] = []
        self.comprehension(node.generators, lambda: self.append(
            out, (self.eval(node.key), self.eval(node.value))))
        self.known(*(pair[0] for pair in out))
        return self.guard(lambda: dict(out))

    def append(self, out: list[object], item: object) -> None:
        self.known(item)
        out.append(item)
        if len(out) > self.limits.length:
            raise _Stop(Unknown(f"result longer than {self.limits.length}", "limit"))

    # -- helpers -------------------------------------------------------------------------
    @staticmethod
    def known(*values: object) -> None:
        for value in values:
            if isinstance(value, Unknown):
                raise _Stop(value)
            if isinstance(value, _Function):
                raise _Stop(Unknown(f"function '{value.name}' used as a value",
                                    "unsupported"))

    @staticmethod
    def guard(action: Callable[[], Any]) -> Any:
        try:
            return action()
        except budget.OverBudget as err:
            kind: UnknownKind = "unsupported" if err.kind == "unsupported" else "limit"
            raise _Stop(Unknown(err.reason, kind)) from None
        except (ArithmeticError, TypeError, ValueError, LookupError, AttributeError) as err:
            raise _Stop(Unknown(f"{type(err).__name__}: {err}", "error")) from None


def _shape_ok(tree: ast.AST, limits: Limits) -> Unknown | None:
    """Check node count and nesting depth without recursion."""
    count = 0
    stack: list[tuple[ast.AST, int]] = [(tree, 0)]
    while stack:
        node, depth = stack.pop()
        count += 1
        if count > limits.nodes:
            return Unknown(f"expression has more than {limits.nodes} parts", "limit")
        if depth > limits.depth:
            return Unknown(f"expression nested deeper than {limits.depth}", "limit")
        stack.extend((child, depth + 1) for child in ast.iter_child_nodes(node))
    return None


def evaluate(text: str, names: Callable[[str], object] | None = None,
             functions: Mapping[str, Any] | None = None,
             limits: Limits | None = None) -> object:
    """Evaluate the Python expression ``text`` safely; an ``Unknown`` when it cannot be.

    ``functions`` defaults to ``BUILTINS``; pass ``{**BUILTINS, **MATH, ...}`` to add
    more. Never raises for bad input and never runs code from ``text``.
    """
    limits = limits or Limits()
    if len(text) > limits.text:
        return Unknown(f"expression longer than {limits.text} characters", "limit")
    try:
        tree = syntax.parse(text.strip(), mode="eval")
    except SyntaxError as err:
        return Unknown(f"not a Python expression: {err.msg}", "syntax")
    except (RecursionError, MemoryError, ValueError):
        return Unknown("expression too deeply nested", "limit")
    refused = _shape_ok(tree, limits)
    if refused is not None:
        return refused
    interpreter = _Interpreter(names, BUILTINS if functions is None else functions, limits)
    try:
        result = interpreter.eval(tree)
        interpreter.known(result)
        return result
    except _Stop as stop:
        return stop.unknown
    except RecursionError:
        return Unknown("expression too deeply nested", "limit")


def names_from(mapping: Mapping[str, object]) -> Callable[[str], object]:
    """A ``names`` callback over a mapping (``KeyError`` for names not in it)."""
    return mapping.__getitem__


def unknown_reasons(values: Iterable[object]) -> list[str]:
    return [v.reason for v in values if isinstance(v, Unknown)]
