"""One ROS 2 launch file with everything resolved (``haros-arch launch FILE --flatten``).

Written from the launch model, as the ROS 1 flattener is: every include is inlined,
every argument and substitution performed, every decided condition applied, and each
node written with its final name, absolute namespace, arguments, remaps (``SetRemap``
and ``--ros-args -r`` ones included) and parameters as values (``SetParameter``,
parameter files and ``-p`` already applied in launch_ros's order). A component is
written inside its container when the container is in the same file and starts under
the same conditions (``node_container``), else loaded into it by name
(``load_composable_node``). A node started by a ``TimerAction`` is written inside a
timer of the same period.

Three formats of the same content: ROS 2 XML, YAML and Python. A parameter value is
written as launch_ros reads it back: in XML, text that is YAML for the value (``'1'``
for the string "1"), checked by reading it back as the loader does; in YAML, the value
as YAML types it and in Python the literal (launch_yaml and launch_ros keep a string a
string). What
cannot be written (a part not known statically, a condition not decided, a component
with no name in XML or YAML, a node started by an event handler, which is written to
start at once) is said both in a comment at its place and in the notes returned.
``facts`` is what a flattened file must keep: the test and ``bench/launch_flatten.py``
compare it between the original and the flat file.
"""

from __future__ import annotations

import json
import math
import re
import shlex
from dataclasses import dataclass, field
from typing import Any

import yaml
from lxml import etree

from ..model import LaunchModel, NodeDecl
from . import naming

FORMATS = ("xml", "yaml", "python")
_PERIOD = re.compile(r"period=([^)\s]+)")


@dataclass
class FlatNode:
    """One node to write: a plain node, a container, or a component."""

    decl: NodeDecl
    params: list[tuple[str, Any]]  # (dotted key, value) in launch order
    timers: list[str] = field(default_factory=list)  # periods, outermost first
    components: list[FlatNode] = field(default_factory=list)
    comments: list[str] = field(default_factory=list)


@dataclass
class Flat:
    """The flattened launch description: nodes and loads into named containers."""

    source: str
    items: list[FlatNode] = field(default_factory=list)
    comments: list[str] = field(default_factory=list)  # nodes left out
    notes: list[str] = field(default_factory=list)
    # indices in the model's nodes of what is not written as it is in the original
    left_out: set[int] = field(default_factory=set)
    params_left_out: set[tuple[int, str]] = field(default_factory=set)
    started_at_once: set[int] = field(default_factory=set)  # by an event handler


def flatten(model: LaunchModel, fmt: str = "xml") -> tuple[str, list[str]]:
    """The flattened launch file's text in ``fmt`` and notes on what it leaves out."""
    flat = collect(model, fmt)
    writer = {"xml": as_xml, "yaml": as_yaml, "python": as_python}[fmt]
    return writer(flat), flat.notes


def collect(model: LaunchModel, fmt: str = "python") -> Flat:
    """What the flattened file in ``fmt`` holds, in launch order, with what it leaves out
    said."""
    flat = Flat(model.files[0] if model.files else "")
    params: dict[int, list[tuple[str, Any]]] = {}
    for param in model.params:
        if param.owner is None or param.key is None:
            continue
        if param.pattern is None:
            params.setdefault(param.owner, []).append((param.key, param.value))
        elif not _kept_files(model.nodes[param.owner]):  # a section for a node name
            decl = model.nodes[param.owner]
            why = "a component's parameter file" if decl.composable else (
                "a parameter file that is rewritten")
            text = (f"parameter {decl.name}:{param.key} for nodes named {param.pattern} "
                    f"comes from {why}, not kept as a path; left out")
            flat.notes.append(text)
            flat.comments.append(text)
            flat.params_left_out.add((param.owner, param.key))
    made: dict[int, FlatNode] = {}
    for index, decl in enumerate(model.nodes):
        node = _node(index, decl, params.get(index, []), flat, fmt)
        if node is not None and decl.composable and fmt != "python" and (
                _base(decl) is None):
            _leave_out(flat, index, f"node {decl.name}{_where(decl)} is a component with "
                       f"no name, which launch_ros's {fmt} front end refuses; left out "
                       "(--format python keeps it)")
        elif node is not None:
            made[index] = node
    containers: dict[str, FlatNode] = {}
    names = [d.name for d in model.nodes if not d.composable]
    for index, node in made.items():
        decl = node.decl
        if not decl.composable:
            flat.items.append(node)
            if names.count(decl.name) == 1 and "?" not in decl.name:
                containers[decl.name] = node
            continue
        host = containers.get(decl.container or "")
        if host is not None and host.decl.conditions == decl.conditions:
            host.components.append(node)
        elif decl.container is None or "?" in decl.container or "$(" in decl.container:
            _leave_out(flat, index, f"node {decl.name}{_where(decl)} is loaded into a "
                       "container not known statically; left out")
        else:
            flat.items.append(node)
    return flat


