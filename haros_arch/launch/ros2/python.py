"""Python launch files, interpreted statically over ``ast``: never imported nor run.

``parse_python`` reads the module's imports, constants and functions, then interprets
``generate_launch_description()`` with a small interpreter: assignments, calls to the
launch / launch_ros API (``python_api.API``), list / dict literals, comprehensions and
``for`` loops over known values, ``if`` (both branches, conditional, when the test is
unknown), helper functions of the same file, f-strings, ``%``, ``format`` and ``+``,
``os.path`` helpers. Anything else gives an unknown value and a
``LAUNCH_PY_UNSUPPORTED`` diagnostic; nothing outside the file is called. Work is
bounded: source size, AST size and depth, evaluation steps, call depth, value sizes.

Strings that hold substitutions or unknown parts are ``Lazy`` (a ``Text``); the runner
computes them where the action runs. ``OpaqueFunction`` bodies run when the runner
reaches them, with ``context`` standing for the launch context of that moment.
"""

from __future__ import annotations

import ast
import operator
import os
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ... import diagnostics as diag
from ...diagnostics import Diagnostic
from ...model.location import Location
from ...workspace import Workspace
from . import entities as e

MAX_SOURCE = 512 * 1024
MAX_NODES = 100_000
MAX_DEPTH = 100
MAX_STEPS = 200_000
MAX_CALL_DEPTH = 40
MAX_SIZE = 100_000  # items of a container or characters of a string
MAX_READ = 1024 * 1024  # bytes of a file read by open() / yaml.safe_load


class Budget(Exception):
    """A bound was reached: interpretation stops."""


class Unsupported(Exception):
    """A construct outside the subset, where a value cannot stand for it."""


class _Flow(Exception):
    """return / break / continue, as control flow of the interpreted code."""


class _Return(_Flow):
    def __init__(self, value: Any) -> None:
        self.value = value


class _Break(_Flow):
    pass


class _Continue(_Flow):
    pass


@dataclass(frozen=True)
class Unk:
    """A value we do not know; ``why`` says what it came from."""

    why: str


@dataclass(frozen=True)
class Lazy:
    """A string with substitutions or unknown parts, computed when the action runs."""

    text: e.Text


@dataclass(frozen=True)
class Ref:
    """A module or a name imported from one: ``launch_ros.actions.Node``."""

    qualified: str


@dataclass
class Func:
    node: ast.FunctionDef | ast.Lambda
    closure: dict[str, Any]


@dataclass(frozen=True)
class ReadOnlyFile:
    """What ``open(path)`` gives: only ``read()`` and ``yaml.safe_load`` use it."""

    path: str


@dataclass
class LaunchDescription:
    actions: list[Any] = field(default_factory=list)


@dataclass(frozen=True)
class Context:
    """The ``context`` an ``OpaqueFunction`` receives: reads the runner's scope."""

    perform: Callable[[e.Text], Any]


