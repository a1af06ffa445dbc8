"""Where the value of a name comes from, for the Python evaluator: the frame's locals,
then the module (its imports, classes, functions, constants, star imports of the
package, ``from pkg.msg import *`` of interface packages); and the items a ``for`` loop
over a known sequence takes.

``EvaluatorBase`` is the state the parts of the evaluator share (``values.Evaluator``
is them together).
"""

from __future__ import annotations

import ast
import itertools

from ...model.values import Unknown, Value
from . import msg_types
from .modules import Loader, Module, submodule
from .objects import Frame, ModuleRef, Record, Ref, Seq

MAX_UNROLL = 32  # a for loop over a known sequence is walked once per item, up to this
# ... and a loop inside no other unrolled loop, up to this: its cost grows with its items
# only, not with theirs times an outer loop's (mir_bridge's 65 topics, one publisher each)
MAX_UNROLL_OUTER = 256


class EvaluatorBase:
    """What every part of the evaluator sees: the loader, the parameters met so far,
    and ``eval`` (``values.Evaluator.eval``)."""

    def __init__(self, loader: Loader) -> None:
        self.loader = loader
        self.depth = 0
        # rclpy parameters declared so far: name -> default value
        self.declared: dict[str, object] = {}
        # defaults of the parameters read so far, for names built from their values
        self.param_defaults: dict[str, object] = {}
        # the defaults argparse gives the options parsed so far, by their flags
        # (``PrimitiveCall.name_option``): literal strings only
        self.option_defaults: dict[str, str] = {}
        self._computing: set[tuple[str, str]] = set()

    def eval(self, expr: ast.expr, frame: Frame) -> object:
        raise NotImplementedError

    def callee(self, func: ast.expr, frame: Frame) -> object:
        """What a call's function expression names (``values.Evaluator.callee``)."""
        raise NotImplementedError