def _node(index: int, decl: NodeDecl, params: list[tuple[str, Any]], flat: Flat,
          fmt: str) -> FlatNode | None:
    where = _where(decl)
    timers: list[str] = []
    comments: list[str] = []
    for cond in decl.conditions:
        period = _period(cond.text) if cond.statement == "timer" else None
        if period is not None:
            timers.append(period)
        elif cond.statement == "event":
            text = f"node {decl.name}{where} starts {cond.text} in the original; " \
                   "written to start at once"
            flat.notes.append(text)
            comments.append(text)
            flat.started_at_once.add(index)
        else:
            _leave_out(flat, index, f"node {decl.name}{where} runs only {cond}, not known "
                       "statically; left out")
            return None
    base = decl.name.rsplit("/", 1)[-1]
    written = [decl.package, decl.executable, decl.namespace, decl.args,
               decl.container or "", *(f"{a} {b}" for a, b in decl.remaps)]
    if (base != "?" and "?" in base) or any("?" in t or "$(" in t for t in written) or (
            "$(" in decl.name):
        _leave_out(flat, index, f"node {decl.name}{where} has parts not known statically; "
                   "left out")
        return None
    kept: list[tuple[str, Any]] = []
    for key, value in params:
        writable = (_py_plain(value) if fmt == "python" else _yaml_ok(value) if fmt == "yaml"
                    else param_text(value) is not None)
        if "?" in key or "$(" in key or value is None or not writable:
            why = "is not known statically" if "?" in key or value is None else (
                f"cannot be written as a {fmt} value ({value!r:.60})")
            text = f"parameter {decl.name}:{key} {why}; left out"
            flat.notes.append(text)
            comments.append(text)
            flat.params_left_out.add((index, key))
            continue
        kept.append((key, value))
    return FlatNode(decl, kept, timers, comments=comments)


def _period(text: str) -> str | None:
    """A timer condition's period when it is a number (``after timer period=2.0``)."""
    found = _PERIOD.search(text)
    if found is None:
        return None
    period = found.group(1).strip("'\"")
    try:
        return period if math.isfinite(float(period)) else None
    except ValueError:
        return None


def _leave_out(flat: Flat, index: int, text: str) -> None:
    flat.left_out.add(index)
    flat.notes.append(text)
    flat.comments.append(text)


def _where(decl: NodeDecl) -> str:
    return f" ({decl.location})" if decl.location.file else ""


def param_text(value: Any) -> str | None:
    """The XML attribute text launch_xml reads (as YAML) back into ``value``: the value
    itself, its YAML flow form, or a literal block for text of several lines. None if
    none reads back or the text holds a backslash (an escape to launch's substitution
    parser) or ``$(`` (a substitution)."""
    candidates: list[str] = []
    if isinstance(value, str):
        candidates.append(value)
    elif isinstance(value, float) and not math.isfinite(value):
        candidates.append(".nan" if math.isnan(value) else (".inf" if value > 0 else "-.inf"))
    for style in (None, "|"):
        try:
            text = yaml.safe_dump(value, default_flow_style=style is None, width=math.inf,
                                  allow_unicode=True, default_style=style)
        except yaml.YAMLError:
            continue
        candidates.append(text if style else text.strip().removesuffix("...").rstrip())
    for text in candidates:
        if "$(" not in text and "\\" not in text and _same(naming.yaml_value(text), value):
            return text
    return None


