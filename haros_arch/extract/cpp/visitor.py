"""Finding roscpp calls in a parsed translation unit.

Every function defined in the workspace's own files is walked with the stack of control
statements around each expression (``conditions.ConditionReader``); a call whose target
is a row of ``api.ROSCPP`` becomes a ``PrimitiveCall``. A call's location is the line
and column of the called function's name (``advertise`` in ``n.advertise<M>(...)``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from clang.cindex import Cursor, CursorKind, TranslationUnit

from ... import diagnostics as diag
from ...diagnostics import Diagnostic
from ...model.conditions import Condition
from ...model.location import Location
from ...model.source import PrimitiveCall
from . import api, msg_types
from .conditions import ConditionReader
from .values import UNKNOWN, Parts, Scope, render, strip, written_arguments

_CONTAINERS = frozenset({
    CursorKind.NAMESPACE, CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL,
    CursorKind.CLASS_TEMPLATE, CursorKind.LINKAGE_SPEC, CursorKind.UNEXPOSED_DECL,
    CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION,
})
_FUNCTIONS = frozenset({
    CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD, CursorKind.CONSTRUCTOR,
    CursorKind.DESTRUCTOR, CursorKind.FUNCTION_TEMPLATE, CursorKind.CONVERSION_FUNCTION,
})
_SCOPES = _CONTAINERS | {CursorKind.CLASS_TEMPLATE}
_API_NAMES = frozenset(name for _, name in [*api.ROSCPP, *api.NODE_NAME])
MAX_DEPTH = 16


def qualified_name(cursor: Cursor | None) -> str:
    """``ros::NodeHandle`` for the NodeHandle class declaration, and so on."""
    parts: list[str] = []
    while cursor is not None and cursor.kind in _SCOPES:
        if cursor.spelling:
            parts.append(cursor.spelling)
        cursor = cursor.semantic_parent
    return "::".join(reversed(parts))


def join_name(namespace: str, name: str) -> str:
    """A name as seen from a handle in ``namespace`` (``~`` private, ``""`` the node's)."""
    if not namespace or name.startswith(("/", "~")):
        return name
    if namespace == "~" or namespace.endswith("/"):
        return namespace + name
    return f"{namespace}/{name}"


def _normalise(namespace: str) -> str:
    if namespace.startswith("~/"):
        namespace = "~" + namespace[2:]
    return namespace.rstrip("/") if len(namespace) > 1 else namespace


class CallFinder:
    """Collects the primitive calls and the node name of one translation unit."""

    def __init__(self, tu: TranslationUnit, source: dict[str, bytes],
                 owned: Callable[[str], bool], where: Callable[[Cursor], Location]) -> None:
        self.tu = tu
        self.source = source
        self.owned = owned
        self.where = where
        self.reader = ConditionReader(source, where)
        self.macros: dict[str, str] = {}
        self.calls: list[PrimitiveCall] = []
        self.rosname: str | None = None
        self.diagnostics: list[Diagnostic] = []

    def run(self) -> None:
        functions = list(self._definitions(self.tu.cursor, top=True))
        for function in functions:
            self._function(function)

    def _definitions(self, parent: Cursor, top: bool = False) -> Iterator[Cursor]:
        for cursor in parent.get_children():
            where = cursor.location.file
            if where is None or not self.owned(where.name):
                continue
            kind = cursor.kind
            if kind == CursorKind.MACRO_DEFINITION:
                tokens = [t.spelling for t in cursor.get_tokens()]
                if len(tokens) == 2:
                    self.macros[tokens[0]] = tokens[1]
            elif kind in _FUNCTIONS and cursor.is_definition():
                yield cursor
            elif kind in _CONTAINERS:
                yield from self._definitions(cursor)

    def _function(self, function: Cursor) -> None:
        scope = Scope(function, self.macros, self.source)
        stack: list[tuple[Cursor, tuple[Condition, ...]]] = [
            (child, ()) for child in reversed(list(function.get_children()))
            if child.kind != CursorKind.PARM_DECL]
        while stack:
            node, conditions = stack.pop()
            if node.kind == CursorKind.CALL_EXPR and node.spelling in _API_NAMES:
                self._call(node, conditions, scope)
            branches = self.reader.branches(node)
            stack.extend((child, conditions + extra) for child, extra in reversed(branches))

    # -- one call ---------------------------------------------------------------------

    def _call(self, call: Cursor, conditions: tuple[Condition, ...], scope: Scope) -> None:
        target = call.referenced
        if target is None:
            return
        key = (qualified_name(target.semantic_parent), target.spelling)
        args = written_arguments(call)
        if key in api.NODE_NAME:
            index = api.NODE_NAME[key].get(len(args))
            if index is not None:
                self.rosname = render(scope.string(args[index]))
            return
        spec = api.ROSCPP.get(key)
        if spec is None or len(args) <= spec.name_arg:
            return
        location = self.where(self._callee(call))
        name = render(scope.string(args[spec.name_arg]))
        if spec.on_handle:
            name = join_name(render(self._handle(call, scope)), name)
        callback = _callback(args, spec.callback_arg)
        self.calls.append(PrimitiveCall(
            kind=spec.kind,
            name=name,
            type=self._type(spec, call, args, callback),
            queue_size=(scope.integer(args[spec.queue_arg])
                        if spec.queue_arg is not None and spec.queue_arg < len(args) else None),
            latch=(spec.latch_arg is not None and spec.latch_arg < len(args)
                   and scope.boolean(args[spec.latch_arg]) is True),
            callback=_callback_name(callback),
            conditions=conditions,
            location=location,
        ))
        if "?" in name:
            self.diagnostics.append(diag.make(
                "CPP_DYNAMIC_NAME", location, kind=spec.kind, name=name))

    @staticmethod
    def _callee(call: Cursor) -> Cursor:
        children = list(call.get_children())
        return strip(children[0]) if children else call

    def _type(self, spec: api.RosFunction, call: Cursor, args: list[Cursor],
              callback: Cursor | None) -> str | None:
        for source in spec.type_from:
            found: str | None = None
            if source in ("template", "template-value"):
                ref = self._template_argument(call)
                if ref is not None:
                    found = (msg_types.message_type(ref.type) if source == "template"
                             else msg_types.param_type(ref.type))
            elif source in ("callback", "service-callback") and callback is not None:
                params = _parameters(callback)
                if params:
                    found = msg_types.message_type(params[0], source == "service-callback")
            elif source in ("arg", "value") and spec.type_arg is not None and (
                spec.type_arg < len(args)
            ):
                ctype = strip(args[spec.type_arg]).type
                found = (msg_types.message_type(ctype) if source == "arg"
                         else msg_types.param_type(ctype))
            if found is not None:
                return found
        return None

    def _template_argument(self, call: Cursor) -> Cursor | None:
        """The first type written as a template argument of the called function."""
        callee = self._callee(call)
        for child in callee.get_children():
            if child.kind == CursorKind.TYPE_REF:
                return child
        return None

    # -- node handles -----------------------------------------------------------------

    def _handle(self, call: Cursor, scope: Scope) -> Parts:
        """The namespace of the NodeHandle a member call is made on."""
        callee = self._callee(call)
        if callee.kind != CursorKind.MEMBER_REF_EXPR:
            return UNKNOWN
        objects = [c for c in callee.get_children() if c.kind.is_expression()]
        if not objects:  # implicit this->: a member function of NodeHandle itself
            return UNKNOWN
        return self._namespace(objects[0], scope, 0)

    def _namespace(self, expr: Cursor, scope: Scope, depth: int) -> Parts:
        expr = strip(expr)
        if depth > MAX_DEPTH:
            return UNKNOWN
        if expr.kind == CursorKind.DECL_REF_EXPR:
            decl = expr.referenced
            if decl is None or decl.kind != CursorKind.VAR_DECL:
                return UNKNOWN
            value = scope.variable(decl)
            return UNKNOWN if value is None else self._namespace(value, scope, depth + 1)
        if expr.kind == CursorKind.MEMBER_REF_EXPR and expr.referenced is not None:
            value = _member_initialiser(expr.referenced)
            if value is None:
                return ("",)  # a member no constructor initialises: the default handle
            return self._namespace(value, Scope(None, self.macros, self.source), depth + 1)
        if expr.kind == CursorKind.UNARY_OPERATOR:  # *pointer
            inner = [c for c in expr.get_children() if c.kind.is_expression()]
            return self._namespace(inner[0], scope, depth + 1) if inner else UNKNOWN
        if expr.kind != CursorKind.CALL_EXPR:
            return UNKNOWN
        target = expr.referenced
        if target is None:
            inner = [c for c in expr.get_children() if c.kind.is_expression()]
            return self._namespace(inner[-1], scope, depth + 1) if inner else UNKNOWN
        factory = (qualified_name(target.semantic_parent), target.spelling)
        if factory in api.HANDLE_FACTORIES:
            return (api.HANDLE_FACTORIES[factory],)
        if target.kind != CursorKind.CONSTRUCTOR or (
            qualified_name(target.semantic_parent) not in api.HANDLE_CLASSES
        ):
            return UNKNOWN
        args = written_arguments(expr)
        if not args:
            return ("",)
        if _is_handle(args[0]):
            parent = render(self._namespace(args[0], scope, depth + 1))
            if len(args) == 1:
                return (parent,)
            child = render(scope.string(args[1]))
            return (_normalise(join_name(parent, child)) if parent else _normalise(child),)
        return (_normalise(render(scope.string(args[0]))),)


def _is_handle(expr: Cursor) -> bool:
    decl = expr.type.get_canonical().get_declaration()
    return qualified_name(decl) in api.HANDLE_CLASSES


def _member_initialiser(field: Cursor) -> Cursor | None:
    """What the constructors of ``field``'s class initialise or assign it with."""
    owner = field.semantic_parent
    if owner is None:
        return None
    for member in owner.get_children():
        if member.kind != CursorKind.CONSTRUCTOR:
            continue
        definition = member.get_definition()
        if definition is None:
            continue
        children = list(definition.get_children())
        for i, child in enumerate(children[:-1]):
            if child.kind == CursorKind.MEMBER_REF and child.referenced == field:
                return children[i + 1]
        for node in definition.walk_preorder():
            if node.kind == CursorKind.CALL_EXPR and node.spelling == "operator=":
                args = list(node.get_arguments())
                if len(args) == 2 and strip(args[0]).kind == CursorKind.MEMBER_REF_EXPR and (
                    strip(args[0]).referenced == field
                ):
                    return args[1]
    return None


def _callback(args: list[Cursor], index: int | None) -> Cursor | None:
    """The function, method or lambda a callback argument names, where cheap."""
    if index is None or index >= len(args):
        return None
    return _callable(args[index], 0)


def _callable(expr: Cursor, depth: int) -> Cursor | None:
    expr = strip(expr)
    if depth > 6:
        return None
    if expr.kind == CursorKind.DECL_REF_EXPR and expr.referenced is not None and (
        expr.referenced.kind in _FUNCTIONS
    ):
        return expr.referenced
    if expr.kind == CursorKind.LAMBDA_EXPR:
        return expr
    if expr.kind == CursorKind.UNARY_OPERATOR:  # &Class::method
        inner = [c for c in expr.get_children() if c.kind.is_expression()]
        return _callable(inner[0], depth + 1) if inner else None
    if expr.kind == CursorKind.CALL_EXPR:
        # boost::function<...>(f), boost::bind(&Class::method, this, _1)
        for arg in written_arguments(expr):
            found = _callable(arg, depth + 1)
            if found is not None:
                return found
        inner = [c for c in expr.get_children() if c.kind.is_expression()]
        if expr.referenced is None and len(inner) == 1:
            return _callable(inner[0], depth + 1)
    return None


def _callback_name(callback: Cursor | None) -> str | None:
    if callback is None or callback.kind == CursorKind.LAMBDA_EXPR:
        return None
    if callback.kind == CursorKind.CXX_METHOD:
        return f"{qualified_name(callback.semantic_parent).split('::')[-1]}::{callback.spelling}"
    return callback.spelling


def _parameters(callback: Cursor) -> list:
    if callback.kind == CursorKind.LAMBDA_EXPR:
        return [c.type for c in callback.get_children() if c.kind == CursorKind.PARM_DECL]
    return list(callback.type.argument_types())
