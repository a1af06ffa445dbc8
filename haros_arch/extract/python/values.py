"""Static values of Python expressions: what a name, type or QoS argument holds.

``Evaluator.eval(expr, frame)`` never runs code. Strings are ``Value``s whose unknown
parts print as ``?`` (f-strings, ``+``, ``%`` and ``str.format`` keep every known part);
numbers, booleans and None are themselves; imported things are ``Ref``s to their
qualified name; parameter reads are ``ParamValue``s (a name that is a parameter's value);
rclpy nodes are ``NodeHandle``s; objects of classes of the package are ``Instance``s
whose attributes come from ``__init__``; anything else is ``Unknown``.
Helper functions whose body is straight-line code ending in ``return`` are evaluated
with their arguments bound, a few calls deep.

The evaluator's parts: ``scopes`` (names and loops), ``calls`` (argument binding),
``instances`` (classes and their objects), ``qos`` (rclpy QoS); here, expressions.
"""

from __future__ import annotations

import ast
import dataclasses
from dataclasses import replace
from typing import Any, NoReturn

from ...evaluate import budget
from ...evaluate import operations as ops
from ...evaluate.python import BUILTINS, Walker, evaluate_counted
from ...model.conditions import Condition
from ...model.values import UNKNOWN_MARK, Unknown, Value
from . import msg_types, rclpy, rospy
from .api import Arg
from .calls import MAX_CALL_DEPTH, argument, unknown_params
from .conditions import condition, tested_text
from .instances import Instances
from .modules import ClassInfo, FunctionInfo, Loader, submodule
from .objects import (
    MAX_ALTERNATIVES,
    Alternatives,
    ArgParser,
    BoundMethod,
    Frame,
    Instance,
    ModuleRef,
    NewParameter,
    NodeHandle,
    NodeMethod,
    ParamElement,
    ParameterClient,
    ParamObject,
    ParamTurn,
    ParamValue,
    ProgramArgs,
    ProgramOptions,
    Record,
    Ref,
    Seq,
    SuperInit,
    returned_alternative,
    same_value,
    text_of,
)
from .qos import QoSProfiles
from .scopes import MAX_UNROLL
from .strings import from_plain, number, percent, plain, string_method

__all__ = ["FULL_NAME", "MAX_CALL_DEPTH", "MAX_UNROLL", "NAMESPACE", "NODE_NAME", "RESOLVED",
           "Evaluator", "argument", "own_name", "unknown_params"]

MAX_EVAL_DEPTH = 60
MAX_RECORD = 64  # entries of a dict literal kept (``Record``)
# the one evaluator's bounds for the values of one walk (a node's files); steps: every
# expression evaluated, helpers' bodies and folded constructs included
LIMITS = ops.Limits(steps=500_000)
# methods of an rclpy node that give its own name; in a name they are the private '~'
NAME_METHODS = ("get_name", "get_fully_qualified_name")
NAMESPACE = "node namespace"  # origin of the unknown get_namespace() gives


def in_namespace(text: Value, version: int = 1) -> Value:
    """``f"{get_namespace()}/x"`` is the relative name ``x``: it resolves in the node's
    namespace (rospy's namespace ends in '/', rclpy's does not). So is the parameter a
    read of that name gives its value of (rbx1's relax_all_servos.py walks the value of
    ``get_param(rospy.get_namespace() + '/joints', '')``). rclpy's (``version`` 2)
    ``f"{get_namespace()}/{get_name()}/x"`` is the node's fully qualified name and what
    follows: it is then written as starting with the node's own name (``own_name``)."""
    parts = text.parts
    if len(parts) < 2 or not isinstance(parts[0], Unknown) or parts[0].origin != NAMESPACE \
            or not isinstance(parts[1], str):
        return text
    if parts[1].strip("/"):
        return Value.of(parts[1].lstrip("/"), *parts[2:])
    if version == 2 and parts[1] == "/" and len(parts) >= 3 and isinstance(
            parts[2], Unknown) and parts[2].origin == NODE_NAME:
        return Value.of(*parts[2:])
    return text