class Interpreter:
    def __init__(self, path: str, workspace: Workspace, environment: dict[str, str]) -> None:
        self.path = path
        self.workspace = workspace
        self.environment = environment
        self.diagnostics: list[Diagnostic] = []
        self.globals: dict[str, Any] = {}
        self.steps = 0
        self.depth = 0
        self.guards: list[str] = []  # texts of unknown Python `if` tests we are under
        from .python_api import API, BUILTINS, METHODS

        self.api = API
        self.builtins = BUILTINS
        self.methods = METHODS

    # -- diagnostics -------------------------------------------------------------------
    def where(self, node: ast.AST | None) -> Location:
        line = getattr(node, "lineno", 0) or 0
        col = getattr(node, "col_offset", -1) + 1
        return self.workspace.location(self.path, line, col)

    def unsupported(self, node: ast.AST | None, detail: str) -> Unk:
        found = diag.make("LAUNCH_PY_UNSUPPORTED", self.where(node), detail=detail)
        if found not in self.diagnostics:
            self.diagnostics.append(found)
        return Unk(detail)

    def tick(self) -> None:
        self.steps += 1
        if self.steps > MAX_STEPS:
            raise Budget(f"more than {MAX_STEPS} evaluation steps")

    def sized(self, value: Any) -> Any:
        if isinstance(value, (str, list, tuple, dict)) and len(value) > MAX_SIZE:
            raise Budget(f"a value with more than {MAX_SIZE} items or characters")
        return value

    # -- module ------------------------------------------------------------------------
    def module(self, tree: ast.Module) -> list[e.Action] | None:
        for stmt in tree.body:
            if isinstance(stmt, (ast.Import, ast.ImportFrom)):
                self.import_(stmt, self.globals)
            elif isinstance(stmt, ast.FunctionDef):
                self.globals[stmt.name] = Func(stmt, self.globals)
            elif isinstance(stmt, (ast.Assign, ast.AnnAssign)):
                self.statement(stmt, self.globals)
            elif isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Constant):
                continue  # docstring
            elif isinstance(stmt, ast.If) and "__name__" in ast.dump(stmt.test):
                continue  # if __name__ == '__main__': never run
            else:
                self.unsupported(stmt, f"module-level {type(stmt).__name__} is not "
                                       "interpreted (never run)")
        entry = self.globals.get("generate_launch_description")
        if not isinstance(entry, Func):
            self.diagnostics.append(diag.make(
                "LAUNCH_PY_UNSUPPORTED", self.where(None),
                detail="no generate_launch_description() function"))
            return None
        result = self.call(entry, [], {}, entry.node)
        return self.actions_of(result, entry.node)

    def actions_of(self, value: Any, node: ast.AST) -> list[e.Action]:
        """The actions in a LaunchDescription, a list of actions, or one action."""
        if isinstance(value, LaunchDescription):
            value = value.actions
        if isinstance(value, e.Action):
            return [value]
        if not isinstance(value, (list, tuple)):
            self.unsupported(node, "launch description is not known statically")
            return []
        out: list[e.Action] = []
        for item in value:
            if isinstance(item, (LaunchDescription, list, tuple)):
                out.extend(self.actions_of(item, node))
            elif isinstance(item, e.Action):
                out.append(item)
            elif item is not None and not isinstance(item, Unk):
                self.unsupported(node, f"{type(item).__name__} is not a launch action")
        return out

    def import_(self, stmt: ast.Import | ast.ImportFrom, env: dict[str, Any]) -> None:
        if isinstance(stmt, ast.Import):
            for alias in stmt.names:
                if alias.asname:
                    env[alias.asname] = Ref(alias.name)
                else:
                    top = alias.name.split(".")[0]
                    env[top] = Ref(top)
            return
        module = ("." * stmt.level) + (stmt.module or "")
        for alias in stmt.names:
            env[alias.asname or alias.name] = Ref(f"{module}.{alias.name}")

    # -- statements --------------------------------------------------------------------
    def block(self, body: list[ast.stmt], env: dict[str, Any]) -> None:
        for stmt in body:
            self.statement(stmt, env)

    def statement(self, stmt: ast.stmt, env: dict[str, Any]) -> None:
        self.tick()
        if isinstance(stmt, ast.Assign):
            value = self.eval(stmt.value, env)
            for target in stmt.targets:
                self.assign(target, value, env)
        elif isinstance(stmt, ast.AnnAssign):
            if stmt.value is not None:
                self.assign(stmt.target, self.eval(stmt.value, env), env)
        elif isinstance(stmt, ast.AugAssign):
            current = self.eval(_load(stmt.target), env)
            value = self.binop(stmt.op, current, self.eval(stmt.value, env), stmt)
            if isinstance(current, list) and isinstance(stmt.op, ast.Add) and isinstance(
                    value, list):
                current[:] = value  # += on a list extends it in place
            self.assign(stmt.target, value, env)
        elif isinstance(stmt, ast.Expr):
            self.eval(stmt.value, env)
        elif isinstance(stmt, ast.Return):
            raise _Return(None if stmt.value is None else self.eval(stmt.value, env))
        elif isinstance(stmt, ast.If):
            self.if_(stmt, env)
        elif isinstance(stmt, ast.For):
            self.for_(stmt, env)
        elif isinstance(stmt, ast.FunctionDef):
            env[stmt.name] = Func(stmt, env)
        elif isinstance(stmt, (ast.Import, ast.ImportFrom)):
            self.import_(stmt, env)
        elif isinstance(stmt, ast.Try):
            self.block(stmt.body, env)
            self.block(stmt.orelse, env)
            self.block(stmt.finalbody, env)
        elif isinstance(stmt, ast.Pass):
            pass
        elif isinstance(stmt, ast.Break):
            raise _Break()
        elif isinstance(stmt, ast.Continue):
            raise _Continue()
        elif isinstance(stmt, ast.With):
            self.with_(stmt, env)
        elif isinstance(stmt, ast.While):
            self.unsupported(stmt, "while loops are not interpreted (never run)")
        else:
            self.unsupported(stmt, f"{type(stmt).__name__} statements are not interpreted")

    def assign(self, target: ast.expr, value: Any, env: dict[str, Any]) -> None:
        if isinstance(target, ast.Name):
            env[target.id] = value
        elif isinstance(target, (ast.Tuple, ast.List)):
            items = list(value) if isinstance(value, (list, tuple)) else None
            if items is None or len(items) != len(target.elts):
                items = [Unk("unpacking")] * len(target.elts)
            for sub, item in zip(target.elts, items, strict=False):
                self.assign(sub, item, env)
        elif isinstance(target, ast.Subscript):
            container = self.eval(target.value, env)
            key = self.eval(target.slice, env)
            if isinstance(container, dict) and not isinstance(key, (Unk, list, dict)):
                container[key] = value
                self.sized(container)
            elif isinstance(container, list) and isinstance(key, int) and (
                    -len(container) <= key < len(container)):
                container[key] = value
        else:
            self.unsupported(target, "assignment to this target is not interpreted")

    def if_(self, stmt: ast.If, env: dict[str, Any]) -> None:
        test = self.truth(self.eval(stmt.test, env))
        if test is True:
            self.block(stmt.body, env)
        elif test is False:
            self.block(stmt.orelse, env)
        else:
            text = _source(stmt.test)
            self.guards.append(text)
            try:
                self.block(stmt.body, env)
            finally:
                self.guards.pop()
            self.guards.append(f"not ({text})")
            try:
                self.block(stmt.orelse, env)
            finally:
                self.guards.pop()

    def with_(self, stmt: ast.With, env: dict[str, Any]) -> None:
        """``with open(path) as f:``: a read-only handle on a file we may read."""
        for item in stmt.items:
            value = self.eval(item.context_expr, env)
            if not isinstance(value, ReadOnlyFile):
                self.unsupported(stmt, "with statements other than open() are not "
                                       "interpreted")
                return
            if item.optional_vars is not None:
                self.assign(item.optional_vars, value, env)
        self.block(stmt.body, env)

    def read(self, path: Any, node: ast.AST) -> str | None:
        """The text of a file of the workspace or an installed package (bounded)."""
        from ...files import read_text
        from ...workspace import installed_roots

        if not isinstance(path, str):
            self.unsupported(node, "a file whose path is not known statically")
            return None
        full = os.path.realpath(path)
        roots = [os.path.realpath(r) for r in [*(self.workspace.roots or
                                                 [self.workspace.root]),
                                               *installed_roots(self.environment)]]
        if not any(full.startswith(root + os.sep) for root in roots):
            self.unsupported(node, f"{path} is outside the workspace; not read")
            return None
        text, found = read_text(full, self.workspace.location(full), MAX_READ)
        self.diagnostics.extend(found)
        return text

    def for_(self, stmt: ast.For, env: dict[str, Any]) -> None:
        items = self.iterable(self.eval(stmt.iter, env), stmt.iter)
        if items is None:
            return
        for item in items:
            self.tick()
            self.assign(stmt.target, item, env)
            try:
                self.block(stmt.body, env)
            except _Break:
                return
            except _Continue:
                continue
        self.block(stmt.orelse, env)

    def iterable(self, value: Any, node: ast.AST) -> list[Any] | None:
        if isinstance(value, dict):
            return list(value)
        if isinstance(value, (list, tuple, str)):
            return list(value)
        self.unsupported(node, "loop over a value that is not known statically")
        return None

    # -- functions -----------------------------------------------------------------------
    def call(self, func: Any, args: list[Any], kwargs: dict[str, Any], node: ast.AST) -> Any:
        if isinstance(func, Func):
            return self.call_function(func, args, kwargs, node)
        if isinstance(func, Ref):
            name = func.qualified
            short = name.rsplit(".", 1)[-1]
            handler = self.api.get(short)
            if handler is not None and (_known_module(name) or short in self.builtins):
                return handler(self, args, kwargs, node)
            return self.unsupported(node, f"call to {name} is not interpreted (never run)")
        if isinstance(func, _Bound):
            return func.call(self, args, kwargs, node)
        return self.unsupported(node, "call to a value that is not known statically")

    def call_function(self, func: Func, args: list[Any], kwargs: dict[str, Any],
                      node: ast.AST) -> Any:
        self.depth += 1
        if self.depth > MAX_CALL_DEPTH:
            self.depth = 0
            raise Budget(f"calls nested deeper than {MAX_CALL_DEPTH}")
        try:
            env = dict(func.closure) if isinstance(func.node, ast.Lambda) else {}
            env["__closure__"] = func.closure
            params = func.node.args
            positional = [a.arg for a in params.posonlyargs + params.args]
            defaults = params.defaults
            for index, name in enumerate(positional):
                if index < len(args):
                    env[name] = args[index]
                elif name in kwargs:
                    env[name] = kwargs[name]
                else:
                    back = index - (len(positional) - len(defaults))
                    env[name] = (self.eval(defaults[back], func.closure) if back >= 0
                                 else Unk(f"argument {name}"))
            for arg, default in zip(params.kwonlyargs, params.kw_defaults, strict=False):
                env[arg.arg] = kwargs.get(arg.arg, Unk(arg.arg) if default is None
                                          else self.eval(default, func.closure))
            if params.vararg:
                env[params.vararg.arg] = list(args[len(positional):])
            if params.kwarg:
                env[params.kwarg.arg] = {k: v for k, v in kwargs.items()
                                         if k not in positional}
            if isinstance(func.node, ast.Lambda):
                return self.eval(func.node.body, env)
            try:
                self.block(func.node.body, env)
            except _Return as ret:
                return ret.value
            return None
        finally:
            self.depth = max(self.depth - 1, 0)

    # -- expressions ---------------------------------------------------------------------
    def lookup(self, name: str, env: dict[str, Any], node: ast.AST) -> Any:
        scope: dict[str, Any] | None = env
        while scope is not None:
            if name in scope:
                return scope[name]
            scope = scope.get("__closure__")
        if name in self.globals:
            return self.globals[name]
        if name in self.builtins:
            return Ref(name)
        if name in ("True", "False", "None"):
            return {"True": True, "False": False, "None": None}[name]
        return self.unsupported(node, f"name {name} is not defined here")

    def eval(self, node: ast.expr, env: dict[str, Any]) -> Any:
        self.tick()
        handler = getattr(self, "e_" + type(node).__name__, None)
        if handler is None:
            return self.unsupported(node, f"{type(node).__name__} is not interpreted")
        return self.sized(handler(node, env))

    def e_Constant(self, node: ast.Constant, env: dict[str, Any]) -> Any:
        return node.value

    def e_Name(self, node: ast.Name, env: dict[str, Any]) -> Any:
        return self.lookup(node.id, env, node)

    def e_List(self, node: ast.List | ast.Tuple | ast.Set, env: dict[str, Any]) -> Any:
        out: list[Any] = []
        for elt in node.elts:
            if isinstance(elt, ast.Starred):
                items = self.iterable(self.eval(elt.value, env), elt)
                out.extend(items or [])
            else:
                out.append(self.eval(elt, env))
            self.sized(out)
        return tuple(out) if isinstance(node, ast.Tuple) else out

    e_Tuple = e_List
    e_Set = e_List

    def e_Dict(self, node: ast.Dict, env: dict[str, Any]) -> Any:
        out: dict[Any, Any] = {}
        for key, value in zip(node.keys, node.values, strict=False):
            if key is None:
                merged = self.eval(value, env)
                if isinstance(merged, dict):
                    out.update(merged)
                continue
            k = self.eval(key, env)
            out[_hashable(k)] = self.eval(value, env)
        return out

    def e_JoinedStr(self, node: ast.JoinedStr, env: dict[str, Any]) -> Any:
        parts: list[Any] = []
        for value in node.values:
            if isinstance(value, ast.FormattedValue):
                parts.append(self.eval(value.value, env))
            else:
                parts.append(self.eval(value, env))
        return concat(parts)

    def e_BinOp(self, node: ast.BinOp, env: dict[str, Any]) -> Any:
        return self.binop(node.op, self.eval(node.left, env), self.eval(node.right, env), node)

    def binop(self, op: ast.operator, left: Any, right: Any, node: ast.AST) -> Any:
        if isinstance(op, ast.Add) and (is_stringy(left) or is_stringy(right)) and not (
                isinstance(left, list) or isinstance(right, list)):
            return concat([left, right])
        if isinstance(left, Unk) or isinstance(right, Unk):
            return Unk("arithmetic on an unknown value")
        if isinstance(op, ast.Mult):
            count = right if isinstance(right, int) else left if isinstance(left, int) else 0
            other = left if isinstance(right, int) else right
            if isinstance(other, (str, list, tuple)) and len(other) * max(count, 0) > MAX_SIZE:
                raise Budget(f"a value with more than {MAX_SIZE} items or characters")
        if isinstance(op, ast.Pow) and isinstance(right, (int, float)) and abs(right) > 256:
            raise Budget("an exponent above 256")
        if isinstance(op, ast.LShift) and isinstance(right, int) and right > 256:
            raise Budget("a shift above 256 bits")
        if isinstance(op, ast.Mod) and isinstance(left, str) and (
                isinstance(right, (Lazy, e.Subst)) or (
                    isinstance(right, tuple) and any(is_lazy(x) for x in right))):
            return self.unsupported(node, "%-formatting with substitutions")
        function = _BINARY.get(type(op))
        known = (str, int, float, bool, list, tuple, type(None))
        if function is None or not isinstance(left, known) or not isinstance(right, known):
            return self.unsupported(node, "operation on values not known statically")
        try:
            return function(left, right)
        except (TypeError, ValueError, ZeroDivisionError, OverflowError, IndexError) as err:
            return self.unsupported(node, f"operation fails: {err}")

    def e_UnaryOp(self, node: ast.UnaryOp, env: dict[str, Any]) -> Any:
        value = self.eval(node.operand, env)
        if isinstance(node.op, ast.Not):
            truth = self.truth(value)
            return Unk("not of an unknown value") if truth is None else not truth
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return -value if isinstance(node.op, ast.USub) else value
        return Unk("unary operation")

    def e_BoolOp(self, node: ast.BoolOp, env: dict[str, Any]) -> Any:
        is_and = isinstance(node.op, ast.And)
        result: Any = None
        for operand in node.values:
            result = self.eval(operand, env)
            truth = self.truth(result)
            if truth is None:
                return Unk("boolean of an unknown value")
            if truth != is_and:
                return result
        return result

    def e_Compare(self, node: ast.Compare, env: dict[str, Any]) -> Any:
        left = self.eval(node.left, env)
        for op, comparator in zip(node.ops, node.comparators, strict=False):
            right = self.eval(comparator, env)
            if _opaque(left) or _opaque(right):
                return Unk(f"comparison {_source(node)}")
            function = _COMPARE.get(type(op))
            if function is None:
                return Unk("comparison")
            try:
                if not function(left, right):
                    return False
            except TypeError:
                return Unk("comparison")
            left = right
        return True

    def e_IfExp(self, node: ast.IfExp, env: dict[str, Any]) -> Any:
        truth = self.truth(self.eval(node.test, env))
        if truth is None:
            return Unk(f"conditional expression {_source(node.test)}")
        return self.eval(node.body if truth else node.orelse, env)

    def e_Subscript(self, node: ast.Subscript, env: dict[str, Any]) -> Any:
        value = self.eval(node.value, env)
        key = self.eval(node.slice, env)
        if isinstance(value, _Environ):
            return value.get(self, [key], node)
        if isinstance(value, Context) and isinstance(node.value, ast.Attribute):
            return value.perform((e.Var(_text_of(key)),))
        if isinstance(key, slice) or isinstance(value, (dict, list, tuple, str)):
            try:
                return value[_hashable(key)]
            except (KeyError, IndexError, TypeError):
                return self.unsupported(node, f"{_source(node)} is not known statically")
        return Unk("subscript")

    def e_Slice(self, node: ast.Slice, env: dict[str, Any]) -> Any:
        parts = [None if p is None else self.eval(p, env)
                 for p in (node.lower, node.upper, node.step)]
        if any(p is not None and not isinstance(p, int) for p in parts):
            return Unk("slice")
        return slice(*parts)

    def e_Attribute(self, node: ast.Attribute, env: dict[str, Any]) -> Any:
        owner = self.eval(node.value, env)
        if isinstance(owner, Ref):
            if owner.qualified == "os" and node.attr == "environ":
                return _Environ()
            return Ref(f"{owner.qualified}.{node.attr}")
        if isinstance(owner, Context) and node.attr == "launch_configurations":
            return owner
        return _Bound(owner, node.attr)

    def e_Call(self, node: ast.Call, env: dict[str, Any]) -> Any:
        func = self.eval(node.func, env)
        args: list[Any] = []
        for arg in node.args:
            if isinstance(arg, ast.Starred):
                args.extend(self.iterable(self.eval(arg.value, env), arg) or [])
            else:
                args.append(self.eval(arg, env))
        kwargs: dict[str, Any] = {}
        for keyword in node.keywords:
            value = self.eval(keyword.value, env)
            if keyword.arg is None:
                if isinstance(value, dict):
                    kwargs.update({str(k): v for k, v in value.items()})
            else:
                kwargs[keyword.arg] = value
        result = self.call(func, args, kwargs, node)
        if self.guards and isinstance(result, e.Action):
            result = self.guarded(result, node)
        return result

    def guarded(self, action: e.Action, node: ast.AST) -> e.Action:
        """An action made under a Python ``if`` whose test is unknown: conditional."""
        text = " and ".join(self.guards)
        cond = e.Cond((e.Opaque(f"Python test {text}"),), source=text)
        if action.condition is None:
            action.condition = cond
            return action
        return e.Group([action], scoped=False, condition=cond, location=action.location)

    def e_Lambda(self, node: ast.Lambda, env: dict[str, Any]) -> Any:
        return Func(node, env)

    def e_ListComp(self, node: ast.ListComp | ast.GeneratorExp | ast.SetComp,
                   env: dict[str, Any]) -> Any:
        out: list[Any] = []
        self.comprehension(node.generators, 0, dict(env, __closure__=env),
                           lambda scope: out.append(self.eval(node.elt, scope)))
        return out

    e_GeneratorExp = e_ListComp
    e_SetComp = e_ListComp

    def e_DictComp(self, node: ast.DictComp, env: dict[str, Any]) -> Any:
        out: dict[Any, Any] = {}

        def add(scope: dict[str, Any]) -> None:
            out[_hashable(self.eval(node.key, scope))] = self.eval(node.value, scope)

        self.comprehension(node.generators, 0, dict(env, __closure__=env), add)
        return out

    def comprehension(self, generators: list[ast.comprehension], index: int,
                      env: dict[str, Any], emit: Callable[[dict[str, Any]], None]) -> None:
        if index == len(generators):
            emit(env)
            return
        gen = generators[index]
        for item in self.iterable(self.eval(gen.iter, env), gen.iter) or []:
            self.tick()
            self.assign(gen.target, item, env)
            tests = [self.truth(self.eval(cond, env)) for cond in gen.ifs]
            if None in tests:
                self.unsupported(gen, "comprehension filter not known statically")
                continue
            if all(tests):
                self.comprehension(generators, index + 1, env, emit)

    def truth(self, value: Any) -> bool | None:
        if _opaque(value):
            return None
        try:
            return bool(value)
        except Exception:
            return None


