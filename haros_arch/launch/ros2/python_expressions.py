"""Expressions of the static Python interpreter: a configuration of the one evaluator's
walk (``evaluate.python.Walker``).

The walk is the evaluator's: dispatch on the node's kind (``eval_Call``, ``eval_BinOp``,
...), one step per node against the file's budget, each value size-checked, and Python's
rules for comparisons, unary operators, slices, conditional expressions, ``and`` / ``or``
and comprehension loops. What is this reader's: its names and scopes (``env``), the launch
API, and its partial values (substitutions, ``Lazy`` strings, ``Unknown``), which an
operation turns into an unknown that says what (``not_known``); a kind without a handler
gives an unknown value and a diagnostic.
"""

from __future__ import annotations

import ast
import builtins
import dataclasses
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from pathlib import PurePosixPath
from typing import TYPE_CHECKING, Any, NoReturn

from ... import diagnostics as diag
from ...diagnostics import Diagnostic
from ...evaluate import operations as ops
from ...evaluate.python import Walker
from ...model.location import Location
from ...model.values import Unknown
from . import entities as e
from .python_values import (
    LIMITS,
    OUTER,
    Budget,
    Constructing,
    Context,
    DefaultDict,
    EnumMember,
    Func,
    Guard,
    Instance,
    LaunchDescription,
    Lazy,
    Method,
    Module,
    PlainClass,
    Record,
    Ref,
    _hashable,
    _opaque,
    _source,
    _text_of,
    concat,
    conjunction,
    derived,
    derived_unknown,
    is_lazy,
    is_stringy,
    launch_object,
    object_text,
    open_keys,
    printable,
    read_outer,
    said_unknown,
    to_text,
    write_outer,
)

# what ``Expressions.bound`` gives for a name no scope defines
UNBOUND = object()
# the mark of a comprehension's own scope (``Expressions.enter``), which a ``:=`` in it
# does not bind in
COMPREHENSION = "__comprehension__"
# the modules not found that a scope star-imports (``from isaac_ros_launch_utils.all_types
# import *``, of a package not in the workspace): a name not defined there may be one
# of theirs, which the message of its use says
UNFOUND_STARS = "__unfound_stars__"

if TYPE_CHECKING:
    from .python import Interpreter

_PATH_ATTRIBUTES = frozenset(("parent", "name", "stem", "suffix", "parts"))
_NOT_KNOWN = {"not": "not of an unknown value", "unary": "unary operation", "slice": "slice",
              "boolean": "boolean of an unknown value",
              "arithmetic": "arithmetic on an unknown value"}


def _read(value: Any, node: ast.Attribute) -> Any:
    """An attribute's value as an expression reads it: ``camera.namespace`` of a camera
    not known is an unknown that says which."""
    if isinstance(value, _Bound) and isinstance(value.owner, Unknown):
        return Unknown(f"{_source(node)} (an attribute of a value not known statically)")
    return value


def _inside(path: PurePosixPath, folder: str) -> bool:
    """Whether ``path`` is ``folder`` or below it."""
    return str(path) == folder or str(path).startswith(folder.rstrip("/") + "/")


def _above(node: ast.AST, package: str, verb: str = "is a folder") -> str:
    """Why a folder above a workspace package's folder is not known (``path_up``)."""
    return (f"{_source(node)} {verb} above package {package}'s, which stands for its "
            f"install share folder: ros2 launch runs the file from <install>/{package}/"
            f"share/{package} (above it an isolated install's <install>/{package}/share or "
            "a merged one's <install>/share) or, resolve()d in a symlink install, from "
            "the source; which one is not known")


def _fails_for_sure(value: Any, key: Any) -> bool:
    """Whether Python's own error on ``value[key]`` is the program's: a container
    known, a key known, and (a dict) no key of it unknown that could be that one."""
    if not isinstance(value, (dict, list, tuple, str)) or open_keys([_hashable(key)]):
        return False
    return not isinstance(value, dict) or not open_keys(value)



# Python's sign of each binary operator (``binop``'s TypeError of a launch object)
_OPERATOR_SIGNS: dict[type, str] = {
    ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.FloorDiv: "//",
    ast.Mod: "%", ast.Pow: "**", ast.BitAnd: "&", ast.BitOr: "|", ast.BitXor: "^",
    ast.LShift: "<<", ast.RShift: ">>", ast.MatMult: "@"}

def _substitution(value: Any) -> bool:
    """Whether ``value`` is a launch substitution object the file made (a
    ``LaunchConfiguration``, ``FindPackageShare``, ``PathJoinSubstitution``, a
    ``pathlib`` path of parts known at launch time...), not text computed when launch
    runs (``Lazy``, a ``str`` then) nor a value not known (``Opaque``: any object), nor
    an object of a substitution class the file defines (``Performed``: it may define
    operators)."""
    return isinstance(value, e.Subst) and not isinstance(value, (e.Opaque, e.Performed))


def _launch_class(ref: Ref) -> bool:
    """Whether ``ref`` names a class of launch's or launch_ros' modules (a CamelCase
    name there: ``launch.substitutions.PathJoinSubstitution``), not a module, function
    or constant."""
    module, _, name = ref.qualified.rpartition(".")
    return module.split(".")[0] in ("launch", "launch_ros") and name[:1].isupper() and (
        not name.isupper() and "_" not in name)


def _operand_kind(value: Any) -> str:
    if isinstance(value, e.PathJoin) and value.python == e.PATHLIB:
        return "a pathlib path"
    if isinstance(value, e.Subst):
        return "a launch substitution"
    if isinstance(value, PurePosixPath):
        return "a pathlib path"
    return "str"