# origin of what rospy.resolve_name(name) gives, the name written after it: a known name,
# resolved and remapped at run time (``visitor._resolved``)
RESOLVED = "resolved name "
NODE_NAME = "node name"  # origin of the unknown get_name() gives (see own_name)
# origin of the unknown rclpy's get_fully_qualified_name() gives: the node's own name as
# rospy's get_name() is (``NODE_NAME``), but never its name without the namespace, which
# is what rclpy's get_name() gives (``PrimitiveCall.name_self``)
FULL_NAME = "node fully qualified name"


SEARCHED = "found by search_param: "  # origin of the name rospy.search_param(x) gives


def search_start(key: str) -> str:
    """The name of a key rospy.search_param looks for: rospy asks the master to search
    from the caller's own name up, so a relative key is first the node's private one
    (``~x``); a global key is only itself."""
    return key if key.startswith(("/", "~", UNKNOWN_MARK)) else "~" + key


def searched_name(text: Value) -> str | None:
    """``x`` when ``text`` is the name ``rospy.search_param(x)`` returned, else None."""
    parts = text.parts
    if len(parts) == 1 and isinstance(parts[0], Unknown) and parts[0].origin.startswith(
            SEARCHED):
        return parts[0].origin[len(SEARCHED):]
    return None


def own_name(text: Value) -> Value:
    """A name that starts with the node's own name (``rospy.get_name()``, rclpy's
    ``get_name()``), alone or followed by ``/``, is the node's private name: ``~`` and
    ``~/x``. Followed by other text (``get_name() + '_status'``, a sibling of the node,
    ``/cam_status``) or anywhere else, the node's name stays unknown."""
    parts = text.parts
    if parts and isinstance(parts[0], Unknown) and parts[0].origin in (NODE_NAME, FULL_NAME) and (
            len(parts) == 1 or (isinstance(parts[1], str) and parts[1].startswith("/"))):
        return Value.of("~", *parts[1:])
    return text


class _Over(Exception):
    """The file's evaluation budget is spent."""


# a Parameter's value, or its ParameterValue message's field of each type
_PARAMETER_VALUES = frozenset({
    "value", "string_value", "integer_value", "double_value", "bool_value",
    "string_array_value", "integer_array_value", "double_array_value", "bool_array_value",
    "byte_array_value"})


# the environment variables a ROS distribution's setup script sets, which a node's
# process has as the run gives them (``Evaluator._environ``)
DISTRO_VARIABLES = frozenset({"ROS_VERSION", "ROS_DISTRO", "ROS_PYTHON_VERSION"})


