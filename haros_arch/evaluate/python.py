"""The one safe evaluator of the Python we read: never ``eval``, never imported, never run.

The text is parsed with :mod:`ast` and interpreted here over a small, bounded subset:
literals, arithmetic, comparisons, ``and``/``or``/``not``, conditional expressions,
indexing and slicing, list/tuple/dict/set literals, f-strings, bounded comprehensions,
methods of known values from an allow-list, and the functions each caller provides.
Anything else (attributes other than allowed methods, dunders, unknown functions,
lambdas, ...) is not run: it yields an :class:`Unknown` that says why. Every operation on
known values goes through ``operations``, which charges it by the size of what it would
make before making it.

The walk itself is ``Walker``: dispatch on the node's kind, the step budget, the size check
of every value made, and the constructs that only compute (comparisons, unary operators,
slices, conditional expressions, ``and`` / ``or``, comprehension loops). ``evaluate`` runs
it with every operand known or the expression stopped; the Python launch-file reader
(``launch/ros2/python_expressions.py``) runs it over its partial values, saying what an
operation on one of them gives.

Each reader is a configuration of this module: its own table of functions (``functions``,
keyed by name or dotted name: ``"os.path.join"``), its own names (``names(name)`` returns
a value, returns an ``Unknown`` for a value nobody knows statically, or raises
``KeyError`` for a name that is not defined), whether lists may be changed in place
(``mutate``, for setup.py's ``files.append(...)``), and whether ``__`` anywhere in the
text is refused (roslaunch's rule, kept for every ``$(eval)``). Three calls::

    evaluate(text, names, functions) -> object | Unknown       # one expression
    evaluate_node(node, names, functions) -> object | Unknown  # an already parsed one
    module.run_module(tree, functions) -> Module               # module-level statements

Work is bounded per call (per file for ``run_module``): source length, AST node count and
depth, evaluation steps, the length of strings and containers built, integer size.
"""

from __future__ import annotations

import ast
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typing import Any, NoReturn

from ..model.values import Unknown, UnknownKind
from . import operations as ops
from . import syntax
from .operations import BUILTINS, MATH, Limits, Refused

__all__ = ["BUILTINS", "MATH", "KeyAttributes", "Limits", "Unknown", "Walker", "evaluate",
           "evaluate_counted", "evaluate_node", "is_unknown", "names_from", "undefined_name"]

def is_unknown(value: object) -> bool:
    return isinstance(value, Unknown)


_UNDEFINED = "name '{}' is not defined"


def _undefined(name: str) -> Unknown:
    return Unknown(_UNDEFINED.format(name), "undefined")


def undefined_name(unknown: Unknown) -> str | None:
    """The name an ``undefined`` result of this evaluator did not find, else None."""
    head, tail = _UNDEFINED.split("{}")
    reason = unknown.reason
    if unknown.kind != "undefined" or not (reason.startswith(head) and reason.endswith(tail)):
        return None
    return reason[len(head):len(reason) - len(tail)]


class KeyAttributes(dict):
    """A mapping whose keys read as attributes too, ``d.origin`` for ``d["origin"]``
    where no method of dict has the name: what xacro's ``load_yaml`` gives (its
    YamlDictWrapper). A name that is no key is an error, as it is there."""


class _Stop(Exception):
    """Evaluation cannot go on; carries the Unknown to return."""

    def __init__(self, unknown: Unknown) -> None:
        super().__init__(unknown.reason)
        self.unknown = unknown


@dataclass(frozen=True)
class _Function:
    name: str
    call: Callable[..., Any]


def _dotted(node: ast.expr) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        owner = _dotted(node.value)
        return f"{owner}.{node.attr}" if owner else None
    return None


