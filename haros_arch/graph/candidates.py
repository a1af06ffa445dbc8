"""Candidates for unknown names: which known resources a name with ``?`` may stand for."""

from __future__ import annotations

import re

from ..model.runtime import Configuration, Resource


def compatible(a: Resource, b: Resource) -> bool:
    """Types agree, or one side does not know its type."""
    return not a.types or not b.types or bool(set(a.types) & set(b.types))


def _rank(unknown: Resource, candidate: Resource) -> tuple[int, int, int, str]:
    """Shared types first, then as many segments (a ``?`` is most often one), then the
    longest common namespace, then the name."""
    shared_types = len(set(unknown.types) & set(candidate.types))
    depth = abs(unknown.name.count("/") - candidate.name.count("/"))
    shared_segments = 0
    for mine, theirs in zip(unknown.name.split("/"), candidate.name.split("/"), strict=False):
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
            pattern = re.compile(resource.rosname.pattern)
            matches = [c for c in known if pattern.match(c.name) and compatible(resource, c)]
            resource.candidates = sorted(matches, key=lambda c: _rank(resource, c))