class Evaluator(Instances, QoSProfiles, Walker):
    """The static value of an expression (``eval``), never running it: a configuration of
    the one evaluator's walk (dispatch, steps, size checks). Its handlers are those of its
    partial values (``Value`` strings with unknown parts, ``Seq``, ``Ref``, node handles,
    instances); a construct it has no handler for, and the constructs that only compute
    (comparisons, ``not``, conditional expressions, ``and`` / ``or``, slices), are folded
    by the one evaluator on plain values (``folded``). One budget of ``LIMITS.steps``
    for everything the walk of a file evaluates, helpers' bodies included; once spent,
    every value is an ``Unknown`` of kind ``limit`` (``limited`` says why)."""

    limits = LIMITS

    def __init__(self, loader: Loader) -> None:
        super().__init__(loader)
        self.steps = 0
        self.limited: str | None = None
        # a helper call's value on the path at hand, by the call's node: one of the
        # values it returns on several paths (``PyVisitor._call``: one call per value)
        self.fixed: dict[int, object] = {}

    def eval(self, expr: ast.AST, frame: Frame | None = None) -> object:
        if self.limited is not None:
            return Unknown(self.limited, "limit")
        if self.fixed and id(expr) in self.fixed:
            return self.fixed[id(expr)]
        if self.depth > MAX_EVAL_DEPTH:
            return Unknown("too deep")
        self.depth += 1
        try:
            return Walker.eval(self, expr, frame)
        except _Over as over:
            if self.depth > 1:
                raise
            return Unknown(str(over), "limit")
        finally:
            self.depth -= 1

    # -- this configuration of the walk --------------------------------------------------
    def over(self, reason: str) -> NoReturn:
        self.limited = reason
        raise _Over(reason)

    def unhandled(self, node: ast.AST, env: Any = None) -> Any:
        return self.folded(node, env)

    def refused(self, err: ops.Refused, node: ast.AST, what: str) -> Any:
        return Unknown(err.reason, "limit" if err.kind == "limit" else "error")

    def folded(self, expr: ast.AST, frame: Frame) -> object:
        """A construct this reader has no handler for (a comparison, ``not``, a
        conditional expression, a dict, ...): the one evaluator computes it when every
        name in it holds a known plain value; unknown otherwise. Its steps are this
        walk's."""

        def names(name: str) -> object:
            try:
                return plain(self.name(name, frame))
            except LookupError:
                return Unknown(name)

        remaining = max(self.limits.steps - self.steps, 1)
        result, used = evaluate_counted(expr, names, BUILTINS, replace(
            ops.DEFAULT, steps=min(remaining, ops.DEFAULT.steps)))
        self.step(used)
        return Unknown(type(expr).__name__) if isinstance(result, Unknown) else \
            from_plain(result)

    # constructs that only compute: on plain values, by the one evaluator
    def eval_Compare(self, node: ast.Compare, env: Any = None) -> Any:
        return self.folded(node, env)

    eval_UnaryOp = eval_IfExp = eval_BoolOp = eval_Slice = eval_Compare  # type: ignore[assignment]

    def eval_Constant(self, expr: ast.Constant, frame: Frame) -> object:
        if isinstance(expr.value, str):
            return Value.of(expr.value)
        if isinstance(expr.value, bool | int | float) or expr.value is None:
            return expr.value
        return Unknown("constant")

    def eval_JoinedStr(self, expr: ast.JoinedStr, frame: Frame) -> object:
        parts: list[Value | str] = []
        for part in expr.values:
            if isinstance(part, ast.Constant) and isinstance(part.value, str):
                parts.append(part.value)
            elif isinstance(part, ast.FormattedValue) and part.format_spec is None:
                parts.append(text_of(self.eval(part.value, frame)))
            else:
                parts.append(Value.unknown("formatted value"))
        return Value.of(*parts)

    def eval_BinOp(self, expr: ast.BinOp, frame: Frame) -> object:
        left, right = self.eval(expr.left, frame), self.eval(expr.right, frame)
        try:  # a concatenation's size, before making it (a = a + a); numbers: ops.binary
            if isinstance(expr.op, ast.Add):
                budget.check_size("a value", _length(left) + _length(right))
        except budget.OverBudget as err:
            return Unknown(err.reason)
        if isinstance(expr.op, ast.Add):
            if isinstance(left, Value) or isinstance(right, Value):
                return Value.of(text_of(left), text_of(right))
            if isinstance(left, Seq) and isinstance(right, Seq):
                return Seq(left.items + right.items)
            # a list grown by one not known: its known items, then what is not known,
            # one item standing for the rest (``['rosbag play', bag] + remaps`` keeps
            # its first words: spencer_bagfile_tools' play.py)
            if isinstance(left, Seq) and isinstance(right, Unknown):
                return Seq((*left.items, right))
            if isinstance(left, Unknown) and isinstance(right, Seq):
                return Seq((left, *right.items))
        turned = _shifted_turn(expr.op, left, right)
        if turned is not None:
            return turned
        if isinstance(expr.op, ast.Mod) and isinstance(left, Value):
            items = right.items if isinstance(right, Seq) else (right,)
            return percent(left, items)
        if number(left) and number(right):  # the one evaluator's arithmetic, bounded
            try:
                return ops.binary(type(expr.op), left, right)
            except ops.Refused as err:
                return Unknown(err.reason)
        return Unknown("operation")

    def eval_Name(self, expr: ast.Name, frame: Frame) -> object:
        return self.name(expr.id, frame)

    def eval_Tuple(self, expr: ast.Tuple, frame: Frame) -> object:
        return Seq(tuple(self.eval(e, frame) for e in expr.elts))

    eval_List = eval_Tuple

    def eval_Dict(self, expr: ast.Dict, frame: Frame) -> object:
        if len(expr.keys) > MAX_RECORD or any(k is None for k in expr.keys):
            return Unknown("dict")  # ``{**other}``, or too large to keep
        keys = [self.eval(k, frame) for k in expr.keys if k is not None]
        texts = [k.literal if isinstance(k, Value) else None for k in keys]
        if any(text is None for text in texts) or len(set(texts)) != len(texts):
            return Unknown("dict")
        return Record(tuple((str(text), self.eval(v, frame))
                            for text, v in zip(texts, expr.values, strict=True)))

    def eval_Subscript(self, expr: ast.Subscript, frame: Frame) -> object:
        base = self.eval(expr.value, frame)
        index = self.eval(expr.slice, frame)
        if isinstance(base, Ref) and base.qualname == "sys.argv":
            base = ProgramArgs(stripped=False)
        if isinstance(base, Ref) and base.qualname == "os.environ":
            return self._environ(index)
        if isinstance(base, ProgramArgs):
            return base.item(index)
        if isinstance(base, Record) and isinstance(index, Value) and index.literal is not None:
            return base.entry(index.literal)
        if isinstance(base, Seq) and isinstance(index, int) and -len(base.items) <= index < len(
                base.items):
            return base.items[index]
        if isinstance(base, ParamElement) and base.field == "." and isinstance(
                index, Value) and index.is_known and index.text:
            return ParamElement(base.name, index.text)  # src['topic']
        if isinstance(base, ParamValue) and frame.module.version == 1:
            return _entry_of(base, index, None)  # rospy.get_param('~camera')['topic']
        return Unknown("subscript")

    def eval_Attribute(self, expr: ast.Attribute, frame: Frame) -> object:
        base = self.eval(expr.value, frame)
        return self.attribute(base, expr.attr, frame)

    def attribute(self, base: object, attr: str, frame: Frame) -> object:
        if isinstance(base, Ref):
            # a constant of a message class (``Topics.DVL_TOPIC``) is the value its
            # definition gives; anything else imported stays a reference
            value = msg_types.constant(self.loader.workspace, base.qualname, attr,
                                       frame.module.version)
            if value is not None:
                return Value.of(value) if isinstance(value, str) else value
            return Ref(f"{base.qualname}.{attr}")
        if isinstance(base, ModuleRef):
            found = self.lookup(base.module, attr)
            inner = submodule(base.module.path, attr) if isinstance(found, Unknown) else None
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
            return Unknown(f"self.{attr}")
        if isinstance(base, ClassInfo):
            for c in self.mro(base):
                if attr in c.constants:
                    return self.eval(c.constants[attr], Frame(c.module))
                if attr in c.methods:
                    return c.methods[attr]
            return Unknown(attr)
        if isinstance(base, ParameterClient) and attr in rclpy.NODE_METHODS:
            return NodeMethod(attr, base.remote)
        if isinstance(base, NodeHandle) and (attr in rclpy.NODE_METHODS or attr in NAME_METHODS
                                             or attr == "get_namespace"):
            return NodeMethod(attr, owner=base)
        if isinstance(base, ProgramOptions):
            return base.value(attr)
        if isinstance(base, ParamObject):
            if attr in _PARAMETER_VALUES:
                return ParamValue(base.name, base.default)
            if attr == "get_parameter_value":
                return base
        if isinstance(base, Unknown | Value | type(None)) and attr in rclpy.NODE_METHODS \
                and frame.module.version == 2:
            return NodeMethod(attr)
        return Unknown(attr)

    def eval_Call(self, expr: ast.Call, frame: Frame) -> object:
        base: object = None
        if isinstance(expr.func, ast.Attribute) and expr.func.attr != "__init__":
            base = self.eval(expr.func.value, frame)  # once: a.b().c().d() is linear
            func = self.attribute(base, expr.func.attr, frame)
        else:
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
        if isinstance(base, ArgParser) and isinstance(expr.func, ast.Attribute) and (
                expr.func.attr in ("parse_args", "parse_known_args")):
            options = _parser_options(expr.func.value, frame.module.tree)
            self.option_defaults.update(
                (flags, default) for _, flags, default in options if default is not None)
            parsed = ProgramOptions(tuple((dest, flags) for dest, flags, _ in options))
            # parse_known_args: the options and the words left
            return parsed if expr.func.attr == "parse_args" else Seq((parsed, Unknown("args")))
        if isinstance(expr.func, ast.Attribute) and expr.func.attr == "get" and isinstance(
                base, ParamValue) and frame.module.version == 1 and 1 <= len(expr.args) <= 2:
            # a dictionary parameter's entry: cfg.get('topic', 'scan')
            args = [self.eval(a, frame) for a in expr.args]
            return _entry_of(base, args[0], args[1] if len(args) > 1 else None)
        if isinstance(expr.func, ast.Attribute) and isinstance(func, Unknown) \
                and isinstance(base, Value):
            return string_method(base, expr.func.attr, [self.eval(a, frame) for a in expr.args],
                                 {k.arg: self.eval(k.value, frame) for k in expr.keywords
                                  if k.arg is not None},
                                 spread=any(k.arg is None for k in expr.keywords))
        if isinstance(expr.func, ast.Name) and expr.func.id in ("str", "int", "float") \
                and len(expr.args) == 1:
            value = self.eval(expr.args[0], frame)
            if expr.func.id == "str":
                return text_of(value)
            if isinstance(value, Value) and value.literal is not None:
                # ``int(os.environ.get("ROS_VERSION", 0))``: a known text read as Python
                # reads it, a text that is no number being an error (not known)
                try:
                    return int(value.literal) if expr.func.id == "int" else float(value.literal)
                except ValueError:
                    return Unknown(expr.func.id)
            return value if number(value) else Unknown(expr.func.id)
        if isinstance(expr.func, ast.Name) and expr.func.id in ("list", "tuple") \
                and not expr.keywords and len(expr.args) <= 1 and isinstance(func, Unknown):
            # ``list()`` is ``[]`` (rbx1's dynamixel_joint_state_publisher.py: ``self.
            # controllers = list()``, then an element appended per joint of a list
            # parameter), and ``list(seq)`` a copy of a sequence the walk knows
            if not expr.args:
                return Seq(())
            value = self.eval(expr.args[0], frame)
            return Seq(value.items) if isinstance(value, Seq) else Unknown("call")
        return Unknown("call")

    def callee(self, func: ast.expr, frame: Frame) -> object:
        """What a call's function expression names."""
        if isinstance(func, ast.Attribute) and func.attr == "__init__":
            inner = func.value
            if isinstance(inner, ast.Call) and isinstance(inner.func, ast.Name) \
                    and inner.func.id == "super":
                return self._super_init(frame)
            base = self.eval(inner, frame)
            if isinstance(base, Ref) and base.key in rclpy.NODE_CLASSES:
                return SuperInit()
        return self.eval(func, frame)

    def _super_init(self, frame: Frame) -> object:
        """What ``super().__init__`` runs: the ``__init__`` of the next class of the
        package after the method's own in the object's class order (a node class of the
        workspace built on another: ``Base.__init__(self, name, topic)`` makes the
        publisher the subclass names), else the ROS node's (``SuperInit``)."""
        instance, owner = frame.instance, frame.owner
        if instance is None or owner is None:
            return SuperInit()
        order = list(self.mro(instance.cls))
        after = order[next((i for i, c in enumerate(order) if c is owner), len(order)) + 1:]
        for cls in after:
            if "__init__" in cls.methods:
                return BoundMethod(instance, cls.methods["__init__"])
        return SuperInit()

    def _call_ref(self, ref: Ref, expr: ast.Call, frame: Frame) -> object:
        key = ref.key
        if key in rclpy.NODE_NAMES:
            spec = rclpy.NODE_NAMES[key]
            found = argument(expr, spec.name)
            return NodeHandle(self.eval(found, frame) if found is not None else None)
        if key in (("rospy", "get_param"), ("rospy", "get_param_cached")):
            name = argument(expr, rospy.ROWS[key].name)
            default = argument(expr, rospy.ROWS[key].value)
            value = ParamValue(own_name(in_namespace(text_of(self.eval(name, frame)))).text
                               if name else "?",
                               self.eval(default, frame) if default is not None else None)
            self.param_defaults[value.name] = value.default
            return value
        if key == ("rospy", "search_param"):
            # the full name of the parameter the search finds: a read of it is a
            # searched read of that parameter (``searched_name``)
            name = argument(expr, rospy.ROWS[key].name)
            text = text_of(self.eval(name, frame)) if name is not None else None
            if text is not None and text.is_known and text.text:
                return Value.unknown(SEARCHED + search_start(text.text))
            return Value.unknown("search_param")
        if ref.qualname == "rospy.myargv":  # the arguments without roslaunch's := words
            return ProgramArgs(stripped=True)
        if key == ("argparse", "ArgumentParser"):
            return ArgParser()
        if key == ("rospy", "get_name") and not expr.args:
            return Value.unknown(NODE_NAME)  # the node's own name: ~ at a name's start
        if key == ("rospy", "get_namespace") and not expr.args:
            return Value.unknown(NAMESPACE)  # relative names resolve in it
        if key == ("rospy", "resolve_name") and len(expr.args) == 1 and not expr.keywords:
            # the name resolved (and remapped) in the node's namespace, as rospy does to
            # a publisher's own name: the name as written, which the graph resolves; text
            # put after it (jsk's mux_selector: ``resolve_name('mux') + '/select'``) is in
            # the remapped name, as a C++ handle's namespace (``RESOLVED``)
            given = self.eval(expr.args[0], frame)
            written = text_of(given)
            if written.is_known and written.text:
                return Value.unknown(RESOLVED + written.text)
            return given
        if key == ("rclpy", "AsyncParameterClient"):
            remote = argument(expr, rclpy.PARAMETER_CLIENT)
            return ParameterClient(text_of(self.eval(remote, frame)) if remote is not None
                                   else Value.unknown("remote node"))
        if key == ("rclpy", "Parameter") and (expr.args or expr.keywords):
            named = argument(expr, Arg(0, "name"))
            given = argument(expr, Arg(2, "value"))
            return NewParameter(text_of(self.eval(named, frame)) if named is not None
                                else Value.unknown("parameter name"),
                                self.eval(given, frame) if given is not None else None)
        if key == ("rclpy", "QoSProfile"):
            return self.qos_profile(expr, frame)
        if ref.qualname in ("os.environ.get", "os.getenv") and expr.args and not any(
                isinstance(a, ast.Starred) for a in expr.args):
            return self._environ(self.eval(expr.args[0], frame))
        if ref.qualname in ("os.path.join", "posixpath.join") and expr.args and not any(
                isinstance(a, ast.Starred) for a in expr.args):
            return _path_join([text_of(self.eval(a, frame)) for a in expr.args])
        if ref.qualname in _NUMPY_ARRAYS and len(expr.args) == 1 and not expr.keywords \
                and not isinstance(expr.args[0], ast.Starred):
            # an array of a parameter's value: a loop over it walks the parameter's
            # elements, each written as the element is (tauv's thruster manager names a
            # publisher per id of ``np.array(rospy.get_param('~thruster_ids'))``); not
            # with a dtype, which changes them (``dtype=float``), nor of a list the walk
            # knows, whose arithmetic numpy does per element, not as a list's
            given = self.eval(expr.args[0], frame)
            return given if isinstance(given, ParamValue) else Unknown(ref.qualname)
        return Unknown(ref.qualname)

    def _environ(self, key: object) -> object:
        """An environment variable of the node's process that the distribution's setup
        sets (``DISTRO_VARIABLES``: ros_compatibility's ``os.environ.get("ROS_VERSION",
        0)``), from the run's environment; any other is not known here (the robot's
        shell sets it), nor is one the run does not set (not its default)."""
        name = key.literal if isinstance(key, Value) else None
        environment = self.loader.environment
        if name in DISTRO_VARIABLES and name in environment:
            return Value.of(environment[name])
        return Unknown(f"environment variable {name or '?'}")

    def _node_method(self, name: str, expr: ast.Call, frame: Frame) -> object:
        if name in NAME_METHODS and not expr.args:
            # the node's own name: as rospy.get_name() at a name's start; get_name() is
            # the name without the namespace, which the graph knows per instance
            return Value.unknown(NODE_NAME if name == "get_name" else FULL_NAME)
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
        return Unknown(name)

    def returned(self, func: FunctionInfo | BoundMethod, expr: ast.Call, frame: Frame) -> object:
        """What a helper returns, read from its body without running it (``paths``): the
        value when every path gives one alike; names, strings or numbers that differ as
        ``Alternatives``, each under its path's conditions (a call given them is one call
        per value, as for a local an ``if`` sets); unknown when a path does more than
        assignments and ``if`` (a loop, a ``try``) or the paths are too many."""
        if frame.depth >= MAX_CALL_DEPTH:
            return Unknown("call depth")
        inner = self.call_frame(func, expr, frame)
        info = func.function if isinstance(func, BoundMethod) else func
        found: list[tuple[object, tuple[Condition, ...]]] = []
        if not self.paths(list(info.node.body), inner, (), found):
            return Unknown(f"{info.qualname}()")
        if all(same_value(value, found[0][0]) for value, _ in found):
            return found[0][0]
        options = tuple((each, (*under, *more)) for value, under in found
                        for each, more in (value.options if isinstance(value, Alternatives)
                                           else ((value, ()),)))
        if len(options) <= MAX_ALTERNATIVES and all(returned_alternative(v)
                                                  for v, _ in options):
            return Alternatives(options)
        return Unknown(f"{info.qualname}() (one of several values)")

    def paths(self, statements: list[ast.stmt], frame: Frame,
              under: tuple[Condition, ...],
              found: list[tuple[object, tuple[Condition, ...]]]) -> bool:
        """Each path through ``statements`` to its ``return`` (or its end: None), with
        the conditions it runs under, added to ``found``: assignments and bare
        expressions in order; an ``if`` whose test the evaluator decides by its path,
        one it cannot by both, each from the locals before it, under its condition as
        the reader's own ``if`` puts it. False when a path does what is not followed or
        the paths are more than ``MAX_ALTERNATIVES``."""
        for index, statement in enumerate(statements):
            if isinstance(statement, ast.Return):
                found.append((self.eval(statement.value, frame) if statement.value
                              else None, under))
                return len(found) <= MAX_ALTERNATIVES
            if isinstance(statement, ast.Assign | ast.AnnAssign):
                self.assign(statement, frame)
            elif isinstance(statement, ast.If):
                rest = statements[index + 1:]
                taken = _truth(self.eval(statement.test, frame))
                if taken is not None:
                    return self.paths([*(statement.body if taken else statement.orelse),
                                       *rest], frame, under, found)
                text = tested_text(frame.module.lines, statement.test,
                                   lambda arg: literal_name(self.eval(arg, frame)))
                where = self.loader.location(frame.module.path, statement.lineno,
                                             statement.col_offset + 1)
                return all(self.paths([*branch, *rest], replace(
                    frame, locals=dict(frame.locals)), (*under, made), found)
                    for branch, made in ((statement.body, condition("if", text, where)),
                                         (statement.orelse, condition("else", text, where))))
            elif not isinstance(statement, ast.Expr | ast.Pass):
                return False
        found.append((None, under))
        return len(found) <= MAX_ALTERNATIVES