def _yaml_ok(value: Any) -> bool:
    """A value the YAML launch file can hold as it is (its strings are read for
    substitutions and escapes: none may hold ``$(`` or a backslash)."""
    if isinstance(value, list):
        return bool(value) and all(_yaml_ok(v) for v in value)
    if isinstance(value, str):
        return "$(" not in value and "\\" not in value
    return isinstance(value, bool | int | float)


def _same(a: Any, b: Any) -> bool:
    try:
        return json.dumps(a, sort_keys=True) == json.dumps(b, sort_keys=True)
    except (TypeError, ValueError):
        return False


def _namespace(decl: NodeDecl) -> str | None:
    ns = decl.namespace.rstrip("/")
    return ns or None


def _base(decl: NodeDecl) -> str | None:
    base = decl.name.rsplit("/", 1)[-1]
    return None if base == "?" else base


def _identity(decl: NodeDecl, kind: str) -> list[tuple[str, str]]:
    """``pkg``, ``exec`` (``plugin`` for a component), ``name`` when known and
    ``namespace``, in the order and with the keys of XML and YAML launch files."""
    found = [("pkg", decl.package), (kind, decl.executable)]
    base = _base(decl)
    if base is not None:
        found.append(("name", base))
    found.append(("namespace", _namespace(decl) or "/"))
    return found


_PY_KEYS = {"pkg": "package", "exec": "executable"}  # Python's names for the others


def _py_identity(decl: NodeDecl, kind: str) -> list[tuple[str, str]]:
    return [(_PY_KEYS.get(key, key), repr(value)) for key, value in _identity(decl, kind)]


def _words(decl: NodeDecl) -> list[str]:
    try:
        return shlex.split(decl.args)
    except ValueError:
        return decl.args.split()


def _header(flat: Flat) -> str:
    return f"flattened by haros-arch from {flat.source}"


# -- XML ------------------------------------------------------------------------------
def as_xml(flat: Flat) -> str:
    root = etree.Element("launch")
    root.append(etree.Comment(f" {_comment(_header(flat))} "))
    for text in flat.comments:
        root.append(etree.Comment(f" haros-arch: {_comment(text)} "))
    for node in flat.items:
        parent = root
        for period in node.timers:
            parent = etree.SubElement(parent, "timer", period=period)
        _xml_node(parent, node)
    return etree.tostring(root, pretty_print=True, encoding="unicode")


def _xml_node(parent: etree._Element, node: FlatNode) -> None:
    decl = node.decl
    for text in node.comments:
        parent.append(etree.Comment(f" haros-arch: {_comment(text)} "))
    if decl.composable:
        load = etree.SubElement(parent, "load_composable_node", target=decl.container or "")
        _xml_component(load, node)
        return
    tag = "node_container" if node.components else "node"
    attrs = dict(_identity(decl, "exec"))
    if decl.args:
        attrs["args"] = decl.args
    element = etree.SubElement(parent, tag, attrs)
    _xml_body(element, node)
    for component in node.components:
        for text in component.comments:
            element.append(etree.Comment(f" haros-arch: {_comment(text)} "))
        _xml_component(element, component)


def _xml_component(parent: etree._Element, node: FlatNode) -> None:
    decl = node.decl
    attrs = dict(_identity(decl, "plugin"))
    _xml_body(etree.SubElement(parent, "composable_node", attrs), node)


def _files(node: FlatNode) -> list[str]:
    return _kept_files(node.decl)


