"""What a query may touch: the allow-list of model fields per class, declared as data.

A query reads a value's attribute only when the value's class (or a base class) lists
the name here; everything else is an error that lists the names that are allowed.
Strings expose a few read-only methods. Nothing here can write: the model is read-only
to queries because no listed name is a setter or a method that mutates.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from ..model.conditions import Condition
from ..model.diagnostic import Diagnostic
from ..model.launch_tree import IncludeArg, PackageUse
from ..model.location import Location
from ..model.model import Model
from ..model.rosname import RosName
from ..model.runtime import (
    Action,
    ActionClientLink,
    ActionServerLink,
    Configuration,
    Link,
    NodeInstance,
    Parameter,
    ParamReadLink,
    ParamWriteLink,
    PublishLink,
    Remap,
    Resource,
    Service,
    ServiceClientLink,
    ServiceProviderLink,
    SubscribeLink,
    Topic,
)
from ..model.source import Dependency, Node, Package, PrimitiveCall
from ..model.values import UNKNOWN_MARK


@dataclass(frozen=True)
class Pair:
    """One entry of a mapping walked by a path (``configs/args``)."""

    key: Any
    value: Any


_LINK = ("kind", "node", "rosname", "name", "type", "queue_size", "qos", "latch",
         "conditions", "undecided_conditions", "location", "call", "resource", "origin")
_RESOURCE = ("name", "id", "rosname", "types", "conditions", "is_unresolved", "links",
             "candidates")

# class -> the attribute names a query may read; subclasses add to their bases'
FIELDS: dict[type, tuple[str, ...]] = {
    Model: ("project", "packages", "configs", "configurations", "nodes", "files",
            "diagnostics"),
    Package: ("name", "path", "build_type", "version", "format", "dependencies",
              "plugins", "nodes", "location"),
    Dependency: ("name", "kind", "condition"),
    Node: ("package", "executable", "name", "kind", "language", "sources", "calls",
           "rosname", "conditions", "location", "completeness", "completeness_reasons",
           "is_complete", "model"),
    PrimitiveCall: ("kind", "name", "type", "queue_size", "qos", "latch", "callback",
                    "conditions", "location", "name_param", "name_default", "origin",
                    "has_default", "default", "searched", "tested", "handle_namespace",
                    "deletes", "queue_size_missing"),
    Configuration: ("name", "launch", "args", "nodes", "topics", "services", "actions",
                    "parameters", "links", "direct_links", "diagnostics", "package_paths",
                    "incomplete_nodes", "remaps", "package_uses", "include_args"),
    PackageUse: ("package", "user", "kind", "test", "guard", "optional", "chosen_by",
                 "location"),
    IncludeArg: ("name", "value", "use", "unseen", "file", "declared", "hint", "location"),
    Remap: ("source", "target", "text", "nodes", "node", "users", "unseen", "conditional",
            "near", "hint", "node_names", "location"),
    NodeInstance: ("name", "id", "node", "namespace", "remaps", "args", "conditions",
                   "location", "rosname", "links", "publishers", "subscribers", "servers",
                   "clients", "action_servers", "action_clients", "reads", "writes",
                   "origin", "ros_version", "test", "hosted", "offered", "remaps_applied",
                   "completeness", "completeness_reasons", "is_complete"),
    Resource: _RESOURCE,
    Topic: ("publishers", "subscribers", "is_disconnected"),
    Service: ("servers", "clients", "is_disconnected"),
    Action: ("servers", "clients", "is_disconnected"),
    Parameter: ("value", "type", "launch_type", "set_by_launch", "launch_location",
                "location", "readers", "writers", "reads", "writes", "setters", "is_set",
                "is_read",
                "has_default", "read_as_part_of", "for_test", "setting"),
    Link: _LINK,
    PublishLink: ("topic", "topic_name"),
    SubscribeLink: ("topic", "topic_name"),
    ServiceProviderLink: ("service", "service_name"),
    ServiceClientLink: ("service", "service_name"),
    ActionServerLink: ("action", "action_name"),
    ActionClientLink: ("action", "action_name"),
    ParamReadLink: ("parameter", "param_name"),
    ParamWriteLink: ("parameter", "param_name"),
    RosName: ("given", "full", "namespace", "own", "is_global", "is_private",
              "is_relative", "is_unresolved", "pattern"),
    Location: ("package", "file", "line", "column"),
    Condition: ("text", "kind", "statement", "location"),
    Diagnostic: ("code", "severity", "message", "location"),
    Pair: ("key", "value"),
}


def _calls(kind: str) -> Callable[[Node], list[PrimitiveCall]]:
    return lambda node: [call for call in node.calls if call.kind == kind]


# computed names that the model does not have under that name (HAROS's spellings)
def _is_latched(link: Link) -> bool:
    """A late subscriber still gets the last message: ROS 1 ``latch`` or ROS 2
    transient-local durability."""
    return link.latch or (isinstance(link.qos, dict)
                          and str(link.qos.get("durability", "")).lower() == "transient_local")


def _wire_type(link: Any) -> str | None:
    from ..extract.cpp.interfaces import wire_key  # the definitions we know, read lazily

    return wire_key(link.type, kind="srv" if link.kind in ("server", "client") else "msg")


# roscpp's any-message (md5sum ``*``): a subscriber of it connects to a publisher of any
# type, a publisher of it (topic_tools' relay) sends the type it received
_ANY_TYPES = frozenset({"topic_tools/ShapeShifter"})


def _known_type(link: Any) -> str | None:
    """The type when it is known statically: None for no type, for one with the
    unknown mark (a call the parse could not resolve is typed ``?``), which the type
    checks must not compare as if it were a type, and for topic_tools' ShapeShifter,
    which stands for any type."""
    found = link.type
    return found if isinstance(found, str) and found and UNKNOWN_MARK not in found and (
        found not in _ANY_TYPES) else None


def _is_offered(link: Any) -> bool:
    """Made by the model of a plugin its host loads because it loads every class it finds
    (mavros'): its node's (ROS 2, ``NodeInstance.offered``) or its call's on the host
    (ROS 1, ``PrimitiveCall.offered``)."""
    return link.origin == "model" and (bool(link.node.offered) or (
        link.call is not None and bool(link.call.offered)))


def _modelled(instance: NodeInstance) -> bool:
    """What it runs is known from an interface model (its code is not in the workspace)."""
    return instance.node is not None and instance.node.model is not None


VIEWS: dict[type, dict[str, Callable[[Any], Any]]] = {
    # what a ROS 1 connection compares (the md5sum of the definition) where we know it;
    # ``is_modelled``: made by code known only from an interface model (a modelled plugin's
    # anywhere; on a modelled node, all but the calls of the robot description's Gazebo
    # plugins a modelled gazebo instance loads, ``description``)
    Link: {"is_latched": _is_latched, "wire_type": _wire_type, "known_type": _known_type,
           "is_modelled": lambda link: link.origin == "model" or (
               link.origin != "description" and _modelled(link.node)),
           "is_offered": _is_offered},
    Parameter: {"reads": lambda p: p.readers, "writes": lambda p: p.writers},
    NodeInstance: {"is_modelled": _modelled},
    Node: {"advertise": _calls("publish"), "subscribe": _calls("subscribe"),
           "service": _calls("server"), "client": _calls("client"),
           "read_param": _calls("read"), "write_param": _calls("write")},
}

STRING_METHODS = frozenset({
    "startswith", "endswith", "lower", "upper", "strip", "lstrip", "rstrip", "find",
    "count", "split",
})

PRIMITIVES = (str, int, float, bool, type(None))


@dataclass(frozen=True)
class Method:
    """A read-only string method bound to its string, callable from a query."""

    target: str
    name: str


_CACHE: dict[type, dict[str, Callable[[Any], Any]]] = {}


def readers_of(cls: type) -> dict[str, Callable[[Any], Any]]:
    """Every attribute a query may read on instances of ``cls``, with how to read it."""
    found = _CACHE.get(cls)
    if found is not None:
        return found
    found = {}
    for base in reversed(cls.__mro__):
        for name in FIELDS.get(base, ()):
            found[name] = _getter(name)
        found.update(VIEWS.get(base, {}))
    _CACHE[cls] = found
    return found


def _getter(name: str) -> Callable[[Any], Any]:
    def read(obj: Any) -> Any:
        return getattr(obj, name)
    return read


def is_model_value(value: Any) -> bool:
    return bool(readers_of(type(value)))