def literal_name(value: object) -> str | None:
    """The text of a value known to be one string, else None."""
    return value.literal if isinstance(value, Value) and isinstance(value.literal, str) \
        else None


def _truth(value: object) -> bool | None:
    """A test's truth where the evaluator knows its value, else None."""
    if value is None or isinstance(value, bool | int | float):
        return bool(value)
    if isinstance(value, Value) and value.literal is not None:
        return bool(value.literal)
    return None


# numpy's functions that make an array of a list as it is: its elements, one per turn of
# a loop over the array (a list of lists is a list of rows: the loop walks rows too)
_NUMPY_ARRAYS = frozenset({"numpy.array", "numpy.asarray", "numpy.asanyarray"})


def _path_join(parts: list[Value]) -> Value:
    """``os.path.join(a, b, ...)`` on Linux: a part that starts with ``/`` starts over,
    the others are joined with one ``/`` (a name built so: ``os.path.join(ns, 'cmd')``)."""
    joined = parts[0]
    for part in parts[1:]:
        if part.text.startswith("/"):
            joined = part
        elif not joined.text or joined.text.endswith("/"):
            joined = joined + part
        else:
            joined = joined + "/" + part
    return joined


def _entry_of(param: ParamValue, key: object, default: object) -> object:
    """An entry of a ROS 1 dictionary parameter: the parameter under it
    (``rospy.get_param('~camera')['topic']`` reads ``~camera/topic``), its default the
    one given, else the entry of the dictionary's default; unknown for a key not known."""
    if not (isinstance(key, Value) and key.is_known and key.text) or "?" in param.name:
        return Unknown("subscript")
    if default is None and isinstance(param.default, dict):
        default = param.default.get(key.text)
    return ParamValue(f"{param.name.rstrip('/')}/{key.text}", default)