class Walker:
    """The walk every configuration of the evaluator shares: dispatch on the node's kind
    (``eval_<Kind>(node, env)``), one step charged per node against ``limits.steps``, each
    value made size-checked (``operations.checked``), and Python's own rules for the
    constructs that only compute on the values of their operands: comparisons, unary
    operators, slices, conditional expressions, ``and`` / ``or``, comprehension loops.
    ``env`` is the configuration's scope (a reader of whole files passes its frame;
    ``evaluate`` passes None). A configuration says what stops it (``over``), what
    a node kind it does not interpret gives (``unhandled``), which values it cannot compute
    with (``opaque``: ``Unknown`` and the reader's own partial values), what an operation on
    them gives (``not_known``), and what an operation the one evaluator refuses gives
    (``refused``)."""

    limits: Limits
    steps: int

    def over(self, reason: str) -> NoReturn:
        raise NotImplementedError

    def unhandled(self, node: ast.AST, env: Any = None) -> Any:
        raise NotImplementedError

    def opaque(self, value: object) -> bool:
        return isinstance(value, Unknown)

    def not_known(self, node: ast.AST, what: str, values: Iterable[object]) -> Any:
        raise NotImplementedError

    def refused(self, err: Refused, node: ast.AST, what: str) -> Any:
        raise NotImplementedError

    def step(self, count: int = 1) -> None:
        self.steps += count
        if self.steps > self.limits.steps:
            self.over(f"more than {self.limits.steps} evaluation steps")

    def compute(self, action: Callable[[], Any], node: ast.AST, what: str) -> Any:
        """An operation of ``operations``; what it refuses is the configuration's."""
        try:
            return action()
        except Refused as err:
            return self.refused(err, node, what)

    def eval(self, node: ast.AST, env: Any = None) -> Any:
        self.step()
        handler = getattr(self, "eval_" + type(node).__name__, None)
        if handler is None:
            return self.unhandled(node, env)
        value = handler(node, env)
        return self.compute(lambda: ops.checked(value, self.limits), node, "size")

    def eval_Compare(self, node: ast.Compare, env: Any = None) -> Any:
        left = self.eval(node.left, env)
        for op, comparator in zip(node.ops, node.comparators, strict=True):
            right = self.eval(comparator, env)
            outcome = self.compare_values(op, left, right, node)
            if self.opaque(outcome):
                return outcome
            if not outcome:
                return False
            left = right
        return True

    def compare_values(self, op: ast.cmpop, left: object, right: object,
                       node: ast.Compare) -> Any:
        """One comparison of a chain: its outcome, or a value not known."""
        if self.opaque(left) or self.opaque(right):
            return self.not_known(node, "comparison", (left, right))
        self.step(ops.compare_cost(left, right, self.limits))
        return self.compute(lambda: ops.compare(type(op), left, right), node, "comparison")

    def eval_UnaryOp(self, node: ast.UnaryOp, env: Any = None) -> Any:
        return self.unary_value(node, self.eval(node.operand, env))

    def unary_value(self, node: ast.UnaryOp, value: object) -> Any:
        """A unary operator applied to the value of its operand."""
        what = "not" if isinstance(node.op, ast.Not) else "unary"
        if self.opaque(value):
            # ``not`` of a value the configuration knows the truth of (a launch object)
            truth = self.truth(value) if what == "not" else None
            return self.not_known(node, what, (value,)) if truth is None else not truth
        return self.compute(lambda: ops.unary(type(node.op), value), node, what)

    def eval_Slice(self, node: ast.Slice, env: Any = None) -> Any:
        parts = [self.eval(p, env) if p is not None else None
                 for p in (node.lower, node.upper, node.step)]
        if any(p is not None and (self.opaque(p) or not isinstance(p, int)) for p in parts):
            return self.not_known(node, "slice", parts)
        return slice(*parts)

    past_unknown = False  # and / or: a later operand may still decide (see eval_BoolOp)

    def eval_BoolOp(self, node: ast.BoolOp, env: Any = None) -> Any:
        """Python's short-circuit. An operand not known is ``not_known``; with
        ``past_unknown``, an ``Unknown`` is kept and the later operands are still evaluated
        (one of them may be refused); the result is then that first unknown."""
        is_and = isinstance(node.op, ast.And)
        pending: Unknown | None = None
        result: object = None
        for at, operand in enumerate(node.values):
            result = self.eval(operand, env)
            truth = self.truth(result)
            if truth is not None and at < len(node.values) - 1:
                self.truth_taken(node, operand, result)
            if truth is None:
                if not (self.past_unknown and isinstance(result, Unknown)):
                    return self.not_known(node, "boolean", (result,))
                pending = pending or result
                continue
            if truth != is_and:  # short-circuits: decided whatever came before
                return result if pending is None else pending
        return pending if pending is not None else result

    def truth(self, value: object) -> bool | None:
        """Python's truth of a value; None for one the configuration cannot compute with."""
        return None if self.opaque(value) else bool(value)

    def truth_taken(self, node: ast.BoolOp, operand: ast.expr, value: object) -> None:
        """The ``and`` / ``or`` ``node`` took the truth of ``value``, its ``operand``'s,
        to decide whether to go on (not the last operand, whose value is the result)."""

    def undecided(self, node: ast.IfExp, test: object, env: Any) -> Any:
        """A conditional expression whose test is not known."""
        raise NotImplementedError

    def eval_IfExp(self, node: ast.IfExp, env: Any = None) -> Any:
        test = self.eval(node.test, env)
        truth = self.truth(test)
        if truth is None:
            return self.undecided(node, test, env)
        return self.eval(node.body if truth else node.orelse, env)

    # -- comprehensions: the loops are Python's; what a scope is, the configuration's ----
    def enter(self, env: Any) -> Any:
        """The scope of a comprehension's own variables, inside ``env``."""
        raise NotImplementedError

    def leave(self, scope: Any) -> None:
        pass

    def iterate(self, gen: ast.comprehension, env: Any) -> list[Any]:
        """The items a generator of a comprehension loops over."""
        raise NotImplementedError

    def let(self, target: ast.AST, item: object, env: Any = None) -> None:
        raise NotImplementedError

    def keep(self, gen: ast.comprehension, env: Any) -> bool:
        """Whether the generator's ``if`` filters keep the item just bound."""
        raise NotImplementedError

    def comprehension(self, generators: list[ast.comprehension], env: Any,
                      emit: Callable[[Any], None]) -> None:
        """Run ``emit(scope)`` for each combination of the generators' items that the
        filters keep; each item is one step."""
        def loop(index: int, scope: Any) -> None:
            if index == len(generators):
                emit(scope)
                return
            gen = generators[index]
            for item in self.iterate(gen, scope):
                self.step()
                self.let(gen.target, item, scope)
                if self.keep(gen, scope):
                    loop(index + 1, scope)

        scope = self.enter(env)
        try:
            loop(0, scope)
        finally:
            self.leave(scope)


