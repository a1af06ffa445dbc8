"""Static values of Python expressions: what a name, type or QoS argument holds.

``Evaluator.eval(expr, frame)`` never runs code. Strings are ``Value``s whose unknown
parts print as ``?`` (f-strings, ``+``, ``%`` and ``str.format`` keep every known part);
numbers, booleans and None are themselves; imported things are ``Ref``s to their
qualified name; parameter reads are ``ParamValue``s (a name that is a parameter's value);
rclpy nodes are ``NodeHandle``s; objects of classes of the package are ``Instance``s
whose attributes come from ``__init__``; anything else is ``Opaque``.
Helper functions whose body is straight-line code ending in ``return`` are evaluated
with their arguments bound, a few calls deep.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from typing import Any

from ...model.values import Value
from . import msg_types, rclpy, rospy
from .modules import ClassInfo, FunctionInfo, Loader, Module, submodule
from .objects import (
    BoundMethod,
    Frame,
    Instance,
    ModuleRef,
    NodeHandle,
    NodeMethod,
    Opaque,
    ParameterClient,
    ParamObject,
    ParamValue,
    QoS,
    Ref,
    Seq,
    SuperInit,
    text_of,
)
from .strings import arith, number, percent, string_method

MAX_EVAL_DEPTH = 60
MAX_CALL_DEPTH = 4
MAX_UNROLL = 32  # a for loop over a known sequence is walked once per item, up to this
# methods of an rclpy node that give its own name; in a name they are the private '~'
NAME_METHODS = ("get_name", "get_fully_qualified_name")
NAMESPACE = "node namespace"  # origin of the unknown get_namespace() gives


class Evaluator:
    def __init__(self, loader: Loader) -> None:
        self.loader = loader
        self.depth = 0
        # rclpy parameters declared so far: name -> default value
        self.declared: dict[str, object] = {}
        # defaults of the parameters read so far, for names built from their values
        self.param_defaults: dict[str, object] = {}
        self._computing: set[tuple[str, str]] = set()

    # -- names --------------------------------------------------------------------------

    def lookup(self, module: Module, name: str) -> object:
        if name in module.local_imports:
            path, symbol = module.local_imports[name]
            other = self.loader.load(path)
            if other is None:
                return Opaque(name)
            return ModuleRef(other) if symbol is None else self.lookup(other, symbol)
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
            return module.values.get(name, Opaque(name))
        for path in module.local_stars:
            other = self.loader.load(path)
            if other is not None and other is not module:
                found = self.lookup(other, name)
                if not isinstance(found, Opaque):
                    return found
        return self._star_interface(module, name)

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
        return Opaque(name)

    def name(self, name: str, frame: Frame) -> object:
        if name in frame.locals:
            return frame.locals[name]
        if name == "self" and frame.instance is not None:
            return frame.instance
        return self.lookup(frame.module, name)

    def iteration(self, expr: ast.expr, frame: Frame) -> tuple[object, ...] | None:
        """The items a ``for`` loop over ``expr`` takes, when known and at most
        ``MAX_UNROLL``: a list or tuple, ``range(...)`` of integers, ``enumerate(...)``."""
        if isinstance(expr, ast.Call) and isinstance(expr.func, ast.Name) \
                and not expr.keywords and isinstance(self.eval(expr.func, frame), Opaque):
            args = [self.eval(a, frame) for a in expr.args]
            bounds = [a for a in args if isinstance(a, int) and not isinstance(a, bool)]
            if expr.func.id == "range" and 1 <= len(bounds) == len(args) <= 3 \
                    and (len(bounds) < 3 or bounds[2] != 0):
                steps = range(*bounds)
                return tuple(steps) if len(steps) <= MAX_UNROLL else None
            if expr.func.id == "enumerate" and len(args) == 1 and isinstance(args[0], Seq):
                items = args[0].items
                return tuple(Seq((i, item)) for i, item in enumerate(items)) \
                    if len(items) <= MAX_UNROLL else None
            return None
        value = self.eval(expr, frame)
        if isinstance(value, Seq) and len(value.items) <= MAX_UNROLL:
            return value.items
        return None

    # -- classes ------------------------------------------------------------------------

    def bases(self, cls: ClassInfo) -> list[object]:
        if cls.bases is None:
            cls.bases = []
            cls.bases = [self.eval(b, Frame(cls.module)) for b in cls.node.bases]
        return cls.bases

    def mro(self, cls: ClassInfo, seen: frozenset[int] = frozenset()) -> Iterator[ClassInfo]:
        if id(cls) in seen:
            return
        yield cls
        for base in self.bases(cls):
            if isinstance(base, ClassInfo):
                yield from self.mro(base, seen | {id(cls)})

    def is_node_class(self, cls: ClassInfo) -> bool:
        return any(isinstance(b, Ref) and b.key in rclpy.NODE_CLASSES
                   for c in self.mro(cls) for b in self.bases(c))

    def method(self, cls: ClassInfo, name: str) -> FunctionInfo | None:
        for c in self.mro(cls):
            if name in c.methods:
                return c.methods[name]
        return None

    def class_attrs(self, cls: ClassInfo) -> dict[str, object]:
        """Attributes an object of ``cls`` has after ``__init__``, arguments unknown."""
        if cls.attrs is None:
            cls.attrs = {}
            attrs: dict[str, object] = {}
            for c in reversed(list(self.mro(cls))):
                for key, expr in c.constants.items():
                    attrs[key] = self.eval(expr, Frame(c.module))
            init = self.method(cls, "__init__")
            if init is not None:
                instance = Instance(cls, attrs)
                frame = Frame(init.module, unknown_params(init), instance)
                seen: dict[str, object] = {}
                for statement in _straight(init.node.body):
                    self.assign(statement, frame, seen)
            cls.attrs = attrs
        return cls.attrs

    def new(self, cls: ClassInfo) -> Instance:
        return Instance(cls, dict(self.class_attrs(cls)))

    def construct(self, cls: ClassInfo, expr: ast.Call, frame: Frame) -> Instance:
        """An object of ``cls`` whose ``__init__`` assignments see the call's arguments."""
        instance = self.new(cls)
        init = self.method(cls, "__init__")
        if init is not None and frame.depth < MAX_CALL_DEPTH:
            inner = self.call_frame(BoundMethod(instance, init), expr, frame)
            seen: dict[str, object] = {}
            for statement in _straight(init.node.body):
                self.assign(statement, inner, seen)
        return instance

    def assign(self, statement: ast.stmt, frame: Frame,
               seen: dict[str, object] | None = None) -> None:
        """Bind the targets of an assignment; attributes assigned two different values
        (on two branches) become opaque when ``seen`` tracks them."""
        if isinstance(statement, ast.AugAssign):
            if isinstance(statement.target, ast.Name | ast.Attribute):
                load = ast.copy_location(ast.BinOp(_load(statement.target), statement.op,
                                                   statement.value), statement)
                self.bind(statement.target, self.eval(load, frame), frame, seen)
            return
        if isinstance(statement, ast.Assign):
            targets, expr = statement.targets, statement.value
        elif isinstance(statement, ast.AnnAssign) and statement.value is not None:
            targets, expr = [statement.target], statement.value
        else:
            return
        value = self.eval(expr, frame)
        for target in targets:
            self.bind(target, value, frame, seen)

    def bind(self, target: ast.expr, value: object, frame: Frame,
             seen: dict[str, object] | None = None) -> None:
        if isinstance(target, ast.Name):
            frame.locals[target.id] = value
        elif isinstance(target, ast.Attribute) and isinstance(target.value, ast.Name) \
                and target.value.id == "self" and frame.instance is not None:
            if seen is not None:
                if target.attr in seen and seen[target.attr] != value:
                    value = Opaque(f"self.{target.attr}")
                seen[target.attr] = value
            frame.instance.attrs[target.attr] = value
        elif isinstance(target, ast.Tuple | ast.List):
            items = value.items if isinstance(value, Seq) and len(value.items) == len(
                target.elts) else (Opaque(),) * len(target.elts)
            for element, item in zip(target.elts, items, strict=False):
                self.bind(element, item, frame, seen)

    # -- expressions --------------------------------------------------------------------

    def eval(self, expr: ast.expr, frame: Frame) -> object:
        if self.depth > MAX_EVAL_DEPTH:
            return Opaque("too deep")
        self.depth += 1
        try:
            handler = getattr(self, "_" + type(expr).__name__, None)
            return handler(expr, frame) if handler else Opaque(type(expr).__name__)
        finally:
            self.depth -= 1

    def _Constant(self, expr: ast.Constant, frame: Frame) -> object:
        if isinstance(expr.value, str):
            return Value.of(expr.value)
        if isinstance(expr.value, bool | int | float) or expr.value is None:
            return expr.value
        return Opaque("constant")

    def _JoinedStr(self, expr: ast.JoinedStr, frame: Frame) -> object:
        parts: list[Value | str] = []
        for part in expr.values:
            if isinstance(part, ast.Constant) and isinstance(part.value, str):
                parts.append(part.value)
            elif isinstance(part, ast.FormattedValue) and part.format_spec is None:
                parts.append(text_of(self.eval(part.value, frame)))
            else:
                parts.append(Value.unknown("formatted value"))
        return Value.of(*parts)

    def _BinOp(self, expr: ast.BinOp, frame: Frame) -> object:
        left, right = self.eval(expr.left, frame), self.eval(expr.right, frame)
        if isinstance(expr.op, ast.Add):
            if isinstance(left, Value) or isinstance(right, Value):
                return Value.of(text_of(left), text_of(right))
            if number(left) and number(right):
                return left + right  # type: ignore[operator]
            if isinstance(left, Seq) and isinstance(right, Seq):
                return Seq(left.items + right.items)
        if isinstance(expr.op, ast.Mod) and isinstance(left, Value):
            items = right.items if isinstance(right, Seq) else (right,)
            return percent(left, items)
        if isinstance(expr.op, ast.Mult | ast.Sub | ast.Div) and number(left) and number(right):
            try:
                return arith(expr.op, left, right)
            except (ZeroDivisionError, OverflowError):
                return Opaque("arithmetic")
        return Opaque("operation")

    def _Name(self, expr: ast.Name, frame: Frame) -> object:
        return self.name(expr.id, frame)

    def _Tuple(self, expr: ast.Tuple, frame: Frame) -> object:
        return Seq(tuple(self.eval(e, frame) for e in expr.elts))

    _List = _Tuple

    def _Subscript(self, expr: ast.Subscript, frame: Frame) -> object:
        base = self.eval(expr.value, frame)
        index = self.eval(expr.slice, frame)
        if isinstance(base, Seq) and isinstance(index, int) and -len(base.items) <= index < len(
                base.items):
            return base.items[index]
        return Opaque("subscript")

    def _Attribute(self, expr: ast.Attribute, frame: Frame) -> object:
        base = self.eval(expr.value, frame)
        return self.attribute(base, expr.attr, frame)

    def attribute(self, base: object, attr: str, frame: Frame) -> object:
        if isinstance(base, Ref):
            return Ref(f"{base.qualname}.{attr}")
        if isinstance(base, ModuleRef):
            found = self.lookup(base.module, attr)
            inner = submodule(base.module.path, attr) if isinstance(found, Opaque) else None
            other = self.loader.load(inner) if inner is not None else None
            return ModuleRef(other) if other is not None else found
        if isinstance(base, Instance):
            if attr in base.attrs:
                return base.attrs[attr]
            method = self.method(base.cls, attr)
            if method is not None:
                return BoundMethod(base, method)
            if (attr in rclpy.NODE_METHODS or attr in NAME_METHODS
                    or attr == "get_namespace") and self.is_node_class(base.cls):
                return NodeMethod(attr, owner=base)
            return Opaque(f"self.{attr}")
        if isinstance(base, ClassInfo):
            for c in self.mro(base):
                if attr in c.constants:
                    return self.eval(c.constants[attr], Frame(c.module))
                if attr in c.methods:
                    return c.methods[attr]
            return Opaque(attr)
        if isinstance(base, ParameterClient) and attr in rclpy.NODE_METHODS:
            return NodeMethod(attr, base.remote)
        if isinstance(base, NodeHandle) and (attr in rclpy.NODE_METHODS or attr in NAME_METHODS
                                             or attr == "get_namespace"):
            return NodeMethod(attr, owner=base)
        if isinstance(base, ParamObject):
            if attr in ("value", "string_value", "integer_value", "double_value",
                        "bool_value"):
                return ParamValue(base.name, base.default)
            if attr == "get_parameter_value":
                return base
        if isinstance(base, Opaque | Value | type(None)) and attr in rclpy.NODE_METHODS \
                and frame.module.version == 2:
            return NodeMethod(attr)
        return Opaque(attr)

    def _Call(self, expr: ast.Call, frame: Frame) -> object:
        func = self.callee(expr.func, frame)
        if isinstance(func, ParamObject):  # get_parameter_value()
            return func
        if isinstance(func, Ref):
            return self._call_ref(func, expr, frame)
        if isinstance(func, NodeMethod):
            return self._node_method(func.name, expr, frame)
        if isinstance(func, ClassInfo):
            return self.construct(func, expr, frame)
        if isinstance(func, FunctionInfo | BoundMethod):
            return self.returned(func, expr, frame)
        if isinstance(expr.func, ast.Attribute) and isinstance(func, Opaque):
            base = self.eval(expr.func.value, frame)
            if isinstance(base, Value):
                return string_method(base, expr.func.attr, [
                    self.eval(a, frame) for a in expr.args])
        if isinstance(expr.func, ast.Name) and expr.func.id in ("str", "int", "float") \
                and len(expr.args) == 1:
            value = self.eval(expr.args[0], frame)
            if expr.func.id == "str":
                return text_of(value)
            return value if number(value) else Opaque(expr.func.id)
        return Opaque("call")

    def callee(self, func: ast.expr, frame: Frame) -> object:
        """What a call's function expression names."""
        if isinstance(func, ast.Attribute) and func.attr == "__init__":
            inner = func.value
            if isinstance(inner, ast.Call) and isinstance(inner.func, ast.Name) \
                    and inner.func.id == "super":
                return SuperInit()
            base = self.eval(inner, frame)
            if isinstance(base, Ref) and base.key in rclpy.NODE_CLASSES:
                return SuperInit()
        return self.eval(func, frame)

    def _call_ref(self, ref: Ref, expr: ast.Call, frame: Frame) -> object:
        key = ref.key
        if key in rclpy.NODE_NAMES:
            spec = rclpy.NODE_NAMES[key]
            found = argument(expr, spec.name)
            return NodeHandle(self.eval(found, frame) if found is not None else None)
        if key in (("rospy", "get_param"), ("rospy", "get_param_cached")):
            name = argument(expr, rospy.ROWS[key].name)
            default = argument(expr, rospy.ROWS[key].value)
            value = ParamValue(text_of(self.eval(name, frame)).text if name else "?",
                               self.eval(default, frame) if default is not None else None)
            self.param_defaults[value.name] = value.default
            return value
        if key == ("rospy", "get_name") and not expr.args:
            return Value.of("~")  # the node's own name: private names resolve to it
        if key == ("rospy", "get_namespace") and not expr.args:
            return Value.unknown(NAMESPACE)  # relative names resolve in it
        if key == ("rclpy", "AsyncParameterClient"):
            remote = argument(expr, rclpy.PARAMETER_CLIENT)
            return ParameterClient(text_of(self.eval(remote, frame)) if remote is not None
                                   else Value.unknown("remote node"))
        if key == ("rclpy", "QoSProfile"):
            return self.qos_profile(expr, frame)
        return Opaque(ref.qualname)

    def _node_method(self, name: str, expr: ast.Call, frame: Frame) -> object:
        if name in NAME_METHODS and not expr.args:
            return Value.of("~")  # the node's own name: as rospy.get_name()
        if name == "get_namespace" and not expr.args:
            return Value.unknown(NAMESPACE)
        if name in ("get_parameter", "declare_parameter", "get_parameter_or"):
            found = argument(expr, rclpy.NODE_METHODS[name].name)
            text = text_of(self.eval(found, frame)).text if found is not None else "?"
            default: object = self.declared.get(text)
            value = argument(expr, rclpy.NODE_METHODS[name].value)
            if value is not None:
                default = self.eval(value, frame)
            self.param_defaults[text] = default
            return ParamObject(text, default)
        return Opaque(name)

    def returned(self, func: FunctionInfo | BoundMethod, expr: ast.Call, frame: Frame) -> object:
        """What a helper returns, when its body is straight-line code ending in return."""
        if frame.depth >= MAX_CALL_DEPTH:
            return Opaque("call depth")
        inner = self.call_frame(func, expr, frame)
        info = func.function if isinstance(func, BoundMethod) else func
        for statement in info.node.body:
            if isinstance(statement, ast.Return):
                return self.eval(statement.value, inner) if statement.value else None
            if isinstance(statement, ast.Assign | ast.AnnAssign):
                self.assign(statement, inner)
            elif not isinstance(statement, ast.Expr | ast.Pass):
                break
        return Opaque(f"{info.qualname}()")

    def call_frame(self, func: FunctionInfo | BoundMethod, expr: ast.Call,
                   frame: Frame) -> Frame:
        """A frame for the body of ``func`` with the call's arguments bound."""
        info = func.function if isinstance(func, BoundMethod) else func
        instance = func.instance if isinstance(func, BoundMethod) else None
        values = [self.eval(a, frame) for a in expr.args if not isinstance(a, ast.Starred)]
        starred = any(isinstance(a, ast.Starred) for a in expr.args)
        keywords = {k.arg: self.eval(k.value, frame) for k in expr.keywords if k.arg}
        return Frame(info.module, self.bind_arguments(info, values, keywords, starred,
                                                      skip_self=instance is not None),
                     instance, frame.depth + 1)

    def bind_arguments(self, info: FunctionInfo, values: list[object],
                       keywords: dict[str, object], starred: bool,
                       skip_self: bool) -> dict[str, object]:
        args = info.node.args
        params = [*args.posonlyargs, *args.args]
        if skip_self and params:
            params = params[1:]
        bound: dict[str, object] = dict(info.closure or {})
        defaults = args.defaults
        first_default = len(params) - len(defaults)
        home = Frame(info.module)
        for i, param in enumerate(params):
            if i < len(values) and not starred:
                bound[param.arg] = values[i]
            elif param.arg in keywords:
                bound[param.arg] = keywords[param.arg]
            elif i >= first_default and not starred:
                bound[param.arg] = self.eval(defaults[i - first_default], home)
            else:
                bound[param.arg] = Opaque(f"argument {param.arg}")
        for param, default in zip(args.kwonlyargs, args.kw_defaults, strict=False):
            if param.arg in keywords:
                bound[param.arg] = keywords[param.arg]
            elif default is not None:
                bound[param.arg] = self.eval(default, home)
            else:
                bound[param.arg] = Opaque(f"argument {param.arg}")
        return bound

    # -- QoS ----------------------------------------------------------------------------

    def qos(self, value: object) -> dict[str, Any] | None:
        if isinstance(value, bool):
            return None
        if isinstance(value, int):
            return {**rclpy.DEFAULT_QOS, "depth": value}
        if isinstance(value, QoS):
            return value.as_dict()
        if isinstance(value, Ref):
            parts = value.qualname.split(".")
            if parts[-1] in rclpy.PRESETS:
                return dict(rclpy.PRESETS[parts[-1]])
            if len(parts) >= 2 and parts[-1] == "value" and parts[-2] in rclpy.PRESET_ENUM:
                return dict(rclpy.PRESETS[rclpy.PRESET_ENUM[parts[-2]]])
        return None

    def qos_profile(self, expr: ast.Call, frame: Frame) -> QoS:
        policies: dict[str, Any] = dict(rclpy.DEFAULT_QOS)
        for keyword in expr.keywords:
            if keyword.arg == "depth":
                depth = self.eval(keyword.value, frame)
                policies["depth"] = depth if isinstance(depth, int) else None
            elif keyword.arg in rclpy.POLICIES:
                policies[keyword.arg] = _policy(self.eval(keyword.value, frame),
                                                rclpy.POLICIES[keyword.arg])
            elif keyword.arg is None:
                base = self.qos(self.eval(keyword.value, frame))
                if base:
                    policies.update(base)
        return QoS(tuple(policies.items()))