def _kept_files(decl: NodeDecl) -> list[str]:
    """Parameter files kept as paths: those of a node whose name is not known, which
    launch_ros hands to the node (the sections for its name apply when it runs); its
    values written after them are the same as theirs where they overlap."""
    if decl.composable:
        return []
    return [f for f in decl.params_files_given if "$(" not in f]


def _xml_body(element: etree._Element, node: FlatNode) -> None:
    for path in _files(node):
        etree.SubElement(element, "param", {"from": path})
    for key, value in node.params:
        etree.SubElement(element, "param", name=key, value=str(param_text(value)))
    for source, target in node.decl.remaps:
        etree.SubElement(element, "remap", {"from": source, "to": target})


def _comment(text: str) -> str:
    return text.replace("--", "- -")


# -- YAML -----------------------------------------------------------------------------
def as_yaml(flat: Flat) -> str:
    items: list[dict[str, Any]] = []
    for node in flat.items:
        item = _yaml_node(node)
        for period in reversed(node.timers):
            item = {"timer": {"period": period, "children": [item]}}
        items.append(item)
    lines = [f"# {_header(flat)}"]
    lines += [f"# haros-arch: {text}" for text in flat.comments]
    for node in flat.items:
        lines += [f"# haros-arch: {text}" for text in node.comments]
        lines += [f"# haros-arch: {text}" for c in node.components for text in c.comments]
    body = yaml.safe_dump({"launch": items}, sort_keys=False, allow_unicode=True,
                          width=1_000_000)
    return "\n".join(lines) + "\n" + body


def _yaml_node(node: FlatNode) -> dict[str, Any]:
    decl = node.decl
    if decl.composable:
        return {"load_composable_node": {"target": decl.container,
                                         "composable_node": [_yaml_component(node)]}}
    body: dict[str, Any] = dict(_identity(decl, "exec"))
    if decl.args:
        body["args"] = decl.args
    body.update(_yaml_body(node))
    if node.components:
        body["composable_node"] = [_yaml_component(c) for c in node.components]
        return {"node_container": body}
    return {"node": body}


def _yaml_component(node: FlatNode) -> dict[str, Any]:
    decl = node.decl
    body: dict[str, Any] = dict(_identity(decl, "plugin"))
    body.update(_yaml_body(node))
    return body


def _yaml_body(node: FlatNode) -> dict[str, Any]:
    body: dict[str, Any] = {}
    if node.params or _files(node):
        # launch_yaml gives the value as YAML typed it; a string stays a string
        body["param"] = [{"from": f} for f in _files(node)] + [
            {"name": k, "value": v} for k, v in node.params]
    if node.decl.remaps:
        body["remap"] = [{"from": a, "to": b} for a, b in node.decl.remaps]
    return body


# -- Python ---------------------------------------------------------------------------
def as_python(flat: Flat) -> str:
    lines = [f'"""{_header(flat)}."""', ""]
    lines += [f"# haros-arch: {text}" for text in flat.comments]
    lines += ["from launch import LaunchDescription",
              "from launch.actions import TimerAction",
              "from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, "
              "Node",
              "from launch_ros.descriptions import ComposableNode", "", "",
              "def generate_launch_description():",
              "    return LaunchDescription(["]
    pad = " " * 8
    for node in flat.items:
        for text in [*node.comments, *(t for c in node.components for t in c.comments)]:
            lines.append(f"{pad}# haros-arch: {text}")
        call = _py_node(node, pad)
        for period in reversed(node.timers):
            call = f"TimerAction(period={_py_number(period)}, actions=[{call}])"
        lines.append(f"{pad}{call},")
    lines += ["    ])", ""]
    return "\n".join(lines)


