"""Extraction hints from the project file, in HAROS's format (plus actions).

Global hints (``nodes:`` keyed by ``pkg/executable``) complete what the source says of a
node; configuration hints (``configurations.<name>.hints:`` keyed by a node instance's
full name) complete one configuration's graph and may create instances that no launch
file starts (``create: true`` with ``node_type: pkg/executable``). A hint whose name
matches a call or link with a ``?`` name of the same kind and a compatible type
completes it; any other hint adds a call or link. Whatever a hint made has
``origin == "hint"``. A hint that cannot be used is a diagnostic.

An entry looks like HAROS's::

    publishers:
      - topic: /wheel_cmd          # or name:
        msg_type: std_msgs/Int32   # or type:
        queue_size: 10
        latch: false
        conditions: ["use_wheels"]  # strings, or {text:, statement:}
        location: {package: p, file: src/x.cpp, line: 12}
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

from .. import diagnostics as diag
from ..diagnostics import Diagnostic
from ..model.conditions import Condition
from ..model.location import Location
from ..model.rosname import RosName, as_namespace, namespace_of, pattern_for, resolve
from ..model.runtime import Configuration, NodeInstance
from ..model.source import CallKind, Node, PrimitiveCall
from ..model.values import UNKNOWN_MARK
from .build import RESOURCE_OF_KIND, Resources, link

# hint section -> (call kind, keys that may hold the name, keys that may hold the type)
SECTIONS: dict[str, tuple[CallKind, tuple[str, ...], tuple[str, ...]]] = {
    "publishers": ("publish", ("topic", "name"), ("msg_type", "type")),
    "subscribers": ("subscribe", ("topic", "name"), ("msg_type", "type")),
    "servers": ("server", ("service", "name"), ("srv_type", "type")),
    "clients": ("client", ("service", "name"), ("srv_type", "type")),
    "action_servers": ("action-server", ("action", "name"), ("action_type", "type")),
    "action_clients": ("action-client", ("action", "name"), ("action_type", "type")),
    "getters": ("read", ("parameter", "param", "name"), ("param_type", "type")),
    "setters": ("write", ("parameter", "param", "name"), ("param_type", "type")),
}
NODE_KEYS = {"rosname", "node_type", "create", "namespace", "traceability", "hpl",
             "description"}


def _calls(owner: str, hints: Mapping[str, Any], where: Location,
           found: list[Diagnostic]) -> list[PrimitiveCall]:
    """The calls a hint block describes; malformed entries become diagnostics."""
    calls: list[PrimitiveCall] = []
    for section, entries in hints.items():
        if section in NODE_KEYS:
            continue
        if section not in SECTIONS:
            found.append(diag.make("HINT_INVALID", where,
                                   detail=f"{owner}: unknown hint section '{section}'"))
            continue
        kind, name_keys, type_keys = SECTIONS[section]
        for entry in entries if isinstance(entries, list) else [entries]:
            name = _first(entry, name_keys) if isinstance(entry, dict) else None
            if not isinstance(name, str) or not name:
                found.append(diag.make("HINT_INVALID", where,
                                       detail=f"{owner}: an entry of {section} has no name"))
                continue
            type_ = _first(entry, type_keys)
            queue = entry.get("queue_size")
            calls.append(PrimitiveCall(
                kind=kind, name=name, type=str(type_) if type_ else None,
                queue_size=queue if isinstance(queue, int) else None,
                latch=bool(entry.get("latch", entry.get("latched", False))),
                conditions=_conditions(entry.get("conditions"), where),
                # a read's default in code (``default: false``): a read with one is
                # never "read but not set"
                has_default=kind == "read" and "default" in entry,
                default=entry.get("default") if kind == "read" else None,
                location=_location(entry.get("location"), where), origin="hint"))
    return calls


def _first(entry: Mapping[str, Any], keys: tuple[str, ...]) -> Any:
    return next((entry[k] for k in keys if entry.get(k) is not None), None)


def _conditions(raw: Any, where: Location) -> tuple[Condition, ...]:
    items = raw if isinstance(raw, list) else [] if raw is None else [raw]
    result = []
    for item in items:
        if isinstance(item, dict):
            text = str(item.get("text", item.get("condition", "")))
            result.append(Condition(text, "hint", str(item.get("statement", "if")), where))
        else:
            result.append(Condition(str(item), "hint", "if", where))
    return tuple(result)


def _location(raw: Any, where: Location) -> Location:
    if not isinstance(raw, dict):
        return where
    line = raw.get("line")
    column = raw.get("column")
    return Location(raw.get("package"), raw.get("file"),
                    line if isinstance(line, int) else 0,
                    column if isinstance(column, int) else 0)


def _completes(unknown: str, known: str) -> bool:
    return UNKNOWN_MARK in unknown and re.match(pattern_for(unknown), known) is not None


def _types_agree(a: str | None, b: str | None) -> bool:
    return a is None or b is None or a == b


def apply_node_hints(nodes: dict[str, Node], hints: Mapping[str, Any],
                     where: Location) -> list[Diagnostic]:
    """Global ``nodes:`` hints. A node nobody builds is created from its hints alone."""
    found: list[Diagnostic] = []
    for name, block in hints.items():
        if not isinstance(block, dict) or "/" not in name:
            found.append(diag.make("HINT_INVALID", where,
                                   detail=f"node hint '{name}' must be 'pkg/executable: "
                                          "{publishers: [...], ...}'"))
            continue
        node = nodes.get(name)
        if node is None:
            package, _, executable = name.partition("/")
            node = nodes[name] = Node(package, executable, location=where)
        if isinstance(block.get("rosname"), str):
            node.rosname = block["rosname"]
        for call in _calls(name, block, where, found):
            target = next((c for c in node.calls if c.kind == call.kind
                           and _completes(c.name, call.name)
                           and _types_agree(c.type, call.type)), None)
            if target is None:
                node.calls.append(call)
            else:
                target.name, target.origin = call.name, "hint"
                target.type = target.type or call.type
    return found


def apply_hints(config: Configuration, hints: Mapping[str, Any], nodes: Mapping[str, Node],
                where: Location) -> list[Diagnostic]:
    """Configuration hints, keyed by node instance name, applied to a built graph."""
    found: list[Diagnostic] = []
    resources = Resources(config)
    for name, block in hints.items():
        if not isinstance(block, dict):
            found.append(diag.make("HINT_INVALID", where,
                                   detail=f"hint for {name} must be a mapping"))
            continue
        full = resolve(name, "/")
        instance = config.node(full)
        if instance is None:
            if not block.get("create"):
                found.append(diag.make("HINT_UNMATCHED", where, name=full,
                                       configuration=config.name))
                continue
            node_type = str(block.get("node_type", ""))
            instance = NodeInstance(full, nodes.get(node_type), id=f"node:{full}",
                                    namespace=namespace_of(full), location=where,
                                    origin="hint")
            config.nodes.append(instance)
        for call in _calls(full, block, where, found):
            _apply_call(config, instance, call, resources)
    return found


def _apply_call(config: Configuration, instance: NodeInstance, call: PrimitiveCall,
                resources: Resources) -> None:
    namespace = as_namespace(instance.namespace)
    wanted = RosName.make(call.name, namespace, instance.name).full
    for existing in instance.links:
        if existing.kind == LINK_KIND[call.kind] and _completes(existing.rosname.full, wanted) \
                and _types_agree(existing.type, call.type):
            existing.resource.links.remove(existing)
            existing.resource = resources.get(RESOURCE_OF_KIND[call.kind], wanted)
            existing.resource.links.append(existing)
            existing.rosname = RosName(existing.rosname.given, wanted, namespace_of(wanted))
            existing.type = existing.type or call.type
            existing.origin = "hint"
            return
    link(instance, call, {}, resources, config)


LINK_KIND = {kind: ("read" if kind == "declare" else kind) for kind in RESOURCE_OF_KIND}


def prune_orphans(config: Configuration) -> None:
    """Drop resources left without links once hints have moved links away."""
    config.topics[:] = [r for r in config.topics if r.links]
    config.services[:] = [r for r in config.services if r.links]
    config.actions[:] = [r for r in config.actions if r.links]
    config.parameters[:] = [p for p in config.parameters if p.links or p.set_by_launch]