class _Interpreter(Walker):
    def __init__(self, names: Callable[[str], object] | None, functions: Mapping[str, Any],
                 limits: Limits, mutate: bool = False,
                 aliases: Mapping[str, str] | None = None, lenient: bool = False) -> None:
        self.names = names
        self.lenient = lenient
        self.functions = functions
        self.limits = limits
        self.mutate = mutate
        self.aliases = aliases if aliases is not None else {}
        self.steps = 0
        self.scopes: list[dict[str, object]] = []
        self.limited: tuple[Unknown, ast.AST] | None = None

    # -- this configuration: an operand not known stops the expression ------------------
    past_unknown = True

    def over(self, reason: str) -> NoReturn:
        raise _Stop(Unknown(reason, "limit"))

    def unhandled(self, node: ast.AST, env: Any = None) -> Any:
        raise _Stop(Unknown(f"{type(node).__name__} is not supported", "unsupported"))

    def opaque(self, value: object) -> bool:
        return isinstance(value, (Unknown, _Function))

    def not_known(self, node: ast.AST, what: str, values: Iterable[object]) -> Any:
        self.known(*values)
        raise _Stop(Unknown("slice indices must be integers or None", "error"))

    def refused(self, err: Refused, node: ast.AST, what: str) -> Any:
        return self.guard(lambda: _raise(err))

    # -- leaves ------------------------------------------------------------------------
    def eval_Expression(self, node: ast.Expression, env: Any = None) -> Any:
        return self.eval(node.body)

    def eval_Constant(self, node: ast.Constant, env: Any = None) -> Any:
        if node.value is Ellipsis:
            raise _Stop(Unknown("... is not supported", "unsupported"))
        return node.value

    def eval_Name(self, node: ast.Name, env: Any = None) -> Any:
        if "__" in node.id:
            raise _Stop(Unknown(f"name '{node.id}' is forbidden", "unsupported"))
        for scope in reversed(self.scopes):
            if node.id in scope:
                return scope[node.id]
        return self.named(node.id)

    def named(self, name: str) -> Any:
        """A caller's function or value, by name or dotted name (imports applied)."""
        head, dot, rest = name.partition(".")
        qualified = self.aliases.get(head, head) + dot + rest
        for key in (name, qualified):
            if key in self.functions:
                found = self.functions[key]
                return _Function(key, found) if callable(found) else found
        if self.names is None:
            raise _Stop(_undefined(name))
        try:
            return self.names(name)
        except KeyError:
            raise _Stop(_undefined(name)) from None

    def eval_Attribute(self, node: ast.Attribute, env: Any = None) -> Any:
        """A dotted name of the caller's table (``math.pi``), or a key of a
        ``KeyAttributes`` mapping read as an attribute; no other attribute."""
        dotted = _dotted(node)
        unsupported = _Stop(Unknown(f"attribute '{node.attr}' is not supported",
                                    "unsupported"))
        if node.attr.startswith("_"):
            raise unsupported
        if self.is_function(dotted):
            return self.named(str(dotted))
        try:
            owner = self.eval(node.value)
        except _Stop:
            raise unsupported from None
        if isinstance(owner, KeyAttributes) and not hasattr(dict, node.attr):
            if node.attr in owner:
                return owner[node.attr]
            raise _Stop(Unknown(f"no such key: '{node.attr}'", "error"))
        if isinstance(owner, Unknown):
            raise _Stop(owner)  # what it would be read from is not known
        raise unsupported

    # -- containers ----------------------------------------------------------------------
    def item(self, node: ast.AST) -> Any:
        """An item of a list or tuple literal: with ``lenient``, one that cannot be known is
        an ``Unknown`` item and the rest of the literal stays known."""
        if not self.lenient:
            return self.eval(node)
        try:
            return self.eval(node)
        except _Stop as stop:
            if stop.unknown.kind == "limit":
                raise
            return stop.unknown

    def eval_List(self, node: ast.List, env: Any = None) -> Any:
        return [self.item(e) for e in node.elts]

    def eval_Tuple(self, node: ast.Tuple, env: Any = None) -> Any:
        return tuple(self.item(e) for e in node.elts)

    def eval_Set(self, node: ast.Set, env: Any = None) -> Any:
        items = [self.eval(e) for e in node.elts]
        self.known(*items)
        self.step(ops.walk_cost(items, self.limits))  # each item hashed
        return self.guard(lambda: set(items))

    def eval_Dict(self, node: ast.Dict, env: Any = None) -> Any:
        if any(k is None for k in node.keys):
            raise _Stop(Unknown("** in a dict literal is not supported", "unsupported"))
        keys = [self.eval(k) for k in node.keys if k is not None]
        values = [self.eval(v) for v in node.values]
        self.known(*keys)
        self.step(ops.walk_cost(keys, self.limits))  # each key hashed
        return self.guard(lambda: dict(zip(keys, values, strict=True)))

    def eval_JoinedStr(self, node: ast.JoinedStr, env: Any = None) -> Any:
        pieces = [self.eval(v) for v in node.values]
        self.known(*pieces)
        budget_length = sum(len(str(p)) for p in pieces)
        if budget_length > self.limits.length:
            raise _Stop(Unknown(f"result longer than {self.limits.length}", "limit"))
        return "".join(str(p) for p in pieces)

    def eval_FormattedValue(self, node: ast.FormattedValue, env: Any = None) -> Any:
        value = self.eval(node.value)
        spec = self.eval(node.format_spec) if node.format_spec is not None else ""
        self.known(value, spec)
        return self.guard(lambda: ops.format_value(value, spec, node.conversion, self.limits))

    # -- operators -----------------------------------------------------------------------
    def eval_BinOp(self, node: ast.BinOp, env: Any = None) -> Any:
        left, right = self.eval(node.left), self.eval(node.right)
        self.known(left, right)
        return self.made(self.guard(
            lambda: ops.binary(type(node.op), left, right, self.limits)))

    def undecided(self, node: ast.IfExp, test: object, env: Any) -> Any:
        """Both branches: their value when they agree, else the test's unknown."""
        if not isinstance(test, Unknown):
            self.known(test)
        body, orelse = self.eval(node.body), self.eval(node.orelse)
        self.step(ops.compare_cost(body, orelse, self.limits))
        same = not isinstance(body, Unknown) and type(body) is type(orelse) \
            and self.guard(lambda: body == orelse)
        return body if same else test

    def eval_Subscript(self, node: ast.Subscript, env: Any = None) -> Any:
        value = self.eval(node.value)
        index = self.eval(node.slice)
        self.known(value, index)
        self.step(ops.walk_cost(index, self.limits))  # a key is hashed
        return self.made(self.guard(lambda: ops.subscript(value, index)))

    # -- calls -----------------------------------------------------------------------------
    def eval_Call(self, node: ast.Call, env: Any = None) -> Any:
        if any(isinstance(a, ast.Starred) for a in node.args):
            raise _Stop(Unknown("*arguments are not supported", "unsupported"))
        if any(k.arg is None for k in node.keywords):
            raise _Stop(Unknown("**keywords are not supported", "unsupported"))
        dotted = _dotted(node.func)
        if isinstance(node.func, ast.Attribute) and not self.is_function(dotted):
            return self.method(node)
        if dotted is not None and not self.is_function(dotted) \
                and not any(dotted in scope for scope in self.scopes):
            raise _Stop(Unknown(f"'{dotted}' is not a known function", "unsupported"))
        target = self.eval(node.func)
        if not isinstance(target, _Function):
            if isinstance(target, Unknown):
                return target
            raise _Stop(Unknown(f"'{dotted or 'this'}' is not a known function",
                                "unsupported"))
        args = [self.eval(a) for a in node.args]
        kwargs = {str(k.arg): self.eval(k.value) for k in node.keywords}
        self.known(*args, *kwargs.values())
        for arg in (*args, *kwargs.values()):  # what the function may walk
            self.step(ops.walk_cost(arg, self.limits))
        return self.made(self.guard(
            lambda: ops.call_builtin(target.call, args, kwargs, self.limits)))

    def made(self, value: Any) -> Any:
        """Charge a value just made by its size (items, or characters / 64)."""
        self.step(ops.make_cost(value))
        return value

    def is_function(self, dotted: str | None) -> bool:
        if dotted is None or "__" in dotted:
            return False
        head, dot, rest = dotted.partition(".")
        return dotted in self.functions or (self.aliases.get(head, head) + dot + rest) \
            in self.functions

    def method(self, node: ast.Call) -> object:
        func = node.func
        assert isinstance(func, ast.Attribute)
        if func.attr.startswith("_"):
            raise _Stop(Unknown(f"attribute '{func.attr}' is forbidden", "unsupported"))
        owner = self.eval(func.value)
        args = [self.eval(a) for a in node.args]
        kwargs = {str(k.arg): self.eval(k.value) for k in node.keywords}
        self.known(owner, *args, *kwargs.values())
        self.step(ops.method_cost(owner, args, self.limits))
        return self.made(self.guard(lambda: ops.call_method(
            owner, func.attr, args, kwargs, self.limits, self.mutate)))

    # -- comprehensions --------------------------------------------------------------------
    def enter(self, env: Any) -> Any:
        self.scopes.append({})
        return env

    def leave(self, scope: Any) -> None:
        self.scopes.pop()

    def iterate(self, gen: ast.comprehension, env: Any) -> list[Any]:
        if gen.is_async:
            raise _Stop(Unknown("async comprehensions are not supported", "unsupported"))
        iterable = self.eval(gen.iter)
        self.known(iterable)
        if not isinstance(iterable, (str, list, tuple, dict, set, frozenset)):
            raise _Stop(Unknown(f"cannot iterate over {type(iterable).__name__}",
                                "unsupported"))
        return list(iterable)

    def keep(self, gen: ast.comprehension, env: Any) -> bool:
        return all(self.known_truth(self.eval(cond)) for cond in gen.ifs)

    def let(self, target: ast.AST, item: object, env: Any = None) -> None:
        if isinstance(target, ast.Name):
            if "__" in target.id:
                raise _Stop(Unknown(f"name '{target.id}' is forbidden", "unsupported"))
            self.scopes[-1][target.id] = item
        elif isinstance(target, (ast.Tuple, ast.List)) and isinstance(item, (tuple, list)) \
                and len(item) == len(target.elts):
            for sub, value in zip(target.elts, item, strict=True):
                self.let(sub, value)
        else:
            raise _Stop(Unknown("unsupported comprehension target", "unsupported"))

    def known_truth(self, value: object) -> bool:
        self.known(value)
        return bool(value)

    def eval_ListComp(self, node: ast.ListComp | ast.GeneratorExp | ast.SetComp,
                      env: Any = None) -> Any:
        out: list[object] = []
        self.comprehension(node.generators, None,
                           lambda _: self.append(out, self.eval(node.elt)))
        return out

    eval_GeneratorExp = eval_ListComp  # a generator passed to a function: a list will do

    def eval_SetComp(self, node: ast.SetComp, env: Any = None) -> Any:
        items = self.eval_ListComp(node)
        self.step(ops.walk_cost(items, self.limits))
        return self.guard(lambda: set(items))

    def eval_DictComp(self, node: ast.DictComp, env: Any = None) -> Any:
        out: list[Any] = []
        self.comprehension(node.generators, None, lambda _: self.append(
            out, (self.eval(node.key), self.eval(node.value))))
        self.known(*(pair[0] for pair in out))
        self.step(ops.walk_cost([pair[0] for pair in out], self.limits))
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
        except Refused as err:
            kind: UnknownKind = "unsupported" if err.kind == "unsupported" else (
                "error" if err.kind == "error" else "limit")
            raise _Stop(Unknown(err.reason, kind)) from None
        except (ArithmeticError, TypeError, ValueError, LookupError, AttributeError) as err:
            raise _Stop(Unknown(ops.error_text(err), "error")) from None

    def run(self, node: ast.AST) -> object:
        """``node``'s value, or the ``Unknown`` that stopped it (the first bound reached is
        kept in ``limited``, with the expression that reached it)."""
        try:
            result = self.eval(node)
            self.known(result)
            return result
        except _Stop as stop:
            if stop.unknown.kind == "limit" and self.limited is None:
                self.limited = (stop.unknown, node)
            return stop.unknown
        except RecursionError:
            return Unknown("expression too deeply nested", "limit")