class Expressions(Walker):
    """The expression half of ``Interpreter`` (statements and calls live there)."""

    globals: dict[str, Any]
    builtins: frozenset[str]
    methods: dict[str, Any]
    environment: Mapping[str, str]
    # variables the file sets (``os.environ[key] = ...``) under a test not known
    # statically: read after, their value is not known
    environment_unsure: set[str]
    # variables the file removes (``del os.environ[key]``) under no test: not set after
    environment_removed: set[str]
    # the names ``del`` unbound, per scope (by the scope's identity, the scope kept):
    # read where no scope binds them again, they are Python's NameError
    # (``Interpreter.delete_name``)
    deleted: dict[int, tuple[dict[str, Any], set[str]]]
    argv: list[Any] | None  # ``sys.argv``: the ros2 launch command line, if known
    guards: list[Guard]
    # the expressions whose value Python's handling of a launch object decided: ``not``
    # of one, one compared with ``==`` (``compare_values``); by id, the node kept alive
    # so that no later node takes its id
    decided: dict[int, ast.AST]
    diagnostics: list[Diagnostic]

    guard_runs: int  # the runs of Python tests not known statically so far (``guard``)
    path: str  # the file whose code runs
    # per file read, the names its code binds anywhere (``python.names_bound``)
    bindings: dict[str, frozenset[str] | None]

    def sized(self, value: Any) -> Any:
        raise NotImplementedError

    def guard(self, text: str, test: int | None = None) -> Guard:
        """A run of a test not known statically, to push on ``guards`` (``test``: the
        ``if`` test's node it comes from, by id)."""
        self.guard_runs += 1
        return Guard(text, self.guard_runs, test)

    def guarding(self) -> None:
        """An action is made under ``guards``: the tests not said yet are said."""

    def unsupported(self, node: ast.AST | None, detail: str,
                    code: str = "LAUNCH_PY_UNSUPPORTED") -> Unknown:
        raise NotImplementedError

    def where(self, node: ast.AST | None) -> Location:
        raise NotImplementedError

    def package_folder(self, path: PurePosixPath) -> tuple[str, str] | None:
        """The name and folder of the workspace package whose folder holds the absolute
        ``path`` (the source folder that stands for its install share folder), or None."""
        return None

    def path_up(self, owner: PurePosixPath, up: PurePosixPath, node: ast.AST) -> Any:
        """``up``, a folder above ``owner`` (``owner.parent``, ``owner.parents[N]``): as
        it is up to the folder of the workspace package that holds ``owner``, which
        stands for its install share folder, where ``ros2 launch`` runs a launch file
        from; a folder above that is not known, and said (``_above``)."""
        found = self.package_folder(owner)
        if found is None or _inside(up, found[1]):
            return up
        return self.unsupported(node, _above(node, found[0]))

    def path_parents(self, owner: PurePosixPath, node: ast.AST) -> tuple[Any, ...]:
        """``owner.parents``: each folder as ``path_up`` has it, those above the package's
        folder one unknown value, said once."""
        found = self.package_folder(owner)
        if found is None:
            return tuple(owner.parents)
        inside = tuple(p for p in owner.parents if _inside(p, found[1]))
        if len(inside) == len(owner.parents):
            return inside
        above = self.unsupported(node, _above(node, found[0], "holds folders"))
        return inside + (above,) * (len(owner.parents) - len(inside))

    def placed(self, value: Unknown, node: ast.AST) -> Unknown:
        """``value``, with the place that made it: its own when known, else ``node``'s
        (an unknown part a list of actions takes in here)."""
        if value.where is not None:
            return value
        return dataclasses.replace(value, where=self.where(node))

    def failed(self, node: ast.AST | None, detail: str, reason: str) -> Unknown:
        """A Python error of the interpreted code: said and unknown; the launch file's
        interpreter gives it to a ``try`` that catches it (``Interpreter.failed``)."""
        return self.unsupported(node, detail)

    def unknown_value(self, node: ast.AST, detail: str) -> None:
        """Report a value that cannot be known statically (LAUNCH_UNKNOWN_VALUE)."""
        raise NotImplementedError

    def call(self, func: Any, args: list[Any], kwargs: dict[str, Any], node: ast.AST) -> Any:
        raise NotImplementedError

    def assign(self, target: ast.expr, value: Any, env: dict[str, Any]) -> None:
        raise NotImplementedError

    def iterable(self, value: Any, node: ast.AST) -> list[Any] | None:
        raise NotImplementedError

    def either(self, values: list[Any], what: str = "one of several return values") -> Any:
        raise NotImplementedError

    # -- expressions ---------------------------------------------------------------------
    def bound(self, name: str, env: dict[str, Any]) -> Any:
        """``name``'s value in ``env``'s scopes, then the module's globals; ``UNBOUND``
        when none has it (nothing is said)."""
        scope: dict[str, Any] | None = env
        while scope is not None:
            if name in scope:
                return scope[name]
            scope = scope.get("__closure__")
        return self.globals.get(name, UNBOUND)

    def unbound_by_del(self, name: str, env: dict[str, Any]) -> bool:
        """Whether ``del`` unbound ``name`` in one of ``env``'s scopes or the module's,
        none of which binds it now."""
        scope: dict[str, Any] | None = env
        while scope is not None:
            if name in self.deleted_in(scope):
                return True
            scope = scope.get("__closure__")
        return name in self.deleted_in(self.globals)

    def deleted_in(self, scope: dict[str, Any]) -> set[str]:
        """The names ``del`` unbound in ``scope``."""
        found = self.deleted.get(id(scope))
        return found[1] if found is not None else set()

    def lookup(self, name: str, env: dict[str, Any], node: ast.AST) -> Any:
        value = self.bound(name, env)
        if value is not UNBOUND:
            return value
        if name in self.builtins:
            return Ref(name)
        if name in ("True", "False", "None"):
            return {"True": True, "False": False, "None": None}[name]
        stars = self.bound(UNFOUND_STARS, env)
        if isinstance(stars, list) and stars:
            return self.unsupported(node, f"name {name} is not defined here; it may be one of "
                                          + ", ".join(f"'from {m} import *'" for m in stars)
                                          + (", a module" if len(stars) == 1 else ", modules")
                                          + " not found")
        if hasattr(builtins, name):  # a builtin of Python the reader does not run
            return self.unsupported(node, f"builtin {name} is not interpreted (never run)")
        if self.unbound_by_del(name, env):
            return self.failed(node, f"name {name} is read after del unbound it: Python "
                               "raises NameError here, and launch stops",
                               f"NameError: name '{name}' is not defined")
        bindings = self.bindings.get(self.path)
        if bindings is not None and name not in bindings:
            # bound nowhere in the file, in code run or not: Python's NameError there
            return self.failed(node, f"name {name} is not defined anywhere in the file: "
                               "Python raises NameError here, and launch stops",
                               f"NameError: name '{name}' is not defined")
        return self.unsupported(node, f"name {name} is not defined here")

    # -- this configuration of the one evaluator's walk (``Walker``) -------------------
    def over(self, reason: str) -> NoReturn:
        raise Budget(reason)

    def unhandled(self, node: ast.AST, env: Any = None) -> Any:
        return self.unsupported(node, f"{type(node).__name__} is not interpreted")

    def opaque(self, value: object) -> bool:
        return _opaque(value)

    def truth(self, value: object) -> bool | None:
        """Python's truth of a value: a launch object is true (``launch_object``); a
        string with substitutions or an unknown is not known."""
        if launch_object(value):
            return True
        return super().truth(value)

    def truth_taken(self, node: ast.BoolOp, operand: ast.expr, value: object) -> None:
        """An ``and`` / ``or`` over a condition or a substitution (``condition=
        IfCondition(a) and IfCondition(b)``, ``LaunchConfiguration('ns') or 'robot'``):
        Python takes the object as true, never evaluating it, so the ``and`` gives its
        last operand whole and the ``or`` the object itself: ``LAUNCH_PY_BOOLEAN_OBJECT``
        at the operand. Not an action: ``node and [...]`` is the usual test of a variable
        that may hold None."""
        if isinstance(value, (e.Subst, e.Cond)):
            is_and = isinstance(node.op, ast.And)
            self.diagnostics.append(diag.make(
                "LAUNCH_PY_BOOLEAN_OBJECT", self.where(operand), test=_source(operand),
                op="and" if is_and else "or",
                result=("is its last operand whole: this one is never tested" if is_and
                        else "is this object itself: what follows it is never used")))

    def not_known(self, node: ast.AST, what: str, values: Iterable[object]) -> Any:
        """An operation on a substitution or an unknown: an unknown, which says what
        (one of values already said not known: ``derived_unknown``)."""
        # an ``and`` / ``or`` stops at its first operand not known: the later ones, not
        # evaluated, are unknown for causes of their own
        made = derived_unknown(what, values, self.where(node)) if what != "boolean" else None
        if made is not None:
            return made
        if what == "comparison":
            return Unknown(f"comparison {_source(node)}")
        return Unknown(_NOT_KNOWN.get(what, what))

    def refused(self, err: ops.Refused, node: ast.AST, what: str) -> Any:
        """A bound of the one evaluator stops the file (``Budget``); a comparison or a unary
        operator it refuses is an unknown; any other operation an unsupported construct."""
        if err.kind == "limit":
            raise Budget(err.reason) from None
        if what in ("comparison", "unary"):
            return Unknown(_NOT_KNOWN[what] if what == "unary" else what)
        if err.kind == "error":
            return self.failed(node, f"operation fails: {err.reason}", err.reason)
        return self.unsupported(node, err.reason)

    def operation(self, action: Callable[[], Any], node: ast.AST) -> Any:
        """An operation of the one evaluator on known values (``refused`` if it refuses)."""
        return self.compute(action, node, "operation")

    def eval_Constant(self, node: ast.Constant, env: dict[str, Any]) -> Any:
        return node.value

    def eval_Name(self, node: ast.Name, env: dict[str, Any]) -> Any:
        return self.lookup(node.id, env, node)

    def eval_List(self, node: ast.List | ast.Tuple | ast.Set, env: dict[str, Any]) -> Any:
        out: list[Any] = []
        for elt in node.elts:
            if isinstance(elt, ast.Starred):
                value = self.eval(elt.value, env)
                items = self.iterable(value, elt)
                if items is None:  # ``[*helper(), Node(...)]``: unknown items, not none
                    out.append(self.placed(value if isinstance(value, Unknown) else Unknown(
                        f"the items of {_source(elt.value)}"), elt))
                else:
                    out.extend(items)
            else:
                out.append(self.eval(elt, env))
            self.sized(out)
        return tuple(out) if isinstance(node, ast.Tuple) else out

    eval_Tuple = eval_List
    eval_Set = eval_List

    def eval_Dict(self, node: ast.Dict, env: dict[str, Any]) -> Any:
        out: dict[Any, Any] = {}
        for key, value in zip(node.keys, node.values, strict=False):
            if key is None:
                merged = self.eval(value, env)
                if isinstance(merged, dict):
                    out.update(merged)
                continue
            k = self.eval(key, env)
            self.step(ops.walk_cost(k, LIMITS))  # the key is hashed
            out[_hashable(k)] = self.eval(value, env)
        return out

    def eval_JoinedStr(self, node: ast.JoinedStr, env: dict[str, Any]) -> Any:
        parts: list[Any] = []
        for value in node.values:
            if isinstance(value, ast.FormattedValue):
                parts.append(self.formatted(value, env))
            else:
                parts.append(self.eval(value, env))
        return concat(parts)

    def formatted(self, node: ast.FormattedValue, env: dict[str, Any]) -> Any:
        """``{value!r:spec}`` of an f-string: formatted by the one evaluator when the value
        and the spec are known; a text made when launch runs keeps its place otherwise.
        An object of launch's API (a substitution, a condition, an action) is formatted
        as Python formats it, with ``object``'s ``__format__``: its object text
        (``object_text``, as ``str()``), never the value it stands for; with a format
        spec, a TypeError."""
        value = self.eval(node.value, env)
        text = object_text(value)
        if text is not None:
            spec = self.eval(node.format_spec, env) if node.format_spec is not None else ""
            if not isinstance(spec, str):
                return Unknown("the format spec of a launch object")
            if spec:
                return self.failed(node, f"{{{ast.unparse(node.value)}:...}}: a launch "
                                   "object takes no format spec", "TypeError")
            return text
        # a list, tuple or dict of plain values prints as str() prints it
        container = isinstance(value, (list, tuple, dict)) and printable(value, path=False)
        if node.format_spec is None and node.conversion == -1 and isinstance(value, bool):
            # ``f"not {fake}"`` of a bool the file computed (``perform(context) ==
            # "true"``): Python's text of it, True or False (a PythonExpression of it)
            return str(value)
        if node.format_spec is None and node.conversion == -1 and not container:
            return value
        spec = self.eval(node.format_spec, env) if node.format_spec is not None else ""
        if not isinstance(spec, str) or not (
                container or isinstance(value, (str, int, float, bool))) or value is None:
            return value
        return self.operation(lambda: ops.format_value(value, spec, node.conversion, LIMITS),
                              node)

    def eval_BinOp(self, node: ast.BinOp, env: dict[str, Any]) -> Any:
        return self.binop(node.op, self.eval(node.left, env), self.eval(node.right, env), node)

    def binop(self, op: ast.operator, left: Any, right: Any, node: ast.AST) -> Any:
        if isinstance(op, ast.Div) and (isinstance(left, PurePosixPath) or isinstance(
                right, PurePosixPath)) and isinstance(left, (str, PurePosixPath)) \
                and isinstance(right, (str, PurePosixPath)):
            return PurePosixPath(left) / right  # pathlib, pure: no file is looked at
        if isinstance(op, ast.Div) and isinstance(left, PurePosixPath) and isinstance(
                right, Lazy):
            # a known path and a str known when launch runs (an f-string of an
            # environment variable, robosub-ros2's ``f'{robot_name}.yaml'``): the path
            # pathlib's join makes (a substitution object is no str: Python refuses it)
            return e.PathJoin((to_text(left), to_text(right)), e.PATHLIB)
        if isinstance(op, ast.Div) and isinstance(left, e.PathJoin):
            # PathJoinSubstitution / part, as pathlib.Path does (launch >= 3.7)
            if isinstance(right, Unknown):
                return Unknown("a path part not known statically")
            return e.PathJoin((*left.parts, to_text(right)), left.python)
        if isinstance(op, ast.Add) and (_substitution(left) or _substitution(right)) and (
                is_stringy(left) or isinstance(left, PurePosixPath)) and (
                is_stringy(right) or isinstance(right, PurePosixPath)) and not (
                isinstance(left, (Unknown, e.Opaque)) or isinstance(right, (Unknown, e.Opaque))):
            # launch's substitutions define no ``+`` (``Substitution`` has ``describe``
            # and ``perform`` alone, and a str's ``+`` takes a str): Python raises where
            # the file is loaded. A list of them, ``[LaunchConfiguration('ns'), '/scan']``,
            # or ``PathJoinSubstitution`` is what joins them
            kinds = " and ".join(dict.fromkeys(_operand_kind(x) for x in (left, right)))
            return self.failed(node, f"{_source(node)} fails: TypeError: unsupported "
                               f"operand type(s) for +: {kinds}; a list of the parts joins "
                               "them", "TypeError")
        if isinstance(op, ast.Add) and (is_stringy(left) or is_stringy(right)) and not (
                isinstance(left, list) or isinstance(right, list)):
            return concat([left, right])
        if isinstance(op, ast.Add) and (isinstance(left, list) != isinstance(right, list)) \
                and all(isinstance(x, (list, Unknown, Lazy)) for x in (left, right)):
            # ``unknown_actions() + [Node(...)]``: the known items keep their place, the
            # unknown part (two unknowns added read as a Lazy text) stays one unknown
            # item; what made it was reported
            return [*(left if isinstance(left, list) else [
                        self.placed(_unknown_part(left), node)]),
                    *(right if isinstance(right, list) else [
                        self.placed(_unknown_part(right), node)])]
        if (isinstance(left, (e.Cond, e.Action)) or isinstance(right, (e.Cond, e.Action))) \
                and not (isinstance(left, Unknown) or isinstance(right, Unknown)):
            # launch's conditions and actions define no operator: Python raises
            # (amigo_ros2's ``IfCondition(a) & IfCondition(b)``; ``all`` of conditions,
            # launch's AndSubstitution, is what combines them)
            sign = _OPERATOR_SIGNS.get(type(op), type(op).__name__)
            kinds = " and ".join(dict.fromkeys(
                "a launch condition" if isinstance(x, e.Cond) else "a launch action"
                if isinstance(x, e.Action) else type(x).__name__ for x in (left, right)))
            return self.failed(node, f"{_source(node)} fails: TypeError: unsupported "
                               f"operand type(s) for {sign}: {kinds}", "TypeError")
        if isinstance(left, Unknown) or isinstance(right, Unknown):
            return self.not_known(node, "arithmetic", (left, right))
        if isinstance(op, ast.Mod) and isinstance(left, str) and (
                isinstance(right, (Lazy, e.Subst)) or (
                    isinstance(right, tuple) and any(is_lazy(x) for x in right))):
            return self.unsupported(node, "%-formatting with substitutions")
        known = (str, int, float, bool, list, tuple, type(None))
        if not isinstance(left, known) or not isinstance(right, known):
            return self.unsupported(node, "operation on values not known statically")
        return self.operation(lambda: ops.binary(type(op), left, right, LIMITS), node)

    def compare_values(self, op: ast.cmpop, left: object, right: object,
                       node: ast.Compare) -> Any:
        """Python's comparison. ``name in os.environ`` reads the configuration's
        environment. A launch object (a substitution, a condition, an action) compared
        with ``==`` / ``!=`` / ``is`` is compared as Python compares it, by identity
        (launch's classes define no ``__eq__``): ``LaunchConfiguration('sim') == 'true'``
        is always false, whatever the argument (``decided`` notes it)."""
        if isinstance(right, _Environ) and isinstance(op, (ast.In, ast.NotIn)):
            found = right.has(self, left, node)
            if found is None:
                return Unknown(f"comparison {_source(node)}")
            return found == isinstance(op, ast.In)
        if isinstance(op, (ast.In, ast.NotIn)) and isinstance(right, dict) and (
                _hashable(left) not in right and open_keys(right)):
            # a key it does not hold among the known ones may be the unknown one
            return Unknown(f"comparison {_source(node)}")
        if isinstance(op, (ast.Eq, ast.NotEq, ast.Is, ast.IsNot)) and (
                launch_object(left) or launch_object(right)):
            if isinstance(op, (ast.Eq, ast.NotEq)) and _taken_as_value(left, right):
                self.decided[id(node)] = node
            return (left is right) == isinstance(op, (ast.Eq, ast.Is))
        return super().compare_values(op, left, right, node)

    def unary_value(self, node: ast.UnaryOp, value: object) -> Any:
        """``not`` of a launch object is False, as Python takes the object as true
        (``decided`` notes it for a substitution or a condition: ``not`` of an action
        is the usual test of a variable that may hold None)."""
        if isinstance(node.op, ast.Not) and launch_object(value):
            if isinstance(value, (e.Subst, e.Cond)):
                self.decided[id(node)] = node
            return False
        return super().unary_value(node, value)

    def eval_Subscript(self, node: ast.Subscript, env: dict[str, Any]) -> Any:
        if isinstance(node.value, ast.Attribute) and node.value.attr == "parents":
            # ``path.parents[N]``: that one folder, said only when above the package's
            owner = self.eval(node.value.value, env)
            if isinstance(owner, PurePosixPath):
                key = self.eval(node.slice, env)
                if isinstance(key, int) and not isinstance(key, bool):
                    try:
                        up = owner.parents[key]
                    except IndexError:
                        return self.failed(node, f"{_source(node)} fails: IndexError: "
                                           f"{key}", "IndexError")
                    return self.path_up(owner, up, node)
            value = _read(self.attribute_of(owner, node.value), node.value)
        else:
            value = self.eval(node.value, env)
        key = self.eval(node.slice, env)
        if isinstance(value, Ref) and _launch_class(value):
            # ``PathJoinSubstitution[share, 'x.launch.py']``: a class of launch or
            # launch_ros subscripted, not called; none defines ``__class_getitem__``, so
            # Python raises where the file is loaded
            return self.failed(node, f"{_source(node)} fails: TypeError: type "
                               f"'{value.qualified.rsplit('.', 1)[-1]}' is not "
                               "subscriptable; the class is called with a list of the parts, "
                               f"{value.qualified.rsplit('.', 1)[-1]}([...])", "TypeError")
        if isinstance(value, _Environ):
            return value.get(self, [key], node)
        if isinstance(value, Context) and isinstance(node.value, ast.Attribute):
            state, held = value.held(key)
            if state == "value":  # set by the function, or launch_ros' global_params
                return held
            return value.perform((e.Var(_text_of(key)),))
        if isinstance(value, (list, tuple)) and value and _opaque(key) and all(
                isinstance(item, e.Action) for item in value):
            # an item not known of a list of actions (neo_simulation2's
            # ``ld.add_action(spawn_entity[i])`` in a loop over robots whose number is
            # not known): one of them, so each, under the test it was made under
            return self.either(list(value), f"{_source(node)}")
        if isinstance(value, DefaultDict) and value.factory is not None and not (
                _opaque(key) or isinstance(key, (list, dict, slice))):
            hashable = _hashable(key)
            if not _opaque(hashable) and hashable not in value and not open_keys(value):
                # a key it lacks: what the factory makes, stored, as Python's does
                value[hashable] = self.call(value.factory, [], {}, node)
                self.sized(value)
        if isinstance(key, slice) or isinstance(value, (dict, list, tuple, str)):
            self.step(ops.walk_cost(key, LIMITS))  # a key is hashed
            try:
                return ops.subscript(value, _hashable(key))
            except ops.Refused as err:
                made = said_unknown("a slice", [value])
                if made is not None:  # said where it was made
                    return made
                if err.kind == "error" and _fails_for_sure(value, key):
                    # a missing key, an index out of range of a value known: Python
                    # raises, to a ``try`` whose handler catches it (``failed``)
                    return self.failed(node, f"{_source(node)} fails: {err.reason}",
                                       err.reason)
                return self.unsupported(node, f"{_source(node)} is not known statically")
        # a value said unknown where it was made (a file outside the workspace, a call
        # not run): its items are as unknown, said no more (III-Drone's parameters
        # dict, read from ~/.config, then subscripted at each use)
        made = said_unknown("an item", [value])
        if made is not None:
            return made
        # which expression, as an attribute of an unknown value says (it was "subscript")
        return Unknown(f"{_source(node)} (a subscript of a value not known statically)")

    def eval_Attribute(self, node: ast.Attribute, env: dict[str, Any]) -> Any:
        return _read(self.attribute(node, env), node)

    def attribute(self, node: ast.Attribute, env: dict[str, Any]) -> Any:
        """``owner.attr``; a method of a value waits for its call (``_Bound``)."""
        return self.attribute_of(self.eval(node.value, env), node)

    def attribute_of(self, owner: Any, node: ast.Attribute) -> Any:
        """``owner.attr`` of the value ``owner`` (``node.value`` evaluated)."""
        if isinstance(owner, Ref):
            if owner.qualified == "os" and node.attr == "environ":
                return _Environ()
            if owner.qualified == "sys" and node.attr == "argv" and self.argv is not None:
                return list(self.argv)  # the ros2 launch command line (Runner.argv)
            if f"{owner.qualified}.{node.attr}" in OS_VALUES:  # os.pathsep
                return OS_VALUES[f"{owner.qualified}.{node.attr}"]
            if owner.qualified == "math" and math_constant(node.attr):
                return ops.MATH[node.attr]  # math.pi
            if owner.qualified == "launch.logging.launch_config" and node.attr == "log_dir":
                # the folder launch's logging writes this run's logs to (``~/.ros/log/
                # <date>-<host>-<pid>`` unless ROS_LOG_DIR says), chosen when it runs:
                # cabot's ``SetEnvironmentVariable('ROS_LOG_DIR', launch_config.log_dir)``
                return Lazy((e.Opaque("the log folder launch chooses when it runs",
                                      report=False),))
            return Ref(f"{owner.qualified}.{node.attr}")
        if isinstance(owner, Module):  # a module of the workspace the file imported
            if node.attr in owner.names:
                return owner.names[node.attr]
            return self.unsupported(node, f"{owner.name}.{node.attr} is not defined in "
                                          f"{owner.name} as read here")
        if isinstance(owner, (Instance, PlainClass)):
            found = member(owner, node.attr)
            if found is UNBOUND:
                name = owner.cls.name if isinstance(owner, Instance) else owner.name
                return self.unsupported(node, f"{name}.{node.attr} is not set as read here")
            if isinstance(found, _Property):  # run on each read, as Python does
                return self.call(Method(found.func, owner), [], {}, node)
            return found
        if isinstance(owner, Record) and node.attr in owner.attributes:
            return owner.attributes[node.attr]  # MoveItConfigs.robot_description
        if isinstance(owner, EnumMember) and node.attr in ("name", "value"):
            return owner.name if node.attr == "name" else owner.value
        if isinstance(owner, Context) and node.attr == "launch_configurations":
            return owner
        if isinstance(owner, Context) and node.attr == "environment":
            # the process's environment, as ``os.environ`` (depthai's camera.launch.py:
            # ``context.environment.get("DEPTHAI_DEBUG")``)
            return _Environ()
        if isinstance(owner, PurePosixPath) and node.attr == "parent":
            return self.path_up(owner, owner.parent, node)
        if isinstance(owner, PurePosixPath) and node.attr == "parents":
            return self.path_parents(owner, node)
        if isinstance(owner, PurePosixPath) and node.attr in _PATH_ATTRIBUTES:
            return getattr(owner, node.attr)
        if isinstance(owner, LaunchDescription) and node.attr == "entities":
            # launch's property: the description's list of entities itself (an
            # OpaqueFunction returning ``ld.entities``: lbr_fri_ros2_stack's move_group)
            return owner.actions
        if isinstance(owner, Constructing):  # self.x in a constructor
            if node.attr in owner.attributes:
                return owner.attributes[node.attr]
            if owner.built is None:
                return self.unsupported(node, f"{_source(node)} is not set before it is "
                                              "read")
            owner = owner.built
        if isinstance(owner, e.Process) and node.attr in owner.members:
            return owner.members[node.attr]  # WebotsLauncher's _supervisor
        if isinstance(owner, e.DeclareArg) and node.attr == "name":
            return owner.name  # DeclareLaunchArgument.name, a property
        if isinstance(owner, e.Literal) and node.attr == "text":
            return concat(list(owner.text))  # TextSubstitution.text, a property
        return _Bound(owner, node.attr)

    def eval_Call(self, node: ast.Call, env: dict[str, Any]) -> Any:
        if isinstance(node.func, ast.Attribute):  # a method, even of an unknown value
            self.step()
            func = self.attribute(node.func, env)
        else:
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
        if isinstance(func, Ref) and func.qualified == "eval" and len(args) == 1 and (
                not kwargs and isinstance(args[0], str)):
            return self.eval_source(args[0], node, env)
        if OUTER in env and isinstance(func, (Func, Method)):
            # names the caller declared ``global`` / ``nonlocal`` are the scope's, which
            # the function called reads and may set (a helper reading the ``global
            # terrain`` that generate_launch_description set before calling it)
            write_outer(env)
            result = self.call(func, args, kwargs, node)
            read_outer(env)
        else:
            result = self.call(func, args, kwargs, node)
        if self.guards and isinstance(result, (e.Action, e.ComposableNode)):
            result = self.guarded(result, node)
        return result

    def eval_source(self, source: str, node: ast.Call, env: dict[str, Any]) -> Any:
        """Python's ``eval(text)`` of a text known here, given no globals nor locals: the
        expression, read as any of the file's, with the names of the scope it is called
        in, as Python gives it the caller's (navigation2's multi-robot test launch file:
        ``eval(f"{robot['name']}_params_file")`` of its locals ``robot1_params_file``,
        ``robot2_params_file``); interpreted, never run. Its parts are placed at the
        call; a text that is no expression is the SyntaxError Python raises."""
        try:
            tree = ast.parse(source.strip(" \t"), mode="eval")
        except (SyntaxError, ValueError) as err:
            return self.failed(node, f"eval of {source!r} fails: it is no Python expression",
                               f"SyntaxError: {err}")
        for part in ast.walk(tree):
            if isinstance(part, ast.expr):
                ast.copy_location(part, node)
                part.end_lineno, part.end_col_offset = node.end_lineno, node.end_col_offset
        return self.eval(tree.body, env)

    def guarded(self, action: e.Action | e.ComposableNode, node: ast.AST
                ) -> e.Action | e.ComposableNode:
        """An action (or a composable node's description) made under a Python ``if``
        whose test is unknown: conditional. A description that has a condition of its
        own keeps it alone (no group to put it in: it may then be taken when the test
        would not hold, never left out). The test is said once, where it is, for the
        first action it guards (``guarding``), or its value where it was made (a loop's
        items, a filter): not again at each action."""
        self.guarding()
        text = conjunction(self.guards)
        cond = e.Cond((e.Opaque(f"Python test {text}", report=False),), source=text,
                      runs=tuple(guard.run for guard in self.guards))
        if action.condition is None:
            action.condition = cond
            return action
        if isinstance(action, e.ComposableNode):
            return action
        return e.Group([action], scoped=False, condition=cond, location=action.location)

    def eval_Lambda(self, node: ast.Lambda, env: dict[str, Any]) -> Any:
        return Func(node, env)

    def eval_ListComp(self, node: ast.ListComp | ast.GeneratorExp | ast.SetComp,
                   env: dict[str, Any]) -> Any:
        out: list[Any] = []
        self.comprehension(node.generators, env,
                           lambda scope: out.append(self.eval(node.elt, scope)))
        return out

    eval_GeneratorExp = eval_ListComp
    eval_SetComp = eval_ListComp

    def eval_DictComp(self, node: ast.DictComp, env: dict[str, Any]) -> Any:
        out: dict[Any, Any] = {}

        def add(scope: dict[str, Any]) -> None:
            out[_hashable(self.eval(node.key, scope))] = self.eval(node.value, scope)

        self.comprehension(node.generators, env, add)
        return out

    def undecided(self, node: ast.IfExp, test: object, env: Any) -> Any:
        return Unknown(f"conditional expression {_source(node.test)}")

    def enter(self, env: Any) -> Any:
        return dict(env, __closure__=env, **{COMPREHENSION: True})

    def eval_NamedExpr(self, node: ast.NamedExpr, env: dict[str, Any]) -> Any:
        """``(name := value)``: the value, bound to the name in the scope of the code
        around it; in a comprehension, in the scope the comprehension is in (PEP 572).
        Autoware's scenario_test_runner.launch.py: ``if (it := collect_vehicle_parameters())
        != []: parameters += it``."""
        value = self.eval(node.value, env)
        scope = env
        while scope.get(COMPREHENSION) and isinstance(scope.get("__closure__"), dict):
            scope = scope["__closure__"]
        self.assign(node.target, value, scope)
        return value

    def comprehension(self, generators: list[ast.comprehension], env: Any,
                      emit: Callable[[Any], None]) -> None:
        """The evaluator's comprehension, where what is not known is not taken as
        nothing: a loop over a value not known makes one item, not known, under that
        loop; an item whose filter is not known is kept under that filter (its actions
        may run), as an ``if`` of a test not known runs its body."""
        def loop(index: int, scope: Any) -> None:
            if index == len(generators):
                emit(scope)
                return
            gen = generators[index]
            items = self.iterable(self.eval(gen.iter, scope), gen.iter)
            guard = None
            if items is None:
                guard = f"for {_source(gen.target)} in {_source(gen.iter)}"
                # (said where the value was made, or by ``iterable``)
                items = [Unknown(f"an item of {_source(gen.iter)}", "unsupported",
                                 where=self.where(gen.iter))]
                self.guards.append(self.guard(guard))
            try:
                for item in items:
                    self.step()
                    self.let(gen.target, item, scope)
                    tests = [self.truth(self.eval(cond, scope)) for cond in gen.ifs]
                    if False in tests:
                        continue
                    unknown = [c for c, t in zip(gen.ifs, tests, strict=True) if t is None]
                    if unknown:  # kept, and said: a list of plain values may be too long
                        self.unsupported(unknown[0], "comprehension filter not known "
                                                     "statically; the item is kept")
                    self.guards.extend(self.guard(_source(c)) for c in unknown)
                    try:
                        loop(index + 1, scope)
                    finally:
                        del self.guards[len(self.guards) - len(unknown):]
            finally:
                if guard is not None:
                    self.guards.pop()

        scope = self.enter(env)
        try:
            loop(0, scope)
        finally:
            self.leave(scope)

    def let(self, target: ast.AST, item: object, env: Any = None) -> None:
        if isinstance(target, ast.expr):  # a comprehension's target always is
            self.assign(target, item, env)

    def keep(self, gen: ast.comprehension, env: Any) -> bool:
        """Unused: ``comprehension`` keeps an item whose filter is not known."""
        return all(self.truth(self.eval(cond, env)) is not False for cond in gen.ifs)