def _py_node(node: FlatNode, pad: str) -> str:
    """The call that starts ``node``, one keyword argument a line, indented from ``pad``."""
    decl = node.decl
    inner = pad + " " * 8
    if decl.composable:
        return _py_call("LoadComposableNodes", [
            ("target_container", repr(decl.container)),
            ("composable_node_descriptions",
             f"[\n{inner}{_py_component(node, inner)},\n{pad}    ]")], pad)
    kwargs = _py_identity(decl, "exec")
    if decl.args:
        kwargs.append(("arguments", repr(_words(decl))))
    kwargs += _py_body(node, pad)
    if node.components:
        parts = "".join(f"{inner}{_py_component(c, inner)},\n" for c in node.components)
        kwargs.append(("composable_node_descriptions", f"[\n{parts}{pad}    ]"))
        return _py_call("ComposableNodeContainer", kwargs, pad)
    return _py_call("Node", kwargs, pad)


def _py_component(node: FlatNode, pad: str) -> str:
    decl = node.decl
    kwargs = _py_identity(decl, "plugin")
    return _py_call("ComposableNode", kwargs + _py_body(node, pad), pad)


def _py_body(node: FlatNode, pad: str) -> list[tuple[str, str]]:
    out: list[tuple[str, str]] = []
    if node.params or _files(node):
        inner = pad + " " * 8
        entries = "".join(f"{inner}{k!r}: {v!r},\n" for k, v in node.params)
        files = "".join(f"{f!r}, " for f in _files(node))
        out.append(("parameters", f"[{files}{{\n{entries}{pad}    }}]"))
    if node.decl.remaps:
        out.append(("remappings", repr([tuple(r) for r in node.decl.remaps])))
    return out


def _py_plain(value: Any) -> bool:
    """A value launch_ros gives the node as the Python literal is: a boolean, number or
    string (launch_ros dumps a string as YAML and reads it back: it stays that string),
    or a non-empty list of one of those types."""
    def scalar(v: Any) -> bool:
        return isinstance(v, bool | int | str) or (isinstance(v, float) and math.isfinite(v))

    if isinstance(value, list):
        return bool(value) and all(scalar(v) for v in value) and len(
            {type(v) for v in value}) == 1
    return scalar(value)


def _py_number(text: str) -> str:
    try:
        return repr(float(text))
    except ValueError:
        return repr(text)


def _py_call(name: str, kwargs: list[tuple[str, str]], pad: str) -> str:
    lines = "".join(f"{pad}    {k}={v},\n" for k, v in kwargs)
    return f"{name}(\n{lines}{pad})"


# -- what must round-trip ---------------------------------------------------------------
def facts(model: LaunchModel, flat: Flat | None = None) -> list[str]:
    """Each node of ``model`` with its parameters, as one comparable line, sorted:
    name, package, executable, namespace, arguments, remaps, container, the kinds of
    conditions it runs under, its parameters with their typed values and the parameter
    file entries kept for the name the graph will give it (``ParamDecl.pattern``). Given the
    ``flat`` made from ``model``, what it says it leaves out is left out here too, and
    a node it starts at once has no event condition: the facts its file must give."""
    params: dict[int, dict[str, Any]] = {}
    sections: dict[int, list[list[Any]]] = {}  # entries for a node name, not yet given
    for param in model.params:
        if param.owner is None or param.key is None or (
                flat is not None and (param.owner, param.key) in flat.params_left_out):
            continue
        if param.pattern is None:
            params.setdefault(param.owner, {})[param.key] = param.value
        else:
            sections.setdefault(param.owner, []).append(
                [param.pattern, param.key, param.value])
    out = []
    for index, decl in enumerate(model.nodes):
        if flat is not None and index in flat.left_out:
            continue
        kept = params.get(index, {})
        conditions = [c.statement for c in decl.conditions
                      if flat is None or index not in flat.started_at_once
                      or c.statement != "event"]
        out.append(json.dumps({
            "name": decl.name, "package": decl.package, "executable": decl.executable,
            "namespace": decl.namespace.rstrip("/") or "/", "args": _words(decl),
            "remaps": [list(r) for r in decl.remaps], "composable": decl.composable,
            "container": decl.container, "conditions": conditions,
            "params": kept, "sections": sorted(sections.get(index, []), key=str)},
            sort_keys=True, default=str))
    return sorted(out)