def _raise(err: Exception) -> NoReturn:
    raise err


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


DUNDER_REFUSED = "may not contain double underscore expressions"


def evaluate(text: str, names: Callable[[str], object] | None = None,
             functions: Mapping[str, Any] | None = None,
             limits: Limits | None = None, *, dunder: bool = True) -> object:
    """Evaluate the Python expression ``text`` safely; an ``Unknown`` when it cannot be.

    ``functions`` defaults to ``BUILTINS``; pass ``{**BUILTINS, **MATH, ...}`` to add
    more. ``dunder=False`` refuses ``__`` anywhere in the text, as roslaunch does. Never
    raises for bad input and never runs code from ``text``.
    """
    limits = limits or Limits()
    if len(text) > limits.text:
        return Unknown(f"expression longer than {limits.text} characters", "limit")
    if not dunder and "__" in text:
        return Unknown(DUNDER_REFUSED, "unsupported")
    try:
        tree = syntax.parse(text.strip(), mode="eval")
    except SyntaxError as err:
        return Unknown(f"not a Python expression: {err.msg}", "syntax")
    except ValueError as err:  # a NUL character
        return Unknown(f"not a Python expression: {str(err)[:100]}", "syntax")
    except (RecursionError, MemoryError):
        return Unknown("expression too deeply nested", "limit")
    return evaluate_node(tree, names, functions, limits)


def evaluate_node(node: ast.AST, names: Callable[[str], object] | None = None,
                  functions: Mapping[str, Any] | None = None,
                  limits: Limits | None = None) -> object:
    """``evaluate`` for an expression already parsed (a part of a file read with ``ast``)."""
    return evaluate_counted(node, names, functions, limits)[0]


def evaluate_counted(node: ast.AST, names: Callable[[str], object] | None = None,
                     functions: Mapping[str, Any] | None = None,
                     limits: Limits | None = None) -> tuple[object, int]:
    """``evaluate_node``, and the steps it took (for a reader whose own budget pays them)."""
    limits = limits or Limits()
    refused = _shape_ok(node, limits)
    if refused is not None:
        return refused, 1
    interpreter = _Interpreter(names, BUILTINS if functions is None else functions, limits)
    return interpreter.run(node), interpreter.steps


def names_from(mapping: Mapping[str, object]) -> Callable[[str], object]:
    """A ``names`` callback over a mapping (``KeyError`` for names not in it)."""
    return mapping.__getitem__


def unknown_reasons(values: Iterable[object]) -> list[str]:
    return [v.reason for v in values if isinstance(v, Unknown)]
