"""The safe interpreter: evaluates a query AST over the model, within limits.

One handler per AST class (``_eval_<Class>``), found by name. Values are model objects
(read through ``access``), primitives, lists, tuples, dicts, whitelisted functions and
bound string methods; nothing else can be reached. Every binding, path item and function
step is charged to a step budget, and the clock is checked as the budget is spent.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

from ..evaluate.budget import text_length
from . import syntax as s
from .access import _CACHE as _READERS
from .access import PRIMITIVES, STRING_METHODS, Method, Pair, readers_of
from .errors import QueryError, QueryLimitError, QueryNameError, QueryTypeError
from .functions import Function
from .planner import Plan, plan
from .planner import conjuncts as plan_conjuncts

MISSING = object()
# a list a filter reads, the items its first conjuncts keep, and their index (``_Filter``)
_Filtered = tuple[Any, list[Any], dict[str, list[Any]] | None]
DEFAULT_STEPS = 20_000_000
DEFAULT_SECONDS = 10.0
MAX_STRING = 1_000_000
MAX_RESULTS = 1_000_000
# characters of strings the query builds plus the printed size of its results, together:
# what a query may make in memory (each result is counted as printed, shared parts each time)
MAX_MADE = 50_000_000
_CLOCK_EVERY = 4096


def key_of(value: Any) -> Any:
    """A key for set semantics: hashable values by value, others by identity."""
    try:
        hash(value)
    except TypeError:
        return ("#id", id(value))
    return value


def distinct(values: Iterable[Any]) -> list[Any]:
    seen: dict[Any, Any] = {}
    for value in values:
        seen.setdefault(key_of(value), value)
    return list(seen.values())


class Evaluator:
    """Evaluates one query over one context (a mapping of names to values)."""

    def __init__(self, text: str, context: dict[str, Any], max_steps: int = DEFAULT_STEPS,
                 max_seconds: float = DEFAULT_SECONDS) -> None:
        self.text = text
        self.env: dict[str, Any] = dict(context)
        self.steps_left = max_steps
        self.max_steps = max_steps
        self.max_seconds = max_seconds
        self.deadline = time.thread_time() + max_seconds  # processor time: not load
        self.until_clock = _CLOCK_EVERY
        self.plans: dict[int, Plan] = {}
        self.caches: dict[int, dict[Any, Any]] = {}
        self.handlers: dict[type, Callable[[Any], Any]] = {}
        self.hoisted: set[int] = set()  # sub-expressions evaluated once (syntax.invariants)
        self.memo: dict[int, Any] = {}
        self.free: dict[int, frozenset[str]] = {}  # syntax.unbound_names, per sub-expression
        self.bound: set[str] = set()  # every name the query binds (syntax.binders)
        self.filters: dict[int, _Filter] = {}  # per filtered step: its conjuncts, split
        # per filtered step and list it filters (a context name's)
        self.filtered: dict[tuple[int, int], _Filtered] = {}
        self.made = 0

    # ---- limits
    def charge(self, steps: int = 1) -> None:
        self.steps_left -= steps
        self.until_clock -= steps
        if self.steps_left < 0:
            raise QueryLimitError(f"the query used more than {self.max_steps:,} steps; "
                                  "narrow it with filters or an equality join")
        if self.until_clock <= 0:
            self.until_clock = _CLOCK_EVERY
            if time.thread_time() > self.deadline:
                raise QueryLimitError(f"the query ran longer than {self.max_seconds:g} s "
                                      "of processor time")

    def make(self, size: int, node: s.Expr) -> None:
        """Count ``size`` characters (or items) the query makes against ``MAX_MADE``."""
        self.made += size
        if self.made > MAX_MADE:
            raise self.fail(QueryLimitError, f"the query's results and the strings it builds "
                            f"pass {MAX_MADE:,} characters; narrow it or return less", node)

    def fail(self, error: type[QueryError], message: str, node: s.Expr) -> QueryError:
        return error(message, self.text, node.pos)

    # ---- entry
    def run(self, node: s.Expr) -> Any:
        self.free = {}
        s.unbound_names(node, self.free)
        self.bound = s.binders(node)
        self.hoisted = s.invariants(node, self.free, self.bound)
        self.memo = {}
        self.filters = {}
        self.filtered = {}
        try:
            return self.eval(node)
        except RecursionError:
            raise QueryLimitError("the query recursed too deeply", self.text, node.pos) from None

    def eval(self, node: s.Expr) -> Any:
        handler = self.handlers.get(type(node))
        if handler is None:
            handler = self.handlers[type(node)] = getattr(self, "_eval_" + type(node).__name__)
        if id(node) not in self.hoisted:
            return handler(node)
        value = self.memo.get(id(node), MISSING)
        if value is MISSING:
            value = self.memo[id(node)] = handler(node)
        return value

    def truth(self, node: s.Expr) -> bool:
        return bool(self.eval(node))

    def collection(self, node: s.Expr) -> list[Any]:
        """A source of a ``for``, quantifier or set: always a list."""
        value = self.eval(node)
        if isinstance(value, list):
            return value
        if isinstance(value, tuple | set | frozenset):
            return list(value)
        if isinstance(value, dict):
            return [Pair(k, v) for k, v in value.items()]
        return [value]

    # ---- scalars
    def _eval_Literal(self, node: s.Literal) -> Any:
        return node.value

    def _eval_Name(self, node: s.Name) -> Any:
        value = self.env.get(node.name, MISSING)
        if value is MISSING:
            known = ", ".join(sorted(k for k in self.env if not k[:1].isupper()))
            raise self.fail(QueryNameError, f"unknown name '{node.name}' (known: {known})",
                            node)
        return value

    def attribute(self, value: Any, name: str, node: s.Expr) -> Any:
        if isinstance(value, str):
            if name in STRING_METHODS:
                return Method(value, name)
            raise self.fail(QueryNameError, f"a string has no field '{name}' (methods: "
                            f"{', '.join(sorted(STRING_METHODS))})", node)
        readers = readers_of(type(value))
        read = readers.get(name)
        if read is None:
            what = _describe_type(value)
            allowed = f" (fields: {', '.join(sorted(readers))})" if readers else ""
            raise self.fail(QueryNameError, f"{what} has no field '{name}'{allowed}", node)
        return read(value)

    def _eval_Attr(self, node: s.Attr) -> Any:
        value = self.eval(node.obj)
        read = _READERS.get(type(value))
        if read is not None:  # the common case: a model value's allowed field
            getter = read.get(node.name)
            if getter is not None:
                return getter(value)
        return self.attribute(value, node.name, node)

    def _eval_Index(self, node: s.Index) -> Any:
        container, key = self.eval(node.obj), self.eval(node.key)
        if isinstance(container, list | tuple | str) and isinstance(key, int) \
                and not isinstance(key, bool):
            if -len(container) <= key < len(container):
                return container[key]
            raise self.fail(QueryTypeError, f"index {key} is out of range", node)
        if isinstance(container, dict):
            if key in container:
                return container[key]
            raise self.fail(QueryTypeError, f"no key {key!r}", node)
        raise self.fail(QueryTypeError, f"cannot index {_describe_type(container)} with "
                        f"{_describe_type(key)}", node)

    def _eval_Call(self, node: s.Call) -> Any:
        func = self.eval(node.func)
        args = [self.eval(arg) for arg in node.args]
        self.charge()
        try:
            if isinstance(func, Function):
                if not func.min_args <= len(args) <= func.max_args:
                    raise QueryTypeError(f"{func.name}() takes {func.min_args}"
                                         + (f" to {func.max_args}" if func.max_args
                                            != func.min_args else "")
                                         + f" argument(s), got {len(args)}")
                return func.impl(self.charge, *args)
            if isinstance(func, Method):
                return self.call_method(func, args)
        except QueryError as err:
            raise err.at(self.text, node.pos) from None
        raise self.fail(QueryTypeError, f"{_describe_type(func)} is not a function", node)

    def call_method(self, method: Method, args: list[Any]) -> Any:
        if not all(isinstance(a, PRIMITIVES) or (isinstance(a, tuple) and all(
                isinstance(x, str) for x in a)) for a in args):
            raise QueryTypeError(f"str.{method.name}() takes strings and numbers")
        self.charge(1 + len(method.target) // 256)
        try:
            result = getattr(str, method.name)(method.target, *args)
        except (TypeError, ValueError) as err:
            raise QueryTypeError(f"str.{method.name}(): {err}") from None
        if isinstance(result, list):
            self.charge(len(result))
        return result

    def _eval_ListOf(self, node: s.ListOf) -> list[Any]:
        return [self.eval(item) for item in node.items]

    def _eval_Neg(self, node: s.Neg) -> Any:
        value = self.eval(node.operand)
        if isinstance(value, int | float):
            return -value
        raise self.fail(QueryTypeError, f"cannot negate {_describe_type(value)}", node)

    def _eval_Arith(self, node: s.Arith) -> Any:
        left, right = self.eval(node.left), self.eval(node.right)
        numbers = isinstance(left, int | float) and isinstance(right, int | float)
        if node.op == "+" and isinstance(left, str) and isinstance(right, str):
            if len(left) + len(right) > MAX_STRING:
                raise self.fail(QueryLimitError, f"a string longer than {MAX_STRING:,} "
                                "characters", node)
            self.make(len(left) + len(right), node)
            return left + right
        if not numbers:
            raise self.fail(QueryTypeError, f"'{node.op}' needs numbers (or two strings for "
                            f"'+'), got {_describe_type(left)} and {_describe_type(right)}",
                            node)
        if node.op in "/%" and right == 0:
            raise self.fail(QueryTypeError, "division by zero", node)
        result = {"+": lambda: left + right, "-": lambda: left - right,
                  "*": lambda: left * right, "/": lambda: left / right,
                  "%": lambda: left % right}[node.op]()
        if isinstance(result, int) and result.bit_length() > 4096:
            raise self.fail(QueryLimitError, "a number too large", node)
        return result

    # ---- conditions
    def _eval_And(self, node: s.And) -> bool:
        return self.truth(node.left) and self.truth(node.right)

    def _eval_Or(self, node: s.Or) -> bool:
        return self.truth(node.left) or self.truth(node.right)

    def _eval_Not(self, node: s.Not) -> bool:
        return not self.truth(node.operand)

    def _eval_Compare(self, node: s.Compare) -> bool:
        left, right = self.eval(node.left), self.eval(node.right)
        try:
            if node.op == "==":
                return bool(left == right)
            if node.op == "!=":
                return bool(left != right)
            if node.op in ("in", "not in"):
                if isinstance(right, str):
                    if not isinstance(left, str):
                        raise TypeError("'in <string>' needs a string on the left")
                    found = left in right
                elif isinstance(right, list | tuple | set | frozenset | dict):
                    self.charge(1 + len(right) // 64)
                    found = left in right
                else:
                    raise TypeError(f"'in' needs a collection, got {_describe_type(right)}")
                return found if node.op == "in" else not found
            ordering = {"<": lambda: left < right, "<=": lambda: left <= right,
                        ">": lambda: left > right, ">=": lambda: left >= right}
            return bool(ordering[node.op]())
        except TypeError as err:
            message = str(err)
            if "not supported" in message:
                message = (f"cannot compare {_describe_type(left)} {node.op} "
                           f"{_describe_type(right)}")
            raise self.fail(QueryTypeError, message, node) from None

    def _eval_SetCompare(self, node: s.SetCompare) -> bool:
        left = {key_of(v) for v in self.collection(node.left)}
        right = {key_of(v) for v in self.collection(node.right)}
        return {"subset": left <= right, "superset": left >= right,
                "proper subset": left < right, "proper superset": left > right,
                "is": left == right, "is not": left != right}[node.op]

    def _eval_Quantified(self, node: s.Quantified) -> bool:
        items = self.collection(node.source)
        if not items:
            return False  # as pyflwor: nothing satisfies, not even "every"
        saved = self.env.get(node.var, MISSING)
        try:
            for item in items:
                self.charge()
                self.env[node.var] = item
                holds = self.truth(node.condition)
                if node.mode == "some" and holds:
                    return True
                if node.mode == "every" and not holds:
                    return False
            return node.mode == "every"
        finally:
            self._restore(node.var, saved)

    def _restore(self, name: str, saved: Any) -> None:
        if saved is MISSING:
            self.env.pop(name, None)
        else:
            self.env[name] = saved

    # ---- paths and sets
    def _eval_Path(self, node: s.Path) -> list[Any]:
        """As pyflwor: items without the step's field are skipped (``links/topic`` walks
        only topic links); a step that no item has is an error, to catch typos."""
        first = node.steps[0]
        current = self._expand(self._eval_Name(s.Name(first.name, pos=first.pos)), first,
                               first.name not in self.bound)
        for step in node.steps[1:]:
            following: list[Any] = []
            missing: Any = MISSING
            for item in current:
                self.charge()
                if not isinstance(item, str) and step.name not in readers_of(type(item)):
                    missing = item
                    continue
                following.extend(self._expand(self.attribute(item, step.name, step), step))
            if missing is not MISSING and not following and len(current) > 0 \
                    and all(step.name not in readers_of(type(i)) for i in current):
                self.attribute(missing, step.name, step)  # raises, listing the fields
            current = following
        return distinct(current)

    def _expand(self, value: Any, step: s.Step, constant: bool = False) -> list[Any]:
        """The items of ``value`` that ``step``'s filter keeps. ``constant``: ``value`` is
        a context name's, the same list wherever the query reads it; the conjuncts the
        filter begins with that read no bound name but ``self`` are then checked once
        per list, not again on each evaluation (``direct_links[self.kind == 'subscribe'
        and self.type == p.type ...]`` inside a ``for`` over ``p``), and an equality
        after them between ``self``'s side and a side that does not read it looks its
        items up by their strings (``_Filter``)."""
        if isinstance(value, list | tuple | set | frozenset):
            items = list(value)
        elif isinstance(value, dict):
            items = [Pair(k, v) for k, v in value.items()]
        else:
            items = [value]
        if step.where is None:
            return items
        rest = [step.where]
        if constant and isinstance(value, list | tuple):
            split = self._filter(step)
            if split.alone:
                items, rest = self._prefiltered(value, items, step, split)
        kept = []
        saved = self.env.get("self", MISSING)
        try:
            for item in items:
                self.charge()
                self.env["self"] = item
                if all(self.truth(c) for c in rest):
                    kept.append(item)
        finally:
            self._restore("self", saved)
        return kept

    def _filter(self, step: s.Step) -> _Filter:
        split = self.filters.get(id(step))
        if split is None:
            conjuncts = plan_conjuncts(step.where)
            alone: list[s.Expr] = []
            while conjuncts and self._self_only(conjuncts[0]):
                alone.append(conjuncts.pop(0))
            own = other = None
            if alone and conjuncts and isinstance(conjuncts[0], s.Compare) \
                    and conjuncts[0].op == "==":
                sides = (conjuncts[0].left, conjuncts[0].right)
                for mine, theirs in (sides, sides[::-1]):
                    if "self" in self.free[id(mine)] and "self" not in self.free[id(theirs)] \
                            and self._self_only(mine):
                        own, other = mine, theirs
                        break
            split = self.filters[id(step)] = _Filter(alone, own, other, conjuncts)
        return split

    def _self_only(self, expr: s.Expr) -> bool:
        """Whether ``expr`` reads no name the query binds but ``self``."""
        return not (self.free[id(expr)] - {"self"}) & self.bound

    def _prefiltered(self, value: Any, items: list[Any], step: s.Step, split: _Filter
                     ) -> tuple[list[Any], list[s.Expr]]:
        """The items of ``value`` that ``split.alone`` keeps, kept per list, and the
        conjuncts left to check on them; through the index of ``split.own`` when it has
        one and the other side is a string."""
        entry = self.filtered.get((id(step), id(value)))
        saved = self.env.get("self", MISSING)
        try:
            if entry is None or entry[0] is not value:
                kept = []
                for item in items:
                    self.charge()
                    self.env["self"] = item
                    if all(self.truth(c) for c in split.alone):
                        kept.append(item)
                index: dict[str, list[Any]] | None = None
                if split.own is not None:
                    index = {}
                    for item in kept:
                        self.charge()
                        self.env["self"] = item
                        key = self.eval(split.own)
                        if type(key) is not str:
                            index = None  # compared as the query writes it, item by item
                            break
                        index.setdefault(key, []).append(item)
                entry = self.filtered[(id(step), id(value))] = (value, kept, index)
        finally:
            self._restore("self", saved)
        _value, kept, index = entry
        if index is not None and split.other is not None:
            probe = self.eval(split.other)  # reads no ``self``: the same for every item
            if type(probe) is str:
                return index.get(probe, []), split.rest[1:]
        return kept, split.rest

    def _eval_SetOp(self, node: s.SetOp) -> list[Any]:
        left, right = self.collection(node.left), self.collection(node.right)
        self.charge(1 + (len(left) + len(right)) // 64)
        if node.op == "|":
            return distinct([*left, *right])
        keys = {key_of(v) for v in right}
        if node.op == "&":
            return distinct(v for v in left if key_of(v) in keys)
        return distinct(v for v in left if key_of(v) not in keys)

    # ---- FLWR
    def _eval_Flwr(self, node: s.Flwr) -> list[Any]:
        the_plan = self.plans.get(id(node))
        if the_plan is None:
            the_plan = self.plans[id(node)] = plan(node)
        results: list[Any] = []
        names = [level.var for level in the_plan.levels] + [var for var, _ in node.lets]
        saved = {name: self.env.get(name, MISSING) for name in names}
        outer_cache = self.caches.get(id(node))
        self.caches[id(node)] = {}  # sources and indexes of this evaluation
        try:
            self._bind(node, the_plan, 0, results)
        finally:
            for name, value in saved.items():
                self._restore(name, value)
            if outer_cache is None:
                del self.caches[id(node)]
            else:
                self.caches[id(node)] = outer_cache
        return results

    def _bind(self, node: s.Flwr, the_plan: Plan, depth: int, results: list[Any]) -> None:
        if depth == len(the_plan.levels):
            for var, expr in node.lets:
                self.env[var] = self.eval(expr)
            if all(self.truth(c) for c in the_plan.residual):
                self.charge()
                if len(results) >= MAX_RESULTS:
                    raise self.fail(QueryLimitError, f"more than {MAX_RESULTS:,} results",
                                    node)
                output = self._output(node)
                self.make(text_length(output, MAX_MADE), node)
                results.append(output)
            return
        level = the_plan.levels[depth]
        candidates: Iterable[Any]
        join = None
        if level.build is not None and level.probe is not None:
            index = self._index(node, depth, level)
            if index is not None:
                candidates = index.get(key_of(self.eval(level.probe)), ())
            else:  # unhashable keys: check the equality on every pair
                candidates, join = self._source(node, depth, level), level.join
        else:
            candidates = self._source(node, depth, level)
        for item in candidates:
            self.charge()
            self.env[level.var] = item
            if join is not None and not self.truth(join):
                continue
            if all(self.truth(f) for f in level.filters):
                self._bind(node, the_plan, depth + 1, results)

    def _source(self, node: s.Flwr, depth: int, level: Any) -> list[Any]:
        if level.correlated:
            return self.collection(level.source)
        cache = self.caches[id(node)]
        key = ("source", depth)
        if key not in cache:
            cache[key] = self.collection(level.source)
        return cache[key]

    def _index(self, node: s.Flwr, depth: int, level: Any) -> dict[Any, list[Any]] | None:
        cache = self.caches[id(node)]
        key = ("index", depth)
        if key in cache:
            return cache[key]
        index: dict[Any, list[Any]] | None = {}
        saved = self.env.get(level.var, MISSING)
        try:
            for item in self._source(node, depth, level):
                self.charge()
                self.env[level.var] = item
                value = self.eval(level.build)
                try:
                    hash(value)
                except TypeError:
                    index = None  # unhashable keys: fall back to checking each pair
                    break
                assert index is not None
                index.setdefault(value, []).append(item)
        finally:
            self._restore(level.var, saved)
        cache[key] = index
        return index

    def _output(self, node: s.Flwr) -> Any:
        values = [self.eval(expr) for expr in node.returns]
        if node.keys is not None:
            return dict(zip(node.keys, values, strict=True))
        return values[0] if len(values) == 1 else tuple(values)


@dataclass
class _Filter:
    """A path step's filter as its conjuncts, in the written order: those it begins with
    that read no bound name but ``self`` (``alone``), then the rest; when the first of
    the rest is ``a == b`` with one side reading ``self`` and no other bound name
    (``own``) and the other not reading ``self`` (``other``), the items ``alone`` keeps
    are looked up by ``own``'s value, a string, instead of comparing each (the same
    items, in their order: ``==`` on strings is the dictionary's)."""

    alone: list[s.Expr]
    own: s.Expr | None
    other: s.Expr | None
    rest: list[s.Expr]


def _describe_type(value: Any) -> str:
    if value is None:
        return "None"
    if isinstance(value, Function):
        return f"the function {value.name}"
    if isinstance(value, list | tuple):
        return "a list"
    if isinstance(value, Method):
        return f"the method str.{value.name}"
    return f"a {type(value).__name__}"
