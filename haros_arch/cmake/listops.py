"""CMake's ``list()``, ``string()`` and ``math()`` commands over a variable scope.

Each function takes the already-expanded arguments and a ``Scope`` (get / set / unset);
subcommands that depend on the build machine (``string(TIMESTAMP)``, ``RANDOM``) set
nothing, which leaves the variable unknown.
"""

from __future__ import annotations

import ast
import operator
import re
import time
from collections.abc import Callable
from typing import Protocol, TypeVar

import regex

_LIST_SEPARATOR = re.compile(r"(?<!\\);")
T = TypeVar("T")


class Scope(Protocol):
    def get(self, name: str) -> str | None: ...
    def set(self, name: str, value: str) -> None: ...
    def unset(self, name: str) -> None: ...


def split_list(value: str | None) -> list[str]:
    """A CMake list: ``;``-separated, empty items dropped, ``\\;`` kept."""
    if not value:
        return []
    if "\\;" not in value:
        return [item for item in value.split(";") if item]
    return [item for item in _LIST_SEPARATOR.split(value) if item]


REGEX_SECONDS = 0.5  # of processor time: one match, search or replace; a backtracking
# pattern stops there
REGEX_WAIT_SECONDS = 32.0  # the longest the engine is let run by the clock


class RegexLimit(Exception):
    """A CMake regular expression ran past ``REGEX_SECONDS`` (a backtracking pattern on a
    long value): what it would have set stays unknown."""


class BoundedRegex:
    """A compiled CMake regular expression whose every use is bounded in time."""

    def __init__(self, compiled: regex.Pattern[str]) -> None:
        self.compiled = compiled
        self.groups = compiled.groups

    def _bounded(self, use: Callable[[float], T]) -> T:
        """``use(timeout)`` within ``REGEX_SECONDS`` of this thread's processor time. The
        engine's bound is of the clock: where it passes while the thread had the processor
        for less than the bound (a machine busy with other work), the use is tried again
        with a longer wait, so that whether a value is known does not depend on the
        machine's load."""
        wait = REGEX_SECONDS
        while True:
            began = time.thread_time()
            try:
                return use(wait)
            except TimeoutError:
                if time.thread_time() - began >= REGEX_SECONDS or wait >= REGEX_WAIT_SECONDS:
                    raise RegexLimit(self.compiled.pattern) from None
                wait *= 4

    def search(self, text: str) -> regex.Match[str] | None:
        return self._bounded(lambda wait: self.compiled.search(text, timeout=wait))

    def finditer(self, text: str) -> list[regex.Match[str]]:
        return self._bounded(lambda wait: list(self.compiled.finditer(text, timeout=wait)))

    def sub(self, replace: Callable[[regex.Match[str]], str], text: str) -> str:
        return self._bounded(lambda wait: self.compiled.sub(replace, text, timeout=wait))


def cmake_regex(pattern: str) -> BoundedRegex | None:
    """CMake regular expressions are close to Python's; bad ones give None. They run on
    the ``regex`` engine, which takes a time bound."""
    try:
        return BoundedRegex(regex.compile(pattern))
    except (regex.error, RecursionError, ValueError):
        return None


def _replacement(text: str) -> Callable[[regex.Match[str]], str]:
    def replace(match: regex.Match[str]) -> str:
        def group(ref: re.Match[str]) -> str:
            index = int(ref.group(1))
            return (match.group(index) or "") if index <= (match.re.groups or 0) else ""
        return re.sub(r"\\(\d)", group, text)
    return replace