@dataclass
class _Bound:
    """``owner.attr`` waiting to be called (a method of a known value)."""

    owner: Any
    attr: str

    def call(self, interp: Interpreter, args: list[Any], kwargs: dict[str, Any],
             node: ast.AST) -> Any:
        handler = interp.methods.get(self.attr)
        if handler is None:
            return interp.unsupported(node, f"method .{self.attr}() is not interpreted")
        return handler(interp, self.owner, args, kwargs, node)


class _Environ:
    """``os.environ``: reads the configuration's environment."""

    def get(self, interp: Interpreter, args: list[Any], node: ast.AST) -> Any:
        name = args[0] if args else None
        if isinstance(name, str) and name in interp.environment:
            return interp.environment[name]
        if len(args) > 1:
            return args[1]
        return Lazy((e.Opaque(f"environment variable {name}"),)) if isinstance(
            name, str) else Unk("environment")


_BINARY: dict[type, Callable[[Any, Any], Any]] = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
    ast.Div: operator.truediv, ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod,
    ast.Pow: operator.pow, ast.LShift: operator.lshift, ast.RShift: operator.rshift,
    ast.BitAnd: operator.and_, ast.BitOr: operator.or_,
}
_COMPARE: dict[type, Callable[[Any, Any], bool]] = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge, ast.In: lambda a, b: a in b,
    ast.NotIn: lambda a, b: a not in b, ast.Is: operator.is_, ast.IsNot: operator.is_not,
}
_KNOWN_ROOTS = ("launch", "launch_ros", "launch_xml", "launch_yaml", "os", "ament_index_python",
                "nav2_common", "builtins", "pathlib", "yaml")