def _length(value: object) -> int:
    """Characters (or items) a value adds to a concatenation."""
    if isinstance(value, Value):
        return sum(len(p) if isinstance(p, str) else 1 for p in value.parts)
    if isinstance(value, Seq):
        return len(value.items)
    return len(value) if isinstance(value, str) else 1


_GROUPS = ("add_mutually_exclusive_group", "add_argument_group")


def _parser_receivers(receiver: ast.expr, tree: ast.Module) -> set[str]:
    """``receiver`` as written, and the groups made of it (``source =
    parser.add_mutually_exclusive_group()``, gazebo_ros' spawn_entity.py, whose
    ``-topic`` is one; groups of groups too): their options are the parser's."""
    found = {ast.unparse(receiver)}
    groups = [(ast.unparse(n.targets[0]), ast.unparse(n.value.func.value))
              for n in ast.walk(tree)
              if isinstance(n, ast.Assign) and len(n.targets) == 1
              and isinstance(n.value, ast.Call) and isinstance(n.value.func, ast.Attribute)
              and n.value.func.attr in _GROUPS]
    grown = True
    while grown:
        grown = False
        for target, made_of in groups:
            if made_of in found and target not in found:
                found.add(target)
                grown = True
    return found


def _parser_options(receiver: ast.expr, tree: ast.Module,
                    ) -> tuple[tuple[str, str, str | None], ...]:
    """The options ``add_argument`` gives a parser: every such call in the module on a
    receiver written as ``receiver`` is (``parser.add_argument("-l", "--limb",
    dest="limb")``), or on a group made of it, each as (``dest``, its flags, its
    ``default=`` when that is a literal string) as argparse names it: ``dest=``, else
    the first long flag, else the first short one, without dashes, ``-`` as ``_``.
    Positional arguments are not options."""
    written = _parser_receivers(receiver, tree)
    found: dict[str, tuple[str, str | None]] = {}
    for node in ast.walk(tree):
        if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                and node.func.attr == "add_argument"
                and ast.unparse(node.func.value) in written):
            continue
        flags = [a.value for a in node.args
                 if isinstance(a, ast.Constant) and isinstance(a.value, str)]
        if not flags or len(flags) != len(node.args) or not all(
                f.startswith("-") and len(f) > 1 for f in flags):
            continue
        dest = next((k.value.value for k in node.keywords if k.arg == "dest"
                     and isinstance(k.value, ast.Constant) and isinstance(k.value.value, str)),
                    None)
        if dest is None:
            long = [f for f in flags if f.startswith("--")]
            dest = (long or flags)[0].lstrip("-").replace("-", "_")
        default = next((k.value.value for k in node.keywords if k.arg == "default"
                        and isinstance(k.value, ast.Constant)
                        and isinstance(k.value.value, str)), None)
        found.setdefault(dest, (" ".join(flags), default))
    return tuple((dest, flags, default) for dest, (flags, default) in found.items())


def _shifted_turn(op: ast.operator, left: object, right: object) -> ParamTurn | None:
    """A counting loop's variable plus or minus a literal integer (``i + 1``, ``1 + i``,
    ``i - 1``): the variable shifted by it; None for any other operation."""
    if isinstance(op, ast.Add) and isinstance(right, ParamTurn) and type(left) is int:
        left, right = right, left
    if not (isinstance(left, ParamTurn) and type(right) is int
            and isinstance(op, ast.Add | ast.Sub)):
        return None
    step = right if isinstance(op, ast.Add) else -right
    return dataclasses.replace(left, shift=left.shift + step)
