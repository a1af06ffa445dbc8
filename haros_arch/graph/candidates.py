"""Candidates for unknown names: which known resources a name with ``?`` may stand for."""

from __future__ import annotations

import re

from ..model.rosname import pattern_for
from ..model.runtime import Configuration, Parameter, Resource
from ..model.values import UNKNOWN_MARK


def compatible(a: Resource, b: Resource) -> bool:
    """Types agree, or one side does not know its type: no type, or a type with ``?``
    (rosserial's bridge publishes whatever the device asks, of type ``?``) that may be
    the other's."""
    if not a.types or not b.types or set(a.types) & set(b.types):
        return True
    return any(_may_be(x, y) or _may_be(y, x) for x in a.types for y in b.types)


def _may_be(unknown: str, other: str) -> bool:
    return UNKNOWN_MARK in unknown and re.match(pattern_for(unknown), other) is not None


def _rank(unknown: Resource, candidate: Resource) -> tuple[int, int, int, str]:
    """Shared types first, then as many segments (a ``?`` is most often one), then the
    longest common namespace, then the name. A name that begins with an unknown part
    (``?``, ``?/cmd_vel``, which may be global) is ranked as if relative, in the
    namespace of the node that uses it: a guess of the likeliest, as the name itself
    claims no namespace."""
    shared_types = len(set(unknown.types) & set(candidate.types))
    name = unknown.name
    if name.startswith(UNKNOWN_MARK) and unknown.links:
        name = unknown.links[0].node.namespace.rstrip("/") + "/" + UNKNOWN_MARK
    depth = abs(name.count("/") - candidate.name.count("/"))
    shared_segments = 0
    for mine, theirs in zip(name.split("/"), candidate.name.split("/"), strict=False):
        if mine != theirs:
            break
        shared_segments += 1
    return (-shared_types, depth, -shared_segments, candidate.name)


def find_candidates(config: Configuration) -> None:
    """Fill ``candidates`` of every resource whose name has ``?``, best match first."""
    for collection in (config.topics, config.services, config.actions, config.parameters):
        known = [r for r in collection if not r.is_unresolved]
        for resource in collection:
            if not resource.is_unresolved:
                continue
            written = resource.rosname.pattern
            if isinstance(resource, Parameter) and any(
                link.kind == "read" and link.node.ros_version == 1 for link in resource.links
            ):
                # a ROS 1 read of a name is a read of everything under it too (the
                # parameter server answers a namespace with its tree: diagnostic_aggregator
                # reads ``<ns>/analyzers`` whole, the namespace a service request names)
                written = written.removesuffix("$") + "(?:/.*)?$"
            pattern = re.compile(written)
            # a parameter is one name whatever the type of its value: a read of another
            # type still asks for it (roscpp rounds a double it is given for an int,
            # rotors' ``getParam("rotor_configuration/" + i + "/direction", int)`` of
            # ``direction: -1.0``); topics of other types are other topics
            typed = not isinstance(resource, Parameter)
            matches = [c for c in known if pattern.match(c.name)
                       and (not typed or compatible(resource, c))]
            resource.candidates = sorted(matches, key=lambda c: _rank(resource, c))