def argument(call: ast.Call, arg: object) -> ast.expr | None:
    """The expression given for ``arg`` (an ``api.Arg``) in ``call``, if any."""
    index, keyword = getattr(arg, "index", None), getattr(arg, "keyword", None)
    if keyword is not None:
        for k in call.keywords:
            if k.arg == keyword:
                return k.value
    if index is not None:
        for i, a in enumerate(call.args):
            if isinstance(a, ast.Starred):
                return None
            if i == index:
                return a
    return None


def unknown_params(info: FunctionInfo) -> dict[str, object]:
    args = info.node.args
    names = [a.arg for a in (*args.posonlyargs, *args.args, *args.kwonlyargs)]
    if info.cls is not None and names:
        names = names[1:]
    return {**(info.closure or {}), **{n: Opaque(f"argument {n}") for n in names}}


def _straight(body: list[ast.stmt]) -> Iterator[ast.stmt]:
    """Assignments of a body, into if/try/with blocks too, in source order."""
    for statement in body:
        if isinstance(statement, ast.Assign | ast.AnnAssign | ast.AugAssign):
            yield statement
        elif isinstance(statement, ast.If | ast.With | ast.Try):
            for block in ("body", "orelse", "finalbody"):
                yield from _straight(getattr(statement, block, []))
            for handler in getattr(statement, "handlers", []):
                yield from _straight(handler.body)


def _load(target: ast.Name | ast.Attribute) -> ast.expr:
    if isinstance(target, ast.Name):
        return ast.Name(target.id, ast.Load())
    return ast.Attribute(target.value, target.attr, ast.Load())


def _policy(value: object, words: tuple[str, ...]) -> str | None:
    """``ReliabilityPolicy.BEST_EFFORT`` (or its older spellings) -> ``best_effort``."""
    if isinstance(value, Ref):
        last = value.qualname.split(".")[-1].lower()
        for word in sorted(words, key=len, reverse=True):
            if last == word or last.endswith("_" + word):
                return word
    if isinstance(value, Value) and value.literal in words:
        return value.literal
    return None