def run_list(args: list[str], scope: Scope) -> None:
    if len(args) < 2:
        return
    sub, var, rest = args[0].upper(), args[1], args[2:]
    items = split_list(scope.get(var))

    def put(values: list[str], name: str = var) -> None:
        scope.set(name, ";".join(values))

    if sub == "APPEND":
        put(items + rest)
    elif sub == "PREPEND":
        put(rest + items)
    elif sub == "LENGTH" and rest:
        scope.set(rest[0], str(len(items)))
    elif sub == "GET" and len(rest) >= 2:
        picked = [items[i] for i in _indexes(rest[:-1], len(items))]
        if len(picked) == len(rest) - 1:
            put(picked, rest[-1])
    elif sub == "JOIN" and len(rest) >= 2:
        scope.set(rest[1], rest[0].join(items))
    elif sub == "SUBLIST" and len(rest) >= 3 and _is_int(rest[0]) and _is_int(rest[1]):
        start, length = int(rest[0]), int(rest[1])
        put(items[start:] if length < 0 else items[start:start + length], rest[2])
    elif sub == "FIND" and len(rest) >= 2:
        scope.set(rest[1], str(items.index(rest[0]) if rest[0] in items else -1))
    elif sub == "INSERT" and rest and _is_int(rest[0]):
        index = int(rest[0])
        put(items[:index] + rest[1:] + items[index:])
    elif sub in ("POP_BACK", "POP_FRONT"):
        take = items[-1:] if sub == "POP_BACK" else items[:1]
        put(items[:-1] if sub == "POP_BACK" else items[1:])
        for name in rest[:1]:
            put(take, name)
    elif sub == "REMOVE_ITEM":
        put([item for item in items if item not in rest])
    elif sub == "REMOVE_AT":
        drop = set(_indexes(rest, len(items)))
        put([item for i, item in enumerate(items) if i not in drop])
    elif sub == "REMOVE_DUPLICATES":
        put(list(dict.fromkeys(items)))
    elif sub == "REVERSE":
        put(items[::-1])
    elif sub == "SORT":
        put(sorted(items, key=str.lower if "INSENSITIVE" in rest else None,
                   reverse="DESCENDING" in rest))
    elif sub == "FILTER" and len(rest) >= 3 and rest[1] == "REGEX":
        pattern = cmake_regex(rest[2])
        if pattern is not None:
            keep = rest[0] == "INCLUDE"
            put([item for item in items if (pattern.search(item) is not None) == keep])
    elif sub == "TRANSFORM" and rest:
        _transform(items, rest, var, scope)


def _transform(items: list[str], rest: list[str], var: str, scope: Scope) -> None:
    action, rest = rest[0].upper(), rest[1:]
    output = var
    if "OUTPUT_VARIABLE" in rest:
        at = rest.index("OUTPUT_VARIABLE")
        output = rest[at + 1] if at + 1 < len(rest) else var
        rest = rest[:at]
    if action in ("APPEND", "PREPEND") and rest:
        done = [x + rest[0] if action == "APPEND" else rest[0] + x for x in items]
    elif action in ("TOUPPER", "TOLOWER", "STRIP"):
        done = [x.upper() if action == "TOUPPER" else x.lower() if action == "TOLOWER"
                else x.strip() for x in items]
    elif action == "REPLACE" and len(rest) >= 2 and (pattern := cmake_regex(rest[0])):
        done = [pattern.sub(_replacement(rest[1]), x) for x in items]
    elif action == "GENEX_STRIP":
        done = [x for x in items if not x.startswith("$<")]
    else:
        return
    scope.set(output, ";".join(done))


def _is_int(text: str) -> bool:
    return re.fullmatch(r"-?\d+", text) is not None


def _indexes(texts: list[str], size: int) -> list[int]:
    out = []
    for text in texts:
        if _is_int(text) and -size <= int(text) < size:
            out.append(int(text) % size)
    return out


def run_string(args: list[str], scope: Scope) -> None:
    if len(args) < 2:
        return
    sub = args[0].upper()
    if sub == "REGEX" and len(args) >= 4:
        _string_regex(args[1].upper(), args[2:], scope)
        return
    rest = args[1:]
    if sub == "REPLACE" and len(rest) >= 3:
        scope.set(rest[2], "".join(rest[3:]).replace(rest[0], rest[1]) if rest[0] else "")
    elif sub in ("CONCAT", "JOIN"):
        if sub == "CONCAT":
            scope.set(rest[0], "".join(rest[1:]))
        elif len(rest) >= 2:
            scope.set(rest[1], rest[0].join(rest[2:]))
    elif sub in ("APPEND", "PREPEND"):
        current = scope.get(rest[0]) or ""
        added = "".join(rest[1:])
        scope.set(rest[0], current + added if sub == "APPEND" else added + current)
    elif sub in ("TOUPPER", "TOLOWER", "STRIP", "MAKE_C_IDENTIFIER", "GENEX_STRIP",
                 "LENGTH") and len(rest) >= 2:
        scope.set(rest[1], _transform_one(sub, rest[0]))
    elif sub == "SUBSTRING" and len(rest) >= 4 and _is_int(rest[1]) and _is_int(rest[2]):
        start, length = int(rest[1]), int(rest[2])
        text = rest[0][start:] if length < 0 else rest[0][start:start + length]
        scope.set(rest[3], text)
    elif sub == "FIND" and len(rest) >= 3:
        finder = str.rfind if "REVERSE" in rest[3:] else str.find
        scope.set(rest[2], str(finder(rest[0], rest[1])))
    elif sub == "REPEAT" and len(rest) >= 3 and _is_int(rest[1]):
        scope.set(rest[2], rest[0] * min(max(int(rest[1]), 0), 1000))
    elif sub == "COMPARE" and len(rest) >= 4:
        left, right = rest[1], rest[2]
        table = {"EQUAL": left == right, "NOTEQUAL": left != right, "LESS": left < right,
                 "GREATER": left > right, "LESS_EQUAL": left <= right,
                 "GREATER_EQUAL": left >= right}
        if rest[0].upper() in table:
            scope.set(rest[3], "1" if table[rest[0].upper()] else "0")
    elif sub in ("TIMESTAMP", "RANDOM", "UUID", "MD5", "SHA1", "SHA256"):
        for name in rest[:1]:
            scope.unset(name)


