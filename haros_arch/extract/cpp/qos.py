"""ROS 2 quality of service written in C++, as a dict: ``{"history", "depth",
"reliability", "durability"}``.

Understood: a depth (``10``, a constant), ``rclcpp::QoS(n)``, ``rclcpp::QoS(KeepLast(n))``,
``rclcpp::QoS(KeepAll())``, ``rclcpp::QoS(QoSInitialization::from_rmw(p), p)``, the named
profiles (``rclcpp::SensorDataQoS()``, ``SystemDefaultsQoS()``, ... and
``rmw_qos_profile_*``), and the setters chained on them (``.reliable()``,
``.best_effort()``, ``.transient_local()``, ``.durability_volatile()``, ``.keep_last(n)``,
``.keep_all()``), also through a local variable written once, and the setters called
on that variable before its use. A part that cannot be known is left out; nothing known
gives None.
"""

from __future__ import annotations

from typing import Any

from clang.cindex import Cursor, CursorKind

from .values import Scope, _integral, operand, strip, written_arguments

QoS = dict[str, Any]
MAX_DEPTH = 16


def _profile(history: str, depth: int, reliability: str, durability: str) -> QoS:
    return {"history": history, "depth": depth, "reliability": reliability,
            "durability": durability}


PROFILES: dict[str, QoS] = {
    "default": _profile("keep_last", 10, "reliable", "volatile"),
    "sensor_data": _profile("keep_last", 5, "best_effort", "volatile"),
    "services_default": _profile("keep_last", 10, "reliable", "volatile"),
    "parameters": _profile("keep_last", 1000, "reliable", "volatile"),
    "parameter_events": _profile("keep_last", 1000, "reliable", "volatile"),
    "rosout": _profile("keep_last", 1000, "reliable", "transient_local"),
    "clock": _profile("keep_last", 1, "best_effort", "volatile"),
    "system_default": _profile("system_default", 0, "system_default", "system_default"),
}
# rclcpp classes that are a named profile
PROFILE_CLASSES = {
    "SensorDataQoS": "sensor_data", "SystemDefaultsQoS": "system_default",
    "ServicesQoS": "services_default", "ParametersQoS": "parameters",
    "ParameterEventsQoS": "parameter_events", "RosoutQoS": "rosout", "ClockQoS": "clock",
}
SETTERS: dict[str, dict[str, str]] = {
    "reliable": {"reliability": "reliable"},
    "best_effort": {"reliability": "best_effort"},
    "transient_local": {"durability": "transient_local"},
    "durability_volatile": {"durability": "volatile"},
    "keep_all": {"history": "keep_all"},
}


def qos(expr: Cursor, scope: Scope) -> QoS | None:
    """The QoS that ``expr`` (an argument of create_publisher, ...) stands for."""
    found = _qos(expr, scope, 0)
    return found or None


def _qos(expr: Cursor, scope: Scope, depth: int) -> QoS:
    if depth > MAX_DEPTH:
        return {}
    expr = strip(expr)
    kind = expr.kind
    if kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
        decl = expr.referenced
        if decl is None:
            return {}
        name = decl.spelling
        if name.startswith("rmw_qos_profile_"):
            return dict(PROFILES.get(name.removeprefix("rmw_qos_profile_"), {}))
        value = scope.variable(decl)
        if value is not None:
            return _changed(_qos(value, scope, depth + 1), decl, expr, scope, depth)
    depth_value = scope.integer(expr)
    if depth_value is not None:
        return {**PROFILES["default"], "depth": depth_value}
    if kind != CursorKind.CALL_EXPR:
        return {}
    target = expr.referenced
    args = written_arguments(expr)
    if target is None:  # an implicit conversion or copy around the real expression
        inner = operand(expr)
        return _qos(inner, scope, depth + 1) if inner is not None else {}
    if target.kind == CursorKind.CONSTRUCTOR:
        return _constructed(target.spelling, args, scope, depth)
    if target.spelling in ("from_rmw",) and args:
        return _qos(args[0], scope, depth + 1)
    return _chained(expr, target.spelling, args, scope, depth)


def _changed(found: QoS, decl: Cursor, at: Cursor, scope: Scope, depth: int) -> QoS:
    """``found``, the QoS a local variable was made with, as the setters called on it
    before ``at`` leave it (``rclcpp::QoS qos{1}; qos.transient_local();``: Autoware's
    pointcloud map loader); a setter that may not run makes what it sets unknown."""
    if decl.kind != CursorKind.VAR_DECL or not found:
        return found
    for call, maybe in scope.method_calls(decl, at):
        method = call.spelling
        change = _setter(method, written_arguments(call), scope)
        if change is None and method in ("history", "reliability", "durability", "depth"):
            change = {method: None}  # set from a value: not read here
        if change is None:
            continue
        _apply(found, change, maybe)
        if method == "keep_all" and not maybe:
            found.pop("depth", None)
    return found


def _constructed(cls: str, args: list[Cursor], scope: Scope, depth: int) -> QoS:
    if cls in PROFILE_CLASSES:
        return dict(PROFILES[PROFILE_CLASSES[cls]])
    if cls == "KeepLast" and args:
        count = scope.integer(args[0])
        return {"history": "keep_last", **({"depth": count} if count is not None else {})}
    if cls == "KeepAll":
        return {"history": "keep_all"}
    if cls in ("QoS", "QoSInitialization"):
        if not args:
            return {}
        base = _qos(args[1], scope, depth + 1) if len(args) > 1 else dict(PROFILES["default"])
        init = _qos(args[0], scope, depth + 1)
        if cls == "QoS" and len(args) == 1 and not init and _integral(args[0]):
            # a depth the parse does not know (``QoS(node_depth())``, the size_t a
            # factory converts): the default profile's policies, the depth unknown
            return {**PROFILES["default"], "depth": None}
        if cls == "QoS" and len(args) == 1 and "reliability" not in init:
            init = {**PROFILES["default"], **init}
        found = {**base, **init}
        if found.get("history") == "keep_all":
            found.pop("depth", None)
        return found
    if len(args) == 1:  # a copy
        return _qos(args[0], scope, depth + 1)
    return {}


def _chained(call: Cursor, method: str, args: list[Cursor], scope: Scope, depth: int) -> QoS:
    children = list(call.get_children())
    if not children or children[0].kind != CursorKind.MEMBER_REF_EXPR:
        return {}
    objects = [c for c in children[0].get_children() if c.kind.is_expression()]
    if not objects:
        return {}
    base = _qos(objects[0], scope, depth + 1)
    change = _setter(method, args, scope)
    if change is None:
        return {}
    _apply(base, change)
    if method == "keep_all":
        base.pop("depth", None)
    return base


def _setter(method: str, args: list[Cursor], scope: Scope) -> QoS | None:
    """The fields a QoS setter sets (a depth None: not known); None for no setter."""
    if method in SETTERS:
        return dict(SETTERS[method])
    if method == "keep_last" and args:
        return {"history": "keep_last", "depth": scope.integer(args[0])}
    return None


def _apply(found: QoS, change: QoS, unknown: bool = False) -> None:
    """``found`` as ``change`` leaves it; a field set to None, or every field of a change
    that may not happen (``unknown``), is no longer known."""
    for field, value in change.items():
        if unknown or value is None:
            found.pop(field, None)
        else:
            found[field] = value