# the ``os`` constants of the Linux a ROS launch runs on (tiago_simulation's
# tiago_gazebo.launch.py joins model paths with ``pathsep``)
OS_VALUES = {"os.sep": "/", "os.path.sep": "/", "os.pathsep": ":", "os.path.pathsep": ":",
             "os.linesep": "\n", "os.curdir": ".", "os.path.curdir": ".", "os.pardir": "..",
             "os.path.pardir": "..", "os.extsep": ".", "os.path.extsep": "."}


def os_value(module: str, name: str) -> Any:
    """What ``from os import name`` (or ``os.path``) binds, when we know it: a constant,
    or ``environ`` (the configuration's environment); None otherwise."""
    if module == "os" and name == "environ":
        return _Environ()
    return OS_VALUES.get(f"{module}.{name}")


def math_constant(name: str) -> bool:
    """Whether ``math.<name>`` is one of the constants of the safe table (``pi``, ``e``,
    ``tau``, ``inf``, ``nan``)."""
    return isinstance(ops.MATH.get(name), float)


def _unknown_part(value: Any) -> Unknown:
    return value if isinstance(value, Unknown) else Unknown("a list not known statically")


@dataclass(eq=False)
class _Property:
    """A property of a ``PlainClass`` read on an instance: its function, run then."""

    func: Func


