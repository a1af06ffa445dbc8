"""One generic serialiser from the model to versioned JSON data.

Dataclass fields are written in declaration order. Field metadata steers it:
``{"json": False}`` leaves an index or back-reference out, ``{"json": "key"}`` renames
it, ``{"ref": True}`` writes a referenced entity as its ``name``, ``{"optional": True}``
writes a field only when it differs from its default (fields added to ``haros-arch/1``
after the fact, so documents without them stay as they were). A class may add
computed entries with ``JSON_HEAD`` (written first) and ``JSON_VIEWS`` (written last),
each a mapping from key to a function of the object.
"""

from __future__ import annotations

import dataclasses
import json
from typing import Any

from .. import SCHEMA
from ..collector import held_back
from .model import Model
from .rosname import RosName
from .runtime import Configuration
from .values import Value


def to_data(obj: Any) -> Any:
    """Turn a model object (or a container of them) into JSON-ready data."""
    kind = _KINDS.get(type(obj))
    if kind is None:
        kind = _kind(obj)
    if kind == "plain":
        return obj
    if kind == "dataclass":
        return _dataclass_to_data(obj)
    if kind == "list":
        return [v if type(v) in _PLAIN else to_data(v) for v in obj]
    if kind == "value":
        return obj.text
    if kind == "rosname":
        return obj.full
    if kind == "dict":
        return {str(k): to_data(v) for k, v in obj.items()}
    if kind == "set":
        return sorted(to_data(v) for v in obj)
    raise TypeError(f"cannot serialise {type(obj).__name__}")


_KINDS: dict[type, str] = {}  # what ``to_data`` does with an object of each type


def _kind(obj: Any) -> str:
    """What ``to_data`` does with ``obj`` (remembered for its type, but for classes)."""
    if obj is None or isinstance(obj, bool | int | float | str):
        kind = "plain"
    elif isinstance(obj, Value):
        kind = "value"
    elif isinstance(obj, RosName):
        kind = "rosname"
    elif isinstance(obj, type):
        return "other"  # a class (a dataclass's too) is not model data
    elif dataclasses.is_dataclass(obj):
        kind = "dataclass"
    elif isinstance(obj, dict):
        kind = "dict"
    elif isinstance(obj, list | tuple):
        kind = "list"
    elif isinstance(obj, set | frozenset):
        kind = "set"
    else:
        kind = "other"
    _KINDS[type(obj)] = kind
    return kind


# per dataclass: its head views, its written fields as (name, key, the default the field
# is left out at or ``_ALWAYS``, whether it is a reference), its optional views and its
# views
_Plan = tuple[dict[str, Any], tuple[tuple[str, str, Any, bool], ...], tuple[str, ...],
              dict[str, Any]]
_PLANS: dict[type, _Plan] = {}
_ALWAYS = object()  # a field written whatever its value (not ``optional``)
_PLAIN = frozenset({str, int, float, bool, type(None)})  # written as they are


def _plan(cls: type) -> _Plan:
    """What ``_dataclass_to_data`` writes of a class, read from its fields once."""
    plan = _PLANS.get(cls)
    if plan is None:
        written = []
        for f in dataclasses.fields(cls):
            key = f.metadata.get("json", f.name)
            if key is not False:
                written.append((f.name, key, _default(f) if f.metadata.get("optional")
                                else _ALWAYS, bool(f.metadata.get("ref"))))
        plan = (getattr(cls, "JSON_HEAD", {}), tuple(written),
                getattr(cls, "JSON_OPTIONAL_VIEWS", ()), getattr(cls, "JSON_VIEWS", {}))
        _PLANS[cls] = plan
    return plan


