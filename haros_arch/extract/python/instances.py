"""Objects of the package's classes: their bases and method resolution order, whether
they are rclpy nodes, the attributes ``__init__`` gives them, and the binding of
assignments (to locals, ``self.x`` attributes, tuples).
"""

from __future__ import annotations

import ast
from collections.abc import Iterator

from ...model.values import Unknown
from . import rclpy
from .calls import MAX_CALL_DEPTH, Calls, unknown_params
from .modules import ClassInfo, FunctionInfo
from .objects import BoundMethod, Frame, Instance, Record, Ref, Seq
from .qos import as_profile, with_policy


class Instances(Calls):
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

    def is_lifecycle_class(self, cls: ClassInfo) -> bool:
        """A subclass of rclpy's managed node (``rclpy.lifecycle.Node`` /
        ``LifecycleNode``), which serves its state machine by itself."""
        return any(isinstance(b, Ref) and b.qualname.startswith(rclpy.LIFECYCLE_MODULE)
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
            self._initialised(init, self.call_frame(BoundMethod(instance, init), expr, frame))
        return instance

    def _initialised(self, init: FunctionInfo, frame: Frame) -> None:
        """The assignments of ``init``'s body to the object of ``frame``, and, in their
        place among them, those of a base class's ``__init__`` it calls on that object
        (``super().__init__(...)``, ``Base.__init__(self, ...)``) with the call's
        arguments: svea's ``SVEAPurePursuit.__init__`` hands its vehicle name to
        ``SVEAManager.__init__``, which builds the interfaces named by it."""
        seen: dict[str, object] = {}
        for statement in _straight(init.node.body, base_inits=True):
            if not isinstance(statement, ast.Expr):
                self.assign(statement, frame, seen)
                continue
            call = statement.value
            assert isinstance(call, ast.Call)
            base = self.callee(call.func, frame) if frame.depth < MAX_CALL_DEPTH else None
            if isinstance(base, FunctionInfo | BoundMethod):
                inner = self.call_frame(base, call, frame)
                info = base.function if isinstance(base, BoundMethod) else base
                if inner.instance is frame.instance and info.node is not init.node:
                    self._initialised(info, inner)

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
                    value = Unknown(f"self.{target.attr}")
                seen[target.attr] = value
            frame.instance.attrs[target.attr] = value
        elif isinstance(target, ast.Attribute) and (
                target.attr == "depth" or target.attr in rclpy.POLICIES) and (
                holder := as_profile(self.eval(target.value, frame))) is not None:
            # a policy set on a profile held by a local or an attribute of ``self`` (a
            # preset too: ``qos = qos_profile_sensor_data`` then ``qos.reliability = ..``)
            changed = with_policy(holder, target.attr, value)
            if changed is not None:
                self.bind(target.value, changed, frame, seen)
        elif isinstance(target, ast.Subscript) and (isinstance(target.value, ast.Name) or (
                isinstance(target.value, ast.Attribute)
                and isinstance(target.value.value, ast.Name) and target.value.value.id == "self")
        ) and isinstance(self.eval(target.value, frame), Seq | Record):
            # an item of a list or dict set (``topics[0] = '/scan'``): what the walk
            # knew of the whole is no longer
            self.bind(target.value, Unknown("changed in place"), frame, seen)
        elif isinstance(target, ast.Tuple | ast.List):
            items = value.items if isinstance(value, Seq) and len(value.items) == len(
                target.elts) else (Unknown(),) * len(target.elts)
            for element, item in zip(target.elts, items, strict=False):
                self.bind(element, item, frame, seen)


def _straight(body: list[ast.stmt], base_inits: bool = False) -> Iterator[ast.stmt]:
    """Assignments of a body, into if/try/with blocks too, in source order; with
    ``base_inits`` also the statements that call an ``__init__`` (``super().__init__(...)``,
    ``Base.__init__(self, ...)``)."""
    for statement in body:
        if isinstance(statement, ast.Assign | ast.AnnAssign | ast.AugAssign) or (
                base_inits and _calls_init(statement)):
            yield statement
        elif isinstance(statement, ast.If | ast.With | ast.Try):
            for block in ("body", "orelse", "finalbody"):
                yield from _straight(getattr(statement, block, []), base_inits)
            for handler in getattr(statement, "handlers", []):
                yield from _straight(handler.body, base_inits)

def _calls_init(statement: ast.stmt) -> bool:
    """A statement that calls an ``__init__``: ``super().__init__(...)``, ``B.__init__(...)``."""
    return isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Call) and \
        isinstance(statement.value.func, ast.Attribute) and statement.value.func.attr == "__init__"


def _load(target: ast.Name | ast.Attribute) -> ast.expr:
    if isinstance(target, ast.Name):
        return ast.Name(target.id, ast.Load())
    return ast.Attribute(target.value, target.attr, ast.Load())
