"""Query functions for checks that claim something is absent, and that must stay fast.

``unknown_users(config, resource)``: the node instances of partial or unknown interface,
or with a name not known statically, that could use the resource through a call the
model does not show. A check that says
"nobody publishes this" or "nobody reads this" is a fact only when this list is empty.

``similar_to(word, items)``: the items (resources, links or strings) whose own name is the
word or within edit distance 2 of it, through an index built once per list, not by
comparing every pair.
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable
from itertools import combinations
from typing import Any
from weakref import WeakKeyDictionary

from ..model.runtime import Configuration, Link, NodeInstance, Parameter, Resource
from .errors import QueryTypeError

Charge = Callable[[int], None]


class _Known:
    """What ``unknown_users`` needs of a configuration, built once per configuration."""

    def __init__(self, config: Configuration) -> None:
        self.size = (len(config.nodes), len(config.links))
        self.by_name: dict[str, NodeInstance] = {}
        for node in config.nodes:
            self.by_name.setdefault(node.name, node)
        self.incomplete = config.incomplete_nodes
        # resource -> nodes that use a name with "?" that may stand for it
        self.guessed: dict[int, list[NodeInstance]] = {}
        for collection in (config.topics, config.services, config.actions,
                           config.parameters):
            for unresolved in collection:
                if not unresolved.is_unresolved:
                    continue
                users = list(dict.fromkeys(link.node for link in unresolved.links))
                for candidate in unresolved.candidates:
                    self.guessed.setdefault(id(candidate), []).extend(users)


_KNOWN: WeakKeyDictionary[Configuration, _Known] = WeakKeyDictionary()


def _known(config: Configuration) -> _Known:
    known = _KNOWN.get(config)
    if known is None or known.size != (len(config.nodes), len(config.links)):
        known = _KNOWN[config] = _Known(config)
    return known


def owner_of(config: Configuration, parameter: Parameter) -> NodeInstance | None:
    """The node instance a parameter is private to (``/ns/node/param`` of ``/ns/node``;
    a ROS 2 parameter always belongs to its node), or None for a shared one."""
    by_name = _known(config).by_name
    name = parameter.name
    while "/" in name.rstrip("/"):
        name = name.rstrip("/").rsplit("/", 1)[0]
        found = by_name.get(name)
        if found is not None:
            return found
    return None


def unknown_users(charge: Charge, config: Any, resource: Any) -> list[NodeInstance]:
    """The node instances that could use ``resource`` through a call the model does not
    show: those of partial or unknown interface, and those that use a name with ``?``
    that may stand for it (a ``getParam(name_read_at_run_time)``).

    A node of partial or unknown interface could publish, subscribe, serve or call any
    topic, service or action name, and read or set any shared parameter; a private
    parameter (ROS 1 ``/node/param``, every ROS 2 parameter) only its own node."""
    if isinstance(resource, Link):
        resource = resource.resource
    if not isinstance(config, Configuration) or not isinstance(resource, Resource):
        raise QueryTypeError("unknown_users() takes a configuration and a topic, service, "
                             "action, parameter or link")
    known = _known(config)
    charge(1)
    found: list[NodeInstance] = list(known.incomplete)
    if found and isinstance(resource, Parameter):
        owner = owner_of(config, resource)
        if owner is not None:
            found = [] if owner.is_complete else [owner]
    found.extend(known.guessed.get(id(resource), ()))
    charge(len(found) // 64)
    return list(dict.fromkeys(found))


MAX_DISTANCE = 2
_LONGEST_INDEXED = 48  # longer words are compared one by one (there are few)
_INDEXES: OrderedDict[int, tuple[Any, dict[str, list[int]], list[int]]] = OrderedDict()
_KEEP_INDEXES = 16


def _own(item: Any) -> str | None:
    if isinstance(item, str):
        return item
    if isinstance(item, Link | Resource):
        return item.rosname.own
    return None


def _deletions(word: str) -> set[str]:
    """The word with up to two characters left out (symmetric-delete candidates)."""
    found = {word}
    for count in range(1, min(MAX_DISTANCE, len(word)) + 1):
        for places in combinations(range(len(word)), count):
            found.add("".join(c for i, c in enumerate(word) if i not in places))
    return found


def _index(items: list[Any], charge: Charge) -> tuple[dict[str, list[int]], list[int]]:
    """Deletion variants -> places of items, and the places of items too long to index."""
    cached = _INDEXES.get(id(items))
    if cached is not None and cached[0] is items:
        _INDEXES.move_to_end(id(items))
        return cached[1], cached[2]
    index: dict[str, list[int]] = {}
    long: list[int] = []
    for place, item in enumerate(items):
        own = _own(item)
        if own is None:
            raise QueryTypeError("similar_to() compares names: strings, resources or links")
        if len(own) > _LONGEST_INDEXED:
            long.append(place)
            continue
        variants = _deletions(own)
        charge(len(variants))
        for variant in variants:
            index.setdefault(variant, []).append(place)
    _INDEXES[id(items)] = (items, index, long)
    while len(_INDEXES) > _KEEP_INDEXES:
        _INDEXES.popitem(last=False)
    return index, long


def similar_to(charge: Charge, word: Any, items: Any) -> list[Any]:
    """The items whose own name equals ``word``'s or is within edit distance 2 of it."""
    from .functions import edit_distance

    word = _own(word)
    if word is None or not isinstance(items, list):
        raise QueryTypeError("similar_to() takes a name (or a resource or link) and a list")
    index, long = _index(items, charge)
    places = set(long)
    probes = _deletions(word) if len(word) <= _LONGEST_INDEXED else {word}
    charge(len(probes))
    for probe in probes:
        places.update(index.get(probe, ()))
    return [items[place] for place in sorted(places)
            if edit_distance(charge, word, _own(items[place])) <= MAX_DISTANCE]