def member(owner: Instance | PlainClass, attr: str) -> Any:
    """``owner.attr`` of an instance (its own attributes first) or of a class: a value, a
    ``Method`` bound to the instance (the class, for a classmethod), a function (a
    staticmethod; a plain method read on the class), a ``_Property``; ``UNBOUND`` when
    neither the instance nor its class has that name."""
    cls = owner.cls if isinstance(owner, Instance) else owner
    if isinstance(owner, Instance) and attr in owner.attributes:
        return owner.attributes[attr]
    if attr in cls.methods:
        kind, func = cls.methods[attr]
        if kind == "static":
            return func
        if kind == "class":
            return Method(func, cls)
        if not isinstance(owner, Instance):
            return func if kind == "method" else UNBOUND
        return _Property(func) if kind == "property" else Method(func, owner)
    return cls.attributes.get(attr, UNBOUND)


@dataclass
class _Bound:
    """``owner.attr`` waiting to be called (a method of a known value)."""

    owner: Any
    attr: str

    def call(self, interp: Interpreter, args: list[Any], kwargs: dict[str, Any],
             node: ast.AST) -> Any:
        handler = interp.methods.get(self.attr)
        if handler is None and isinstance(self.owner, Unknown) \
                and self.owner.kind == "unsupported":
            # a method of a value whose construct was said not interpreted where it was
            # made (``c = LocalClass()`` then ``c.add(...)`` 30 times): said there, once
            return derived(self.owner, f"method .{self.attr}() of a value not known statically")
        if handler is None:
            return interp.unsupported(node, f"method .{self.attr}() is not interpreted")
        return handler(interp, self.owner, args, kwargs, node)


