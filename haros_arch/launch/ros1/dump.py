"""What ``haros-arch launch`` prints: ``roslaunch --nodes`` and ``--dump-params`` in one.

``parameters`` holds the leaf names and values a ROS master would hold right after the
launch (mappings unrolled; values that cannot be known are ``None``).
"""

from __future__ import annotations

from typing import Any

from ...model.serialise import to_data
from ..model import LaunchModel
from .params import Binary


def leaf_parameters(model: LaunchModel) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for param in model.params:
        _leaves(param.name, param.value, out)
    return out


def _leaves(name: str, value: Any, out: dict[str, Any]) -> None:
    if isinstance(value, dict):
        for key, item in value.items():
            _leaves(f"{name.rstrip('/')}/{key}", item, out)
        return
    out.pop(name, None)  # a later value of the same name wins, in launch order
    # plain text, but a binary value keeps its kind (a str holding base64)
    out[name] = str(value) if isinstance(value, str) and not isinstance(value, Binary) else value


def as_data(model: LaunchModel) -> dict[str, Any]:
    nodes = [{
        "name": n.name, "package": n.package, "executable": n.executable,
        "namespace": n.namespace, "args": n.args, "remaps": [list(r) for r in n.remaps],
        "machine": n.machine, "respawn": n.respawn, "required": n.required,
        "test": n.is_test, "ros_version": n.ros_version, "composable": n.composable,
        "container": n.container, "conditions": to_data(list(n.conditions)),
        "location": to_data(n.location)} for n in model.nodes]
    return {"nodes": nodes, "parameters": leaf_parameters(model),
            "includes": model.files[1:], "cleared": model.clear_params,
            "deleted": model.deleted_params,
            "diagnostics": to_data(model.diagnostics), "tree": to_data(model.tree)}


def as_text(model: LaunchModel) -> str:
    lines = ["nodes:"]
    for node in model.nodes:
        cond = "".join(f"  [{c}]" for c in node.conditions)
        loaded = f"  in {node.container}" if node.composable and node.container else ""
        lines.append(f"  {node.name}  ({node.package}/{node.executable}){loaded}{cond}")
        if node.args:
            lines.append(f"      args: {node.args}")
        for source, target in node.remaps:
            lines.append(f"      remap: {source} -> {target}")
    lines.append("parameters:")
    for name, value in sorted(leaf_parameters(model).items()):
        lines.append(f"  {name}: {'?' if value is None else repr(value)}")
    if len(model.files) > 1:
        lines.append("includes:")
        lines.extend(f"  {path}" for path in model.files[1:])
    return "\n".join(lines)