def _transform_one(sub: str, text: str) -> str:
    if sub == "TOUPPER":
        return text.upper()
    if sub == "TOLOWER":
        return text.lower()
    if sub == "STRIP":
        return text.strip()
    if sub == "LENGTH":
        return str(len(text))
    if sub == "GENEX_STRIP":
        return re.sub(r"\$<[^<>]*>", "", text)
    out = re.sub(r"[^A-Za-z0-9_]", "_", text)
    return "_" + out if out[:1].isdigit() else out


def _string_regex(mode: str, rest: list[str], scope: Scope) -> None:
    pattern = cmake_regex(rest[0])
    if pattern is None:
        return
    if mode == "MATCH" and len(rest) >= 3:
        found = pattern.search("".join(rest[2:]))
        scope.set(rest[1], found.group() if found else "")
    elif mode == "MATCHALL" and len(rest) >= 3:
        scope.set(rest[1], ";".join(m.group() for m in pattern.finditer("".join(rest[2:]))))
    elif mode == "REPLACE" and len(rest) >= 4:
        scope.set(rest[2], pattern.sub(_replacement(rest[1]), "".join(rest[3:])))


def _c_divide(a: int, b: int) -> int:
    """C's integer division (toward zero), exact for any size (not through a float)."""
    quotient = abs(a) // abs(b)
    return quotient if (a < 0) == (b < 0) else -quotient


_OPERATORS: dict[type, Callable[..., int]] = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
    ast.Div: _c_divide, ast.Mod: lambda a, b: a - b * _c_divide(a, b),
    ast.LShift: operator.lshift, ast.RShift: operator.rshift, ast.BitAnd: operator.and_,
    ast.BitOr: operator.or_, ast.BitXor: operator.xor,
    ast.USub: operator.neg, ast.UAdd: operator.pos, ast.Invert: operator.invert,
}


def run_math(args: list[str], scope: Scope) -> None:
    """``math(EXPR var "expr" [OUTPUT_FORMAT ...])``: CMake's integer arithmetic, with C's
    rules (64-bit operands, ``/`` and ``%`` toward zero, no floats, no names or calls): not
    Python's, so its own small walker rather than a configuration of the one evaluator."""
    if len(args) < 3 or args[0] != "EXPR":
        return
    value = evaluate_integer(args[2])
    if value is None:
        scope.unset(args[1])
    elif args[3:5] == ["OUTPUT_FORMAT", "HEXADECIMAL"]:
        scope.set(args[1], hex(value))
    else:
        scope.set(args[1], str(value))


def evaluate_integer(text: str) -> int | None:
    if len(text) > 500:
        return None
    try:
        tree = ast.parse(text.strip(), mode="eval")
        return _integer(tree.body)
    except (SyntaxError, ValueError, ZeroDivisionError, OverflowError, RecursionError):
        return None


def _integer(node: ast.AST) -> int:
    if isinstance(node, ast.Constant) and isinstance(node.value, int):
        if abs(node.value) >= 2**63:
            raise OverflowError
        return node.value
    if isinstance(node, ast.UnaryOp) and type(node.op) in _OPERATORS:
        return _OPERATORS[type(node.op)](_integer(node.operand))
    if isinstance(node, ast.BinOp) and type(node.op) in _OPERATORS:
        left, right = _integer(node.left), _integer(node.right)
        if isinstance(node.op, ast.LShift) and right > 63:
            raise OverflowError
        return _OPERATORS[type(node.op)](left, right)
    raise ValueError("not integer arithmetic")
