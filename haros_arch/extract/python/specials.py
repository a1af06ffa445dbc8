"""Calls that give several primitives, or none, from one argument list (the rows of the
API tables with a ``special`` handler), and small helpers the walker shares with them.
"""

from __future__ import annotations

import ast
from dataclasses import replace

from ...model.source import RECONFIGURE_SERVICE, RECONFIGURE_TOPICS, PrimitiveCall
from ...model.values import Value
from . import rclpy
from .api import Arg, PyFunction
from .objects import Frame, NewParameter, Ref, Seq, param_type, plain_value, text_of
from .values import Evaluator, argument, own_name


def special_calls(ev: Evaluator, spec: PyFunction, call: ast.Call, frame: Frame,
                  base: PrimitiveCall, version: int) -> list[PrimitiveCall]:
    """The primitives of a call whose row names a ``special`` handler (none or several
    from one argument list): one per parameter of ``declare_parameters`` /
    ``get_parameters`` / ``set_parameters``, every parameter under the prefix of
    ``get_parameters_by_prefix`` (a read ``under`` the prefix, optional; ``prefix.?`` when
    the prefix is not known), ``/tf`` and ``/tf_static`` for a
    ``TransformListener``, a tf2 buffer's frames service unless ``debug=False`` (ROS 2:
    only when it is given a node)."""
    if spec.special == "tf-listener":
        qos = ({"tf": rclpy.PRESETS["tf"], "tf_static": rclpy.PRESETS["tf_static"]}
               if version == 2 else {})
        return [replace(base, name=f"/{topic}", qos=qos.get(topic),
                        queue_size=qos[topic]["depth"] if qos else None)
                for topic in ("tf", "tf_static")]
    if spec.special == "tf2-buffer":
        debug = argument(call, Arg(1, "debug"))
        if debug is not None and evaluate(ev, debug, frame) is False:
            return []
        return [replace(base, name=spec.fixed_name or "?")]
    if spec.special == "tf2-buffer-node":  # ROS 2: only a buffer given a node serves it
        node = argument(call, spec.owner) if spec.owner is not None else None
        if node is None or (isinstance(node, ast.Constant) and node.value is None):
            return []
        return [replace(base, name=spec.fixed_name or "?")]
    if spec.special == "smach-introspection":
        server = _under(ev, argument(call, Arg(0, "server_name")), frame)
        return [replace(base, name=f"{server}smach/container_init"),
                *(replace(base, kind="publish", name=f"{server}smach/container_{topic}",
                          type=f"smach_msgs/SmachContainer{kind}", queue_size=1)
                  for topic, kind in (("structure", "Structure"), ("status", "Status")))]
    if spec.special == "bond":  # the heartbeat's topic both ways
        topic = own_name(text_of(evaluate(ev, argument(call, Arg(0, "topic")), frame))).text
        named = replace(base, name=topic or "?")
        return [named, replace(named, kind="subscribe")]
    if spec.special == "reconfigure-server":
        return _reconfigure_server(ev, call, frame, base)
    if spec.special == "interactive-marker-server":
        # the namespace joined to each topic by ``+``: as written, not as a namespace
        prefix = own_name(text_of(evaluate(ev, argument(call, Arg(0, "topic_ns")),
                                           frame))).text or "?"
        queue = 100 if base.queue_size_missing else base.queue_size  # ``q_size``'s default
        base = replace(base, queue_size_missing=False)
        return [replace(base, kind="publish", name=prefix + "/update_full", queue_size=100,
                        type="visualization_msgs/InteractiveMarkerInit", latch=True),
                replace(base, kind="publish", name=prefix + "/update", queue_size=100),
                replace(base, kind="subscribe", name=prefix + "/feedback", queue_size=queue,
                        type="visualization_msgs/InteractiveMarkerFeedback")]
    if spec.special == "reconfigure-client":
        server = _under(ev, argument(call, Arg(0, "name")), frame)
        return [replace(base, name=server + RECONFIGURE_SERVICE[0]),
                *(replace(base, kind="subscribe", name=server + topic, type=type_)
                  for topic, type_ in RECONFIGURE_TOPICS)]
    made: list[PrimitiveCall] = []
    if spec.special == "declare-parameters":
        prefix = text_of(evaluate(ev, call.args[0] if call.args else argument(
            call, _kw("namespace")), frame)).text
        items = call.args[1] if len(call.args) > 1 else argument(call, _kw("parameters"))
        for element in _elements(_written(items, call, frame)):
            pair = element.elts if isinstance(element, ast.Tuple) else [element]
            name = text_of(ev.eval(pair[0], frame)).text
            full = f"{prefix}.{name}" if prefix else name
            # ``(name, value)`` declares with that default, ``(name, Parameter.Type.X)``
            # a type and no value; ``(name,)`` dynamically typed, unset (a get returns
            # it, value None: rclpy's deprecated form), and ``(name, None)`` statically
            # typed, uninitialised (a get raises), unless its descriptor says
            # ``dynamic_typing=True`` (rclpy node.py ``declare_parameters``)
            declared_type = type_only(pair[1]) if len(pair) > 1 else None
            value = ev.eval(pair[1], frame) if len(pair) > 1 else None
            ev.declared[full] = value
            described = dynamic_descriptor(pair[2]) if len(pair) > 2 else False
            if len(pair) == 1:
                made.append(replace(base, name=full, has_default=True))
            elif declared_type is not None or (is_none(pair[1]) and described is False):
                made.append(replace(base, name=full, type=declared_type))
            else:
                made.append(replace(base, name=full, type=param_type(value),
                                    has_default=True, default=plain_value(value)))
    elif spec.special == "parameters-under":
        prefix = param_name(text_of(evaluate(ev, argument(call, Arg(0, "prefix")), frame)))
        if "?" in prefix:  # a prefix not known statically: whatever it is
            made.append(replace(base, name=f"{prefix}.?", has_default=True, default={}))
        else:  # what is under ``prefix.`` (``""``: every parameter, the node's ``~`` whole)
            made.append(replace(base, name=f"{prefix}." if prefix else "~",
                                under=bool(prefix), has_default=True, default={},
                                declared_only=version == 2))
    elif spec.special == "parameter-names":
        items = call.args[0] if call.args else argument(call, _kw("names"))
        listed = evaluate(ev, items, frame)
        for item in listed.items if isinstance(listed, Seq) else ():
            made.append(replace(base, name=param_name(text_of(item))))
    elif spec.special == "set-parameters":
        items = call.args[0] if call.args else argument(call, _kw("parameter_list"))
        for element in _elements(_written(items, call, frame)):
            # each parameter where the list names it: one not known statically is kept
            # beside those known (a call site keeps its '?' only where nothing is known)
            base = replace(base, location=replace(
                base.location, line=element.lineno, column=element.col_offset + 1))
            if isinstance(element, ast.Call) and element.args:
                name = param_name(text_of(ev.eval(element.args[0], frame)))
                value_expr = element.args[2] if len(element.args) > 2 else argument(
                    element, _kw("value"))
                made.append(replace(base, name=name, type=param_type(
                    evaluate(ev, value_expr, frame))))
                continue
            built = ev.eval(element, frame)  # param = Parameter(...); set_parameters([param])
            if isinstance(built, NewParameter):
                made.append(replace(base, name=param_name(built.name),
                                    type=param_type(built.value)))
            else:  # a parameter not known statically: unknown, not absent
                made.append(replace(base, name="?"))
    if not made:
        made.append(replace(base, name="?"))
    return made