def _dataclass_to_data(obj: Any) -> dict[str, Any]:
    head, written, optional_views, views = _plan(type(obj))
    data: dict[str, Any] = {}
    for key, view in head.items():
        data[key] = to_data(view(obj))
    for name, key, default, ref in written:
        value = getattr(obj, name)
        if default is not _ALWAYS and value == default:
            continue
        if ref:
            data[key] = None if value is None else value.name
        elif type(value) in _PLAIN:  # the most common case, without a call
            data[key] = value
        else:
            data[key] = to_data(value)
    for key, view in views.items():
        value = view(obj)
        if value or key not in optional_views:
            data[key] = to_data(value)
    return data


def _default(f: dataclasses.Field[Any]) -> Any:
    """A field's default: one made by its factory, kept in the plan only to compare with
    (never handed out, so never changed)."""
    if f.default_factory is not dataclasses.MISSING:
        return f.default_factory()
    return None if f.default is dataclasses.MISSING else f.default


def model_to_data(model: Model) -> dict[str, Any]:
    """The versioned JSON document of DESIGN.md ("The JSON model"), with what reading it
    back needs to give the same model (``_read_back``)."""
    with held_back():  # hundreds of thousands of dictionaries that all live on
        data = {"schema": SCHEMA, **_dataclass_to_data(model)}
        listed = {id(node) for package in model.packages for node in package.nodes}
        for config, written in zip(model.configurations, data.get("configurations", ()),
                                   strict=True):
            _read_back(config, written, listed)
    return data


def _read_back(config: Configuration, data: dict[str, Any], listed: set[int]) -> None:
    """What ``load.from_data`` cannot find by name and place, written into ``data``:
    the node types instances run that no package lists (``listed``: an interface
    model's, a hint's, a command's arguments') under ``node_types`` whole, each instance
    naming its own by ``node_type``; a link's ``call`` when its node type's first call of
    its kind and place is not it (an index in the node type's calls), or when the node
    type does not list it (a plugin's call: the call itself)."""
    from .load import action_links, default_call, wire_call_of

    types: dict[int, int] = {}
    written: list[Any] = []
    for instance, entry in zip(config.nodes, data.get("nodes", ()), strict=True):
        node = instance.node
        if node is None or id(node) in listed:
            continue
        if id(node) not in types:
            types[id(node)] = len(written)
            written.append(to_data(node))
        entry["node_type"] = types[id(node)]
    if written:
        data["node_types"] = written
    index: dict[int, dict[Any, Any]] = {}
    positions: dict[int, dict[int, int]] = {}  # a node type's calls: id -> index
    actions = action_links(config)
    for link, entry in zip(config.links, data.get("links", ()), strict=True):
        call = link.call
        if call is None:
            continue
        given = default_call(link, entry, index)
        if given is None and link.origin == "action":
            given = wire_call_of(link, actions)
        if given is call or given == call:
            continue
        node = link.node.node
        at = None
        if node is not None:
            if id(node) not in positions:
                positions[id(node)] = {id(c): i for i, c in enumerate(node.calls)}
            at = positions[id(node)].get(id(call))
        entry["call"] = to_data(call) if at is None else at


def dumps(model: Model) -> str:
    return json_text(model_to_data(model), indent=2, ensure_ascii=False) + "\n"


def json_text(data: Any, **options: Any) -> str:
    """``json.dumps`` of ``data`` as JSON defines it, for what is written for a user or a
    browser: a float that is no number JSON has (infinity, a parameter's default of
    ``std::numeric_limits<double>::infinity()``, YAML's ``.inf``, in ros2_controllers'
    joint_trajectory_controller model; NaN) is the string ``"Infinity"``,
    ``"-Infinity"`` or ``"NaN"``. Python writes them as bare words, which JSON.parse
    refuses: a report holding one opened as a blank page."""
    try:
        return json.dumps(data, allow_nan=False, **options)
    except ValueError:
        return json.dumps(_finite(data), allow_nan=False, **options)


def _finite(value: Any) -> Any:
    if isinstance(value, float) and value != value:
        return "NaN"
    if isinstance(value, float) and value in (float("inf"), float("-inf")):
        return "Infinity" if value > 0 else "-Infinity"
    if isinstance(value, dict):
        return {key: _finite(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(item) for item in value]
    return value