class Scopes(EvaluatorBase):
    def lookup(self, module: Module, name: str) -> object:
        if name in module.local_imports:
            path, symbol = module.local_imports[name]
            other = self.loader.load(path)
            if other is None:
                return Unknown(name)
            if symbol is None:
                return ModuleRef(other)
            # a name imported in a cycle (``from . import system`` in the package's own
            # ``__init__``: the package is the module itself) is looked up once
            key = (f"import:{module.path}", name)
            if key in self._computing:
                return Unknown(name)
            self._computing.add(key)
            try:
                found = self.lookup(other, symbol)
            finally:
                self._computing.discard(key)
            inner = submodule(other.path, symbol) if isinstance(found, Unknown) else None
            loaded = self.loader.load(inner) if inner is not None else None
            # a name the package's __init__ does not bind: its submodule, as import does
            return ModuleRef(loaded) if loaded is not None else found
        if name in module.imports:
            return Ref(module.imports[name])
        if name in module.classes:
            return module.classes[name]
        if name in module.functions:
            return module.functions[name]
        if name in module.constants:
            key = (module.path, name)
            if name not in module.values and key not in self._computing:
                self._computing.add(key)
                try:
                    module.values[name] = self.eval(module.constants[name], Frame(module))
                finally:
                    self._computing.discard(key)
            return module.values.get(name, Unknown(name))
        if name in module.guarded:
            found = self._guarded(module, name)
            if not isinstance(found, Unknown):
                return found
        for path in module.local_stars:
            other = self.loader.load(path)
            if other is not None and other is not module:
                found = self.lookup(other, name)
                if not isinstance(found, Unknown):
                    return found
        return self._star_interface(module, name)

    def _guarded(self, module: Module, name: str) -> object:
        """The class or function a module-level ``if`` defines (``Module.guarded``) in
        the branch its tests choose, over the module's names (ros_compatibility's
        ``ROS_VERSION == 2``, from the distribution's ROS_VERSION); not known when a
        test is not, or no branch defines it."""
        key = (f"guarded:{module.path}", name)
        if key in self._computing:
            return Unknown(name)
        self._computing.add(key)
        try:
            for tests, made in module.guarded[name]:
                held = [self._truth(test, module) for test, _ in tests]
                if any(h is None for h in held):
                    return Unknown(name)
                if all(h == holds for h, (_, holds) in zip(held, tests, strict=True)):
                    return made
        finally:
            self._computing.discard(key)
        return Unknown(name)

    def _truth(self, test: ast.expr, module: Module) -> bool | None:
        value = self.eval(test, Frame(module))
        plain = value.literal if isinstance(value, Value) else value
        return bool(plain) if isinstance(plain, bool | int | float | str) else None

    def _star_interface(self, module: Module, name: str) -> object:
        guesses: list[str] = []
        for star in dict.fromkeys(module.stars):
            parts = star.split(".")
            if len(parts) != 2 or parts[1] not in msg_types.INTERFACE_MODULES:
                continue
            names = msg_types.interface_names(self.loader.workspace, parts[0], parts[1])
            if names is None:
                guesses.append(star)
            elif name in names:
                return Ref(f"{star}.{name}")
        if len(guesses) == 1 and name[:1].isupper():
            return Ref(f"{guesses[0]}.{name}")
        return Unknown(name)

    def name(self, name: str, frame: Frame) -> object:
        if name in frame.locals:
            return frame.locals[name]
        if name == "self" and frame.instance is not None:
            return frame.instance
        return self.lookup(frame.module, name)

    def iteration(self, expr: ast.expr, frame: Frame,
                  limit: int = MAX_UNROLL) -> tuple[object, ...] | None:
        """The items a ``for`` loop over ``expr`` takes, when known and at most
        ``limit``: a list or tuple, ``range(...)`` of integers, ``enumerate(...)``,
        ``zip(...)`` and ``itertools.product(...)`` of lists or tuples; a dict literal's
        keys (the dict itself, ``keys()``), values or ``(key, value)`` pairs (``items()``),
        Python 2's ``iter*`` spellings too (axis_camera's ``for name, val in
        arg_defaults.iteritems(): rospy.search_param(name)``)."""
        if isinstance(expr, ast.Call) and isinstance(expr.func, ast.Attribute) \
                and not expr.args and not expr.keywords and expr.func.attr in _DICT_VIEWS:
            owner = self.eval(expr.func.value, frame)
            if isinstance(owner, Record):
                return _view(owner, _DICT_VIEWS[expr.func.attr], limit)
        callee = self.eval(expr.func, frame) if isinstance(expr, ast.Call) else None
        if isinstance(expr, ast.Call) and not expr.keywords and isinstance(callee, Ref) \
                and callee.qualname == "itertools.product":
            # ds4_driver's twist node declares inputs.linear.x, ... over the product of
            # three lists of names
            factors = [f for f in (self.eval(a, frame) for a in expr.args)
                       if isinstance(f, Seq)]
            if not factors or len(factors) != len(expr.args):
                return None
            count = 1
            for factor in factors:
                count *= len(factor.items)
            if count > limit:
                return None
            return tuple(Seq(items) for items in itertools.product(
                *(f.items for f in factors)))
        if isinstance(expr, ast.Call) and isinstance(expr.func, ast.Name) \
                and not expr.keywords and isinstance(callee, Unknown):
            args = [self.eval(a, frame) for a in expr.args]
            rows = [a for a in args if isinstance(a, Seq)]
            if expr.func.id == "zip" and args and len(rows) == len(args):
                # as Python does: as long as the shortest
                paired = tuple(Seq(items) for items in zip(*(a.items for a in rows),
                                                           strict=False))
                return paired if len(paired) <= limit else None
            bounds = [a for a in args if isinstance(a, int) and not isinstance(a, bool)]
            if expr.func.id == "range" and 1 <= len(bounds) == len(args) <= 3 \
                    and (len(bounds) < 3 or bounds[2] != 0):
                steps = range(*bounds)
                return tuple(steps) if len(steps) <= limit else None
            if expr.func.id == "enumerate" and len(args) == 1 and isinstance(args[0], Seq):
                items = args[0].items
                return tuple(Seq((i, item)) for i, item in enumerate(items)) \
                    if len(items) <= limit else None
            if expr.func.id in COPIES and len(args) == 1 and isinstance(args[0], Seq) \
                    and len(args[0].items) <= limit:
                return _copied(expr.func.id, args[0].items)
            return None
        value = self.eval(expr, frame)
        if isinstance(value, Seq) and len(value.items) <= limit:
            return value.items
        if isinstance(value, Record):
            return _view(value, "keys", limit)
        return None


# builtins that give the items of the sequence they are given, in an order of their own
# (``for joint in sorted(self.joints)``: rbx1's head_tracker.py)
COPIES = frozenset({"sorted", "reversed", "list", "tuple"})


def _copied(builtin: str, items: tuple[object, ...]) -> tuple[object, ...]:
    """The items a loop over ``builtin(items)`` takes: reversed, sorted when every item
    is a literal text or every one a number, else (``sorted`` of items not all known) as
    written: each is walked once, which is all a call made per item depends on."""
    if builtin == "reversed":
        return items[::-1]
    if builtin != "sorted":
        return items
    texts = [item.literal if isinstance(item, Value) else None for item in items]
    if all(text is not None for text in texts):
        order = sorted(range(len(items)), key=lambda index: str(texts[index]))
        return tuple(items[index] for index in order)
    if all(isinstance(item, int | float) and not isinstance(item, bool) for item in items):
        return tuple(sorted(items, key=float))  # type: ignore[arg-type]
    return items


# a dict's methods that iterate over it, and what each gives
_DICT_VIEWS = {"keys": "keys", "iterkeys": "keys", "values": "values",
               "itervalues": "values", "items": "items", "iteritems": "items"}


def _view(record: Record, view: str, limit: int) -> tuple[object, ...] | None:
    if len(record.entries) > limit:
        return None
    if view == "keys":
        return tuple(Value.of(key) for key, _ in record.entries)
    if view == "values":
        return tuple(value for _, value in record.entries)
    return tuple(Seq((Value.of(key), value)) for key, value in record.entries)