def _under(ev: Evaluator, expr: ast.expr | None, frame: Frame) -> str:
    """The prefix of names a library joins to the name it is given with ``/``: the node's
    own name (``rospy.get_name()``) is its private namespace ``~``."""
    text = own_name(text_of(evaluate(ev, expr, frame))).text or "?"
    if text.startswith("~/"):
        text = "~" + text[2:]
    if text == "~":
        return text
    return text if text.endswith("/") else text + "/"


def _reconfigure_server(ev: Evaluator, call: ast.Call, frame: Frame,
                        base: PrimitiveCall) -> list[PrimitiveCall]:
    """A rospy dynamic_reconfigure server: in its namespace (``~``, or ``~<given>/``, or
    an absolute one), a read of each parameter of its config class with the .cfg's
    default (it writes them back as read: no write is said, as for roscpp's server),
    its two latched topics (queue 10) and its ``set_parameters`` service. A config whose
    .cfg is not found, or names parameters at run time, reads ``?`` there too."""
    given = argument(call, Arg(2, "namespace"))
    namespace = text_of(evaluate(ev, given, frame)).text if given is not None else ""
    if not namespace or namespace == "~":
        namespace = "~"
    else:
        if namespace[0] not in "/~":
            namespace = "~" + namespace
        namespace = (namespace + "/").replace("//", "/")
    made: list[PrimitiveCall] = []
    parameters, partial = _config_parameters(ev, evaluate(ev, argument(
        call, Arg(0, "type")), frame))
    plain = replace(base, callback=None)
    for name, kind, default in parameters:
        made.append(replace(plain, kind="read", name=namespace + name, type=kind,
                            has_default=True, default=default))
    if partial:
        made.append(replace(plain, kind="read", name=namespace + "?", type=None))
    for topic, type_ in RECONFIGURE_TOPICS:
        made.append(replace(plain, kind="publish", name=namespace + topic, type=type_,
                            latch=True, queue_size=10))
    made.append(replace(base, name=namespace + RECONFIGURE_SERVICE[0]))
    return made


