"""Parameter values as roslaunch computes them: typing, YAML, flattening.

``convert_value`` follows roslaunch's rules for ``<param value=... type=...>`` (auto
typing: a dot means float, else int unless there is an underscore, then true/false,
else string). YAML (``<rosparam>``, ``type="yaml"``) is read with a safe loader that
also knows rosparam's ``!degrees`` / ``!radians`` tags and ``deg(...)`` / ``rad(...)``
scalars; the angle expressions go through our own evaluator, never Python's ``eval``.
A mapping loaded into a name is flattened into one parameter per leaf, as the
parameter server stores it.
"""

from __future__ import annotations

import base64
import math
import re
from typing import Any

import yaml

from ... import safe_yaml
from ...model.values import scalar_type
from .. import expression


class ParamError(ValueError):
    """A value roslaunch would refuse."""


def convert_value(text: str, kind: str) -> Any:
    """roslaunch's ``convert_value``; raises ``ParamError`` where roslaunch raises."""
    kind = kind.lower()
    try:
        if kind == "auto":
            try:
                if "." in text:
                    return float(text)
                if "_" not in text:
                    return int(text)
            except ValueError:
                pass
            if text.lower() in ("true", "false"):
                return text.lower() == "true"
            return text
        if kind in ("str", "string"):
            return text
        if kind == "int":
            return int(text)
        if kind == "double":
            return float(text)
        if kind in ("bool", "boolean"):
            lowered = text.lower().strip()
            if lowered in ("true", "1"):
                return True
            if lowered in ("false", "0"):
                return False
            raise ParamError(f"{lowered} is not a '{kind}' type")
        if kind == "yaml":
            return load_yaml(text)
    except ParamError:
        raise
    except ValueError as err:
        raise ParamError(str(err)) from None
    raise ParamError(f"unknown type '{kind}'")


def type_name(value: Any) -> str:
    if isinstance(value, Binary):  # before str, which it subclasses here
        return "binary"  # roslaunch's xmlrpc Binary: an XML-RPC base64 value
    scalar = scalar_type(value)
    if scalar is not None:
        return scalar
    if isinstance(value, (list, tuple)):
        return "list"
    if isinstance(value, dict):
        return "dict"
    return "yaml"


class Binary(str):
    """A ``binfile`` or ``!!binary`` value, kept as its base64 text."""

    @classmethod
    def of(cls, data: bytes) -> Binary:
        return cls(base64.b64encode(data).decode("ascii"))


def _radians(loader: yaml.SafeLoader, node: yaml.Node) -> float:
    text = str(loader.construct_scalar(node)).strip()  # type: ignore[arg-type]
    if text.startswith("rad("):
        text = text[4:-1]
    value = expression.evaluate(text, {"pi": math.pi}.__getitem__, expression.MATH)
    if isinstance(value, expression.Unknown) or not isinstance(value, (int, float)):
        raise ParamError(f"invalid radian expression: {text}")
    return float(value)


def _degrees(loader: yaml.SafeLoader, node: yaml.Node) -> float:
    text = str(loader.construct_scalar(node))  # type: ignore[arg-type]
    if text.startswith("deg("):
        text = text.strip()[4:-1]
    try:
        return float(text) * math.pi / 180.0
    except ValueError:
        raise ParamError(f"invalid degree value: {text}") from None


def _binary(loader: yaml.SafeLoader, node: yaml.Node) -> Binary:
    text = str(loader.construct_scalar(node))  # type: ignore[arg-type]
    return Binary.of(base64.b64decode(text.encode("ascii")))


class RosparamLoader(yaml.SafeLoader):
    """The safe loader plus rosparam's angle tags (without mutating yaml.SafeLoader)."""


RosparamLoader.add_constructor("!radians", _radians)
RosparamLoader.add_constructor("!degrees", _degrees)
RosparamLoader.add_constructor("tag:yaml.org,2002:binary", _binary)
RosparamLoader.add_implicit_resolver("!degrees", re.compile(r"^deg\([^\)]*\)$"), "deg(")
RosparamLoader.add_implicit_resolver("!radians", re.compile(r"^rad\([^\)]*\)$"), "rad(")


def load_yaml(text: str) -> Any:
    """One YAML document, safely; aliases and nesting are bounded (``safe_yaml``)."""
    try:
        return safe_yaml.load(text, RosparamLoader)
    except yaml.YAMLError as err:  # the reader refuses control characters (DEL, form feed)
        raise ParamError(f"invalid YAML: {err}") from None


def join(namespace: str, name: str) -> str:
    """rosgraph's ``ns_join``: a global or private name stays as it is."""
    if name.startswith(("/", "~")):
        return name
    if not namespace:
        return name
    return (namespace if namespace.endswith("/") else namespace + "/") + name


def flatten(name: str, value: Any) -> list[tuple[str, Any]]:
    """Leaf parameters for ``value`` loaded at ``name`` (mappings unrolled, in order)."""
    if isinstance(value, dict):
        out: list[tuple[str, Any]] = []
        for key, item in value.items():
            out.extend(flatten(join(name, str(key)), item))
        return out
    return [(name, value)]
