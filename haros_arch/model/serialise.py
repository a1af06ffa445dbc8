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
from .model import Model
from .rosname import RosName
from .values import Value


def to_data(obj: Any) -> Any:
    """Turn a model object (or a container of them) into JSON-ready data."""
    if obj is None or isinstance(obj, bool | int | float | str):
        return obj
    if isinstance(obj, Value):
        return obj.text
    if isinstance(obj, RosName):
        return obj.full
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        return _dataclass_to_data(obj)
    if isinstance(obj, dict):
        return {str(k): to_data(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple | set | frozenset):
        items = [to_data(v) for v in obj]
        return sorted(items) if isinstance(obj, set | frozenset) else items
    raise TypeError(f"cannot serialise {type(obj).__name__}")


def _dataclass_to_data(obj: Any) -> dict[str, Any]:
    data: dict[str, Any] = {}
    for key, view in getattr(obj, "JSON_HEAD", {}).items():
        data[key] = to_data(view(obj))
    for f in dataclasses.fields(obj):
        key = f.metadata.get("json", f.name)
        if key is False:
            continue
        value = getattr(obj, f.name)
        if f.metadata.get("optional") and value == _default(f):
            continue
        if f.metadata.get("ref"):
            data[key] = None if value is None else value.name
        else:
            data[key] = to_data(value)
    optional_views = getattr(obj, "JSON_OPTIONAL_VIEWS", ())
    for key, view in getattr(obj, "JSON_VIEWS", {}).items():
        value = view(obj)
        if value or key not in optional_views:
            data[key] = to_data(value)
    return data


def _default(f: dataclasses.Field[Any]) -> Any:
    if f.default_factory is not dataclasses.MISSING:
        return f.default_factory()
    return None if f.default is dataclasses.MISSING else f.default


def model_to_data(model: Model) -> dict[str, Any]:
    """The versioned JSON document of DESIGN.md ("The JSON model")."""
    return {"schema": SCHEMA, **_dataclass_to_data(model)}


def dumps(model: Model) -> str:
    return json.dumps(model_to_data(model), indent=2, ensure_ascii=False) + "\n"