def _config_parameters(ev: Evaluator, config: object,
                       ) -> tuple[list[tuple[str, str | None, object]], bool]:
    """The parameters (name, type, default) of a generated config class
    (``<package>.cfg.<Name>Config``), from its package's ``cfg/*.cfg``; and whether
    some may be missing (the class or its .cfg not found, or a partial .cfg)."""
    from ..cpp import reconfigure  # the .cfg reader the C++ extraction shares
    parts = config.qualname.split(".") if isinstance(config, Ref) else []
    if len(parts) < 3 or parts[-2] != "cfg":
        return [], True
    package = parts[-3]
    root = ev.loader.workspace.find(package)
    if root is None:
        return [], True
    found, _ = reconfigure.configs(root, package,
                                   reconfigure.workspace_modules(ev.loader.workspace))
    cfg = found.get(parts[-1])
    if cfg is None:
        return [], True
    return ([(name, reconfigure.TYPES[kind][1] if kind in reconfigure.TYPES else None,
              default) for name, kind, default in cfg.parameters], cfg.partial)


def evaluate(ev: Evaluator, expr: ast.expr | None, frame: Frame) -> object:
    return None if expr is None else ev.eval(expr, frame)


def _kw(keyword: str) -> object:
    return Arg(None, keyword)


def _written(expr: ast.expr | None, call: ast.Call, frame: Frame) -> ast.expr | None:
    """``expr``, or the list or tuple written for it when it is a local of the function
    that makes ``call`` whose one write, before the call, is that literal and which
    nothing else in the function (nor a function in it) names, nor declares ``global``
    or ``nonlocal`` (so nothing appends to it or hands it on):
    raspimouse_ros2_examples' ``parameters = [(name, default), ...]`` then
    ``self.declare_parameters('', parameters)``."""
    if not isinstance(expr, ast.Name):
        return expr
    function = _enclosing(frame.module.tree, call)
    if function is None:
        return expr
    # every use in the function, its inner functions' too (a closure may append to it)
    names = [node for node in ast.walk(function) if isinstance(node, ast.Name)
             and node.id == expr.id]
    writes = [node for node in names if isinstance(node.ctx, ast.Store)]
    if len(names) != 2 or len(writes) != 1 or expr not in names or any(
        isinstance(node, ast.Global | ast.Nonlocal) and expr.id in node.names
        for node in ast.walk(function)
    ):
        return expr
    assigned = next((node for node in _own_nodes(function) if isinstance(node, ast.Assign)
                     and node.targets == [writes[0]]), None)
    if assigned is None or not isinstance(assigned.value, ast.List | ast.Tuple) or (
        assigned.end_lineno is None or assigned.end_lineno >= call.lineno
    ):
        return expr
    return assigned.value