def _known_module(qualified: str) -> bool:
    return qualified.split(".")[0] in _KNOWN_ROOTS


def _source(node: ast.AST) -> str:
    try:
        text = ast.unparse(node)
    except Exception:
        text = "?"
    return text if len(text) <= 200 else text[:197] + "..."


def _load(target: ast.expr) -> ast.expr:
    copy = ast.parse(ast.unparse(target), mode="eval").body
    return ast.copy_location(copy, target)


def _hashable(value: Any) -> Any:
    if isinstance(value, list):
        return tuple(_hashable(v) for v in value)
    if isinstance(value, dict):
        return Unk("dict key")
    return value


def _opaque(value: Any) -> bool:
    return isinstance(value, (Unk, Lazy, e.Subst, e.Cond, e.Action))


def is_lazy(value: Any) -> bool:
    return isinstance(value, (Lazy, e.Subst, Unk))


def is_stringy(value: Any) -> bool:
    return isinstance(value, (str, Lazy, e.Subst, Unk))


def _text_of(value: Any) -> e.Text:
    return to_text(value)


def to_text(value: Any) -> e.Text:
    """A launch text (str / substitution / list of them) as our ``Text``."""
    if isinstance(value, str):
        return (value,)
    if isinstance(value, Lazy):
        return value.text
    if isinstance(value, e.Subst):
        return (value,)
    if isinstance(value, (list, tuple)):
        return e.text(*(to_text(v) for v in value))
    if isinstance(value, bool):
        return (str(value).lower(),)
    if isinstance(value, (int, float)):
        return (str(value),)
    if isinstance(value, Unk):
        return (e.Opaque(value.why),)
    if isinstance(value, e.ParamFile):
        return (e.FileRef(value),)
    return (e.Opaque(f"{type(value).__name__} value"),)


