"""ROS 2 actions on the launch tree: a condition's arguments, an action named as written."""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping

from ...model.launch_tree import LaunchCondition, LaunchItem
from ...model.values import Value
from . import entities as e

MAX_PARTS = 200


def variables(text: e.Text | None) -> list[str]:
    """The launch configurations a text reads (``LaunchConfiguration``, ``$(var)``),
    inside other substitutions too, and its environment variables as ``$NAME``;
    bounded."""
    found: list[str] = []
    stack: list[object] = list(text or ())
    seen = 0
    while stack and seen < MAX_PARTS:
        seen += 1
        part = stack.pop(0)
        if isinstance(part, e.Var):
            name = written(part.name)
            if name not in found:
                found.append(name)
        elif isinstance(part, e.Env):
            name = "$" + written(part.name)
            if name not in found:
                found.append(name)
        elif isinstance(part, tuple):
            stack.extend(part)
        elif isinstance(part, e.Subst) and not isinstance(part, e.FileRef):
            stack.extend(getattr(part, f.name) for f in dataclasses.fields(part))
    return found


def written(text: e.Text | None) -> str:
    """A text as the user wrote it, near enough: ``$(var x)`` for a configuration."""
    if text is None:
        return ""
    out = []
    for part in text[:MAX_PARTS]:
        if isinstance(part, str):
            out.append(part)
        elif isinstance(part, e.Var):
            out.append(f"$(var {written(part.name)})")
        else:
            out.append(f"$({type(part).__name__})")
    return "".join(out)


def condition(cond: e.Cond, configs: Mapping[str, Value | None], holds: bool | None,
              environment: Mapping[str, str]) -> LaunchCondition:
    values: dict[str, str | None] = {}
    for name in variables((*cond.expression, *(cond.equals or ()))):
        if name.startswith("$"):
            values[name] = environment.get(name[1:])
            continue
        value = configs.get(name)
        values[name] = value.text if value is not None else None
    return LaunchCondition(cond.source or written(cond.expression),
                           "unless" if cond.negate else "if", values, holds)


def skipped(action: e.Action, cond: LaunchCondition) -> LaunchItem | None:
    """What a node, include or group left out by a false condition would have started."""
    where = action.location
    if isinstance(action, e.NodeAction):
        return LaunchItem("node", written(action.name) or "?", where, condition=cond,
                          detail=f"{written(action.package)}/{written(action.executable)}",
                          skipped=True)
    if isinstance(action, e.Include):
        return LaunchItem("include", written(action.path), where, condition=cond,
                          skipped=True)
    if isinstance(action, e.Group):
        item = LaunchItem("group", "", where, condition=cond, skipped=True)
        for inner in action.actions:
            if inner.condition is None and len(item.children) < MAX_PARTS:
                made = skipped(inner, cond)
                if made is not None:
                    made.condition = None
                    item.add(made)
        return item
    return None