def _enclosing(tree: ast.Module, call: ast.Call) -> ast.FunctionDef | ast.AsyncFunctionDef | None:
    """The innermost function whose body holds ``call``."""
    found = None
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef) and (
            node.lineno <= call.lineno <= (node.end_lineno or node.lineno)
        ) and any(inner is call for inner in ast.walk(node)) and (
            found is None or node.lineno >= found.lineno
        ):
            found = node
    return found


def _own_nodes(function: ast.FunctionDef | ast.AsyncFunctionDef) -> list[ast.AST]:
    """The nodes of ``function``'s body, not those of the functions, lambdas and classes
    defined in it."""
    found: list[ast.AST] = []
    todo: list[ast.AST] = list(function.body)
    while todo:
        node = todo.pop()
        found.append(node)
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda | ast.ClassDef):
            continue
        todo.extend(ast.iter_child_nodes(node))
    return found


def _elements(expr: ast.expr | None) -> list[ast.expr]:
    if isinstance(expr, ast.List | ast.Tuple):
        return list(expr.elts)
    return []


def is_none(expr: ast.expr) -> bool:
    """Whether ``expr`` is the literal None."""
    return isinstance(expr, ast.Constant) and expr.value is None


def dynamic_descriptor(expr: ast.expr | None) -> bool | None:
    """Whether ``expr``, written ``ParameterDescriptor(...)``, says ``dynamic_typing=True``;
    None when it is no such call (a variable, nothing)."""
    if not isinstance(expr, ast.Call):
        return None
    func = expr.func
    name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
    if name != "ParameterDescriptor":
        return None
    return any(k.arg == "dynamic_typing" and isinstance(k.value, ast.Constant)
               and k.value.value is True for k in expr.keywords)


def param_name(text: Value) -> str:
    """A ROS 2 parameter name as rclcpp's extraction writes it, relative to its node
    (``use_sim_time``; the graph resolves it in the node's own scope)."""
    name = text.text
    return name[2:] if name.startswith("~/") else name.removeprefix("~")


# rclpy's parameter types (Parameter.Type.X, ParameterType.PARAMETER_X) as the model
# names parameter types, for declarations that give a type and no value
_DECLARED_TYPES: dict[str, str | None] = {
    "BOOL": param_type(True), "INTEGER": param_type(0), "DOUBLE": param_type(0.0),
    "STRING": "str", "BYTE_ARRAY": "byte[]", "BOOL_ARRAY": "bool[]",
    "INTEGER_ARRAY": "int[]", "DOUBLE_ARRAY": "double[]", "STRING_ARRAY": "str[]"}


def type_only(expr: ast.expr | None) -> str | None:
    """The parameter type a ``declare_parameter`` value argument names when it is a type
    rather than a value, else None."""
    if not isinstance(expr, ast.Attribute):
        return None
    owner = expr.value
    owner_name = owner.attr if isinstance(owner, ast.Attribute) else (
        owner.id if isinstance(owner, ast.Name) else "")
    if owner_name not in ("Type", "ParameterType"):
        return None
    return _DECLARED_TYPES.get(expr.attr.removeprefix("PARAMETER_"))