def concat(parts: list[Any]) -> Any:
    """Join strings, substitutions and unknowns: a str when all parts are known."""
    out: list[str | e.Subst] = []
    for part in parts:
        if isinstance(part, (int, float)) and not isinstance(part, bool):
            out.append(str(part))
        elif isinstance(part, (str, Lazy, e.Subst, Unk)):
            out.extend(to_text(part))
        else:
            out.append(e.Opaque(f"{type(part).__name__} in a string"))
    if all(isinstance(p, str) for p in out):
        return "".join(p for p in out if isinstance(p, str))
    return Lazy(tuple(out))


def parse_python(text: str, path: str, workspace: Workspace,
                 environment: dict[str, str] | None = None
                 ) -> tuple[list[e.Action] | None, list[Diagnostic]]:
    """The actions of a Python launch file, and what could not be interpreted."""
    where = workspace.location(path)
    if len(text) > MAX_SOURCE:
        return None, [diag.make("LAUNCH_PY_BUDGET", where,
                                detail=f"file larger than {MAX_SOURCE} characters")]
    try:
        tree = ast.parse(text, filename=path)
    except SyntaxError as err:
        return None, [diag.make("LAUNCH_PY_SYNTAX", workspace.location(
            path, err.lineno or 0, err.offset or 0), detail=err.msg)]
    except (RecursionError, MemoryError, ValueError) as err:
        return None, [diag.make("LAUNCH_PY_SYNTAX", where,
                                detail=f"too deeply nested to parse ({type(err).__name__})")]
    count = 0
    stack: list[tuple[ast.AST, int]] = [(tree, 0)]
    while stack:
        node, depth = stack.pop()
        count += 1
        if count > MAX_NODES or depth > MAX_DEPTH:
            what = f"more than {MAX_NODES} syntax nodes" if count > MAX_NODES else \
                f"nesting deeper than {MAX_DEPTH}"
            return None, [diag.make("LAUNCH_PY_BUDGET", where, detail=what)]
        stack.extend((child, depth + 1) for child in ast.iter_child_nodes(node))
    interp = Interpreter(path, workspace, dict(environment or workspace.environment))
    try:
        actions = interp.module(tree)
    except Budget as stop:
        interp.diagnostics.append(diag.make("LAUNCH_PY_BUDGET", where, detail=str(stop)))
        actions = None
    except (RecursionError, _Flow):
        interp.diagnostics.append(diag.make("LAUNCH_PY_BUDGET", where,
                                            detail="interpretation nested too deeply"))
        actions = None
    return actions, interp.diagnostics

