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
from collections.abc import Callable
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
    given = options.get("indent")
    indent = given if isinstance(given, int) and not isinstance(given, bool) else -1
    quick = indent >= 0 and options.keys() <= {"indent", "ensure_ascii"}

    def dump(value: Any) -> str:
        if quick:
            return _indented(value, indent, bool(options.get("ensure_ascii", True)))
        return json.dumps(value, allow_nan=False, **options)

    try:
        return dump(data)
    except ValueError:
        return dump(_finite(data))


_PLAIN = frozenset((str, int, float, bool, type(None)))
_SLOT = "\x00slot\x00"  # where a container goes in its parent's text (``_indented``)


class _NotPlain(Exception):
    """Data ``_indented`` leaves to ``json.dumps``."""


def _refuse(value: Any) -> Any:
    raise _NotPlain


def _indented(data: Any, indent: int, ensure_ascii: bool) -> str:
    """``json.dumps(data, indent=indent, ensure_ascii=ensure_ascii, allow_nan=False)``,
    the same text, about 1.7 times faster on a model's document: Python's encoder writes
    an indented text in Python, item by item; here each container's plain values (and
    empty containers) are written by its C encoder with the container's separator, the
    containers within put in their places (navigation2's 149 MB document: 2.8 s of CPU
    instead of 4.8). Data other than dictionaries, lists and tuples of strings, numbers,
    booleans and None, or a string that is the slot's text, goes to ``json.dumps``."""
    make = getattr(json.encoder, "c_make_encoder", None)
    if make is None:
        return json.dumps(data, indent=indent, ensure_ascii=ensure_ascii, allow_nan=False)
    strings = json.encoder.encode_basestring_ascii if ensure_ascii \
        else json.encoder.encode_basestring
    slot = strings(_SLOT)
    encoders: dict[int, Callable[[Any], str]] = {}
    out: list[str] = []

    def encoder(depth: int) -> Callable[[Any], str]:
        found = encoders.get(depth)
        if found is None:
            made = make(None, _refuse, strings, None, ": ", ",\n" + " " * (indent * depth),
                        False, False, False)
            found = encoders[depth] = lambda value: "".join(made(value, 0))
        return found

    def write(value: Any, depth: int) -> None:
        kind = type(value)
        if kind is dict:
            inner = [v for v in value.values() if type(v) not in _PLAIN and v]
            flat: Any = {k: (v if type(v) in _PLAIN or not v else _SLOT)
                         for k, v in value.items()} if inner else value
            opening, closing = "{", "}"
        elif kind is list or kind is tuple:
            inner = [v for v in value if type(v) not in _PLAIN and v]
            flat = [(v if type(v) in _PLAIN or not v else _SLOT) for v in value] \
                if inner else value
            opening, closing = "[", "]"
        elif kind in _PLAIN:
            out.append(encoder(0)(value))
            return
        else:
            raise _NotPlain
        if not value:
            out.append(opening + closing)
            return
        text = encoder(depth + 1)(flat)
        pad = " " * (indent * (depth + 1))
        parts = text[1:-1].split(slot)
        if len(parts) != len(inner) + 1:
            raise _NotPlain  # a string of the data holds the slot's text
        out.append(opening + "\n" + pad + parts[0])
        for item, part in zip(inner, parts[1:], strict=True):
            write(item, depth + 1)
            out.append(part)
        out.append("\n" + " " * (indent * depth) + closing)

    try:
        with held_back():
            write(data, 0)
    except (_NotPlain, RecursionError):
        return json.dumps(data, indent=indent, ensure_ascii=ensure_ascii, allow_nan=False)
    return "".join(out)


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
