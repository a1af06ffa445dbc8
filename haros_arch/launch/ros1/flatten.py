"""One roslaunch XML file with everything resolved (``haros-arch launch FILE --flatten``).

Written from the launch model, not from the files: every include is already inlined,
every argument substituted and every decided condition applied. Each node is written
with its final namespace, name, remaps, environment and attributes; each parameter as
its full name and typed value (``type="yaml"`` for lists and empty mappings), so the
flattened file sets what the original sets. What cannot be written as it is (a value or
condition not known statically, a ``command=`` parameter) is kept out and said, both in
a comment at its place and in the notes returned.
"""

from __future__ import annotations

import json
import math
import re
from collections import Counter
from typing import Any

import yaml
from lxml import etree

from ..model import LaunchModel, NodeDecl
from .dump import leaf_parameters
from .params import Binary

_ANON = re.compile(r"^(.*/)([^/?$]+)_\?$")  # what $(anon x) gives: x_ and an unknown


def flatten(model: LaunchModel) -> tuple[str, list[str]]:
    """The flattened launch file's text and notes on what it leaves out."""
    root = etree.Element("launch")
    notes: list[str] = []

    def note(text: str) -> None:
        notes.append(text)
        root.append(etree.Comment(f" haros-arch: {_comment(text)} "))

    if model.files:
        root.append(etree.Comment(f" flattened by haros-arch from {_comment(model.files[0])} "))
    for name, address in model.machines.items():
        etree.SubElement(root, "machine", name=name, address=address)
    anon = anonymous_names(model)
    for ns in dict.fromkeys(model.clear_params):
        ns = _anon_prefix(ns, anon)
        if "?" in ns:
            note(f"namespace {ns} (clear_params) is not known statically; left out")
            continue
        etree.SubElement(root, "group", ns=ns, clear_params="true")
    for name, value in leaf_parameters(model).items():
        name = _anon_prefix(name, anon)
        if value is None or "?" in name:
            note(f"parameter {name} is not known statically; left out")
            continue
        if "$(" in str(value) or not isinstance(value, str | int | float | list | dict):
            note(f"parameter {name} cannot be written as a plain value; left out")
            continue
        if isinstance(value, Binary):  # rosparam's !!binary is an XML-RPC Binary
            etree.SubElement(root, "rosparam", param=name).text = f"!!binary {value}"
            continue
        etree.SubElement(root, "param", {"name": name, **_typed(value)})
    for node in model.nodes:
        _node(root, node, anon.get(node.name), note)
    for name in model.deleted_params:
        etree.SubElement(root, "rosparam", command="delete", param=name)
    text = etree.tostring(root, pretty_print=True, encoding="unicode")
    return text, notes


def anonymous_names(model: LaunchModel) -> dict[str, str]:
    """``/ns/x_?`` of a node named ``$(anon x)`` -> ``/ns/$(anon x)``. A name two such
    nodes share (``$(anon x)`` in two includes: two names) is left out: one ``$(anon x)``
    in the flat file would give them one name."""
    seen = Counter(node.name for node in model.nodes)
    out: dict[str, str] = {}
    for node in model.nodes:
        match = _ANON.match(node.name)
        if node.anonymous and match and seen[node.name] == 1:
            out[node.name] = f"{match.group(1)}$(anon {match.group(2)})"
    return out


def _anon_prefix(name: str, anon: dict[str, str]) -> str:
    """A parameter or namespace under an anonymous node, written with ``$(anon)``."""
    for rendered, written in anon.items():
        if name == rendered or name.startswith(rendered + "/"):
            return written + name[len(rendered):]
    return name


def _node(root: etree._Element, node: NodeDecl, anon: str | None, note: Any) -> None:
    where = f" ({node.location})" if node.location.file else ""
    if node.conditions:
        conds = " and ".join(str(c) for c in node.conditions)
        note(f"node {node.name}{where} runs only {conds}, not known statically; left out")
        return
    base = (anon or node.name).rsplit("/", 1)[-1]
    written = [node.package, node.executable, *(f"{a} {b}" for a, b in node.remaps)]
    if ("?" in node.name and anon is None) or "$(" in node.args + node.name or any(
            "?" in text for text in written):
        note(f"node {node.name}{where} has parts not known statically; left out")
        return
    attrs = {"pkg": node.package, "type": node.executable}
    if node.is_test:
        attrs["test-name"] = base
    else:
        attrs["name"] = base
    if node.namespace not in ("", "/"):
        attrs["ns"] = node.namespace
    optional = {"args": node.args, "machine": node.machine, "output": node.output,
                "cwd": node.cwd, "launch-prefix": node.launch_prefix}
    attrs.update({k: v for k, v in optional.items() if v})
    if node.respawn:
        attrs["respawn"] = "true"
        if node.respawn_delay:
            attrs["respawn_delay"] = repr(node.respawn_delay)
    if node.required:
        attrs["required"] = "true"
    element = etree.SubElement(root, "test" if node.is_test else "node", attrs)
    for source, target in node.remaps:
        etree.SubElement(element, "remap", {"from": source, "to": target})
    for name, value in node.env:
        etree.SubElement(element, "env", name=name, value=value)


def _typed(value: Any) -> dict[str, str]:
    """``type`` and ``value`` attributes that give the same typed value back."""
    if isinstance(value, bool):
        return {"type": "bool", "value": str(value).lower()}
    if isinstance(value, int):
        return {"type": "int", "value": str(value)}
    if isinstance(value, float):
        text = "nan" if math.isnan(value) else repr(value)
        return {"type": "double", "value": text}
    if isinstance(value, str) and value == value.strip() and value.isprintable():
        return {"type": "str", "value": value}
    if isinstance(value, str):  # roslaunch strips value=: a YAML (JSON) quoted string
        return {"type": "yaml", "value": json.dumps(value)}
    return {"type": "yaml", "value": yaml.safe_dump(value, default_flow_style=True,
                                                   sort_keys=False).strip()}


def _comment(text: str) -> str:
    return text.replace("--", "- -")