def _taken_as_value(left: object, right: object) -> bool:
    """Whether a comparison holds a substitution or condition on one side and a plain
    value on the other: the file took the launch object for its value."""
    plain = (str, int, float, bool)
    return (isinstance(left, (e.Subst, e.Cond)) and isinstance(right, plain)) or (
        isinstance(right, (e.Subst, e.Cond)) and isinstance(left, plain))


class _Environ:
    """``os.environ``: reads the configuration's environment."""

    def has(self, interp: Expressions, name: Any, node: ast.AST) -> bool | None:
        """``name in os.environ``: True when the configuration sets it, else not known
        (as a ``get`` without a default), and said."""
        if isinstance(name, str) and name in interp.environment_unsure:
            interp.unknown_value(node, unsure_variable(name))
            return None
        if isinstance(name, str) and name in interp.environment_removed:
            return False
        if isinstance(name, str) and name in interp.environment:
            return True
        if isinstance(name, str):
            interp.unknown_value(node, f"environment variable {name} is not set in the "
                                       "configuration")
        return None

    def get(self, interp: Expressions, args: list[Any], node: ast.AST) -> Any:
        name = args[0] if args else None
        if isinstance(name, str) and name in interp.environment_unsure:
            interp.unknown_value(node, unsure_variable(name))
            return Lazy((e.Opaque(f"environment variable {name}", report=False),))
        if isinstance(name, str) and name in interp.environment_removed:
            if len(args) > 1:
                return args[1]
            return Unknown(f"environment variable {name}, removed by the launch file")
        if isinstance(name, str) and name in interp.environment:
            return interp.environment[name]
        if len(args) > 1:
            return args[1]
        if not isinstance(name, str):
            return Unknown("environment")
        interp.unknown_value(node, f"environment variable {name} is not set in the "
                                   "configuration")
        return Lazy((e.Opaque(f"environment variable {name}", report=False),))


def unsure_variable(name: str) -> str:
    return (f"environment variable {name} is set by the launch file under a test or to "
            "a value not known statically")
