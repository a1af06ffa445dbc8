"""Query results as plain data and as the runtime entities they involve."""

from __future__ import annotations

import os
from typing import Any

from ..model.conditions import Condition
from ..model.diagnostic import Diagnostic
from ..model.launch_tree import IncludeArg, LaunchItem, PackageUse
from ..model.location import NOWHERE, Location
from ..model.model import Model
from ..model.rosname import RosName
from ..model.runtime import Configuration, Link, NodeInstance, Parameter, Resource
from ..model.source import Node, Package, PrimitiveCall
from .access import Method, Pair
from .functions import Function


def plain(value: Any) -> Any:
    """A JSON-ready form: entities by their id, links as "kind node name"."""
    if value is None or isinstance(value, bool | int | float | str):
        return value
    if isinstance(value, NodeInstance | Resource):
        return value.id or value.name
    if isinstance(value, Link):
        return f"{value.kind} {value.node.name} {value.rosname.full}"
    if isinstance(value, Node):
        return f"executable:{value.name}"
    if isinstance(value, PrimitiveCall):
        return f"call {value.kind} {value.name} at {value.location}"
    if isinstance(value, Package):
        return f"package:{value.name}"
    if isinstance(value, Configuration):
        return f"configuration:{value.name}"
    if isinstance(value, Model):
        return f"project:{value.project}"
    if isinstance(value, RosName):
        return value.full
    if isinstance(value, Location):
        return str(value)
    if isinstance(value, Condition):
        return str(value)
    if isinstance(value, Pair):
        return [plain(value.key), plain(value.value)]
    if isinstance(value, PackageUse):
        return f"package {value.package} at {value.location}"
    if isinstance(value, IncludeArg):
        return f"argument {value.name} of the include of {value.file} at {value.location}"
    if isinstance(value, Function | Method):
        return repr(value)
    if isinstance(value, dict):
        return {str(k): plain(v) for k, v in value.items()}
    if isinstance(value, list | tuple | set | frozenset):
        return [plain(v) for v in value]
    return repr(value)


def entities(value: Any) -> list[Any]:
    """The runtime entities (node instances, resources, links) a result mentions."""
    found: list[Any] = []
    stack = [value]
    while stack:
        item = stack.pop()
        if isinstance(item, NodeInstance | Resource | Link | Node):
            found.append(item)
        elif isinstance(item, dict):
            stack.extend(reversed(list(item.values())))
        elif isinstance(item, list | tuple):
            stack.extend(reversed(item))
    return found


def entity_ids(items: list[Any]) -> tuple[str, ...]:
    ids: dict[str, None] = {}
    for item in items:
        if isinstance(item, Link):
            ids[item.node.id] = None
            ids[item.resource.id] = None
        elif isinstance(item, NodeInstance | Resource):
            ids[item.id] = None
        elif isinstance(item, Node):
            ids[f"executable:{item.name}"] = None
    return tuple(ids)


def location_of(item: Any) -> Location:
    if isinstance(item, Parameter | PackageUse | IncludeArg | Diagnostic):
        return item.location
    if isinstance(item, Link) and item.origin == "model" and item.node.location.file:
        # a call of an interface model is in code not in the workspace (an installed
        # package's, at the commit the model was made from): the place the user can act
        # on is where the launch file starts the node
        return item.node.location
    if isinstance(item, Link | NodeInstance | Node | PrimitiveCall):
        return item.location
    if isinstance(item, Resource) and item.links:
        # where it is made: a topic's first publisher, a service's or action's first
        # server (a finding about who publishes it points at a publisher, not at the
        # subscriber that happens to come first), else its first link
        makers = [link for link in item.links if link.kind in _MAKERS]
        return (makers or item.links)[0].location
    return NOWHERE


_MAKERS = frozenset({"publish", "server", "action-server"})


def best_location(items: list[Any]) -> Location:
    for item in items:
        where = location_of(item)
        if where.file:
            return where
    return NOWHERE


def place_of(match: Any) -> Location:
    """Where a match without runtime entities points: a diagnostic's, a package use's or
    an include argument's place, itself or among a returned mapping's values."""
    return best_location(placed(match))


def placed(match: Any) -> list[Any]:
    """The package uses, include arguments and diagnostics a match is about."""
    values = list(match.values()) if isinstance(match, dict) else [match]
    return [v for v in values if isinstance(v, PackageUse | IncludeArg | Diagnostic)]


def label(item: Any) -> str:
    """A short human name: "/talker publishes /chatter", "topic /chatter"."""
    verbs = {"publish": "publishes", "subscribe": "subscribes to", "server": "serves",
             "client": "calls", "action-server": "serves action",
             "action-client": "calls action", "read": "reads", "write": "sets"}
    if isinstance(item, Link):
        text = f"{item.node.name} {verbs.get(item.kind, item.kind)} {item.rosname.full}"
        return text + (f" ({item.type})" if item.type else "")
    if isinstance(item, NodeInstance):
        return f"node {item.name}"
    if isinstance(item, Resource):
        return f"{type(item).__name__.lower()} {item.name}"
    if isinstance(item, Node):
        return f"executable {item.name}"
    if isinstance(item, Condition):  # where it is written: two alike are two places
        return f"{item} at {item.location}" if item.location.file else str(item)
    if isinstance(item, LaunchItem) and item.kind == "file":  # absence.Known.elsewhere
        return f"nodes started elsewhere ({os.path.basename(item.name)} starts none)"
    if isinstance(item, LaunchItem) and item.kind == "include":
        if item.detail == "action":
            return f"action not interpreted ({item.name})"
        if item.detail == "container":
            return f"container {item.name} (started elsewhere)"
        if item.detail == "process":
            return f"process {item.name} (a ROS command not interpreted)"
        return f"include {item.name} (not read)"
    return str(plain(item))
