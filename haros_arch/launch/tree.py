"""Recording the launch tree (``model.launch_tree``) while a loader walks its files.

The ROS 1 loader and the ROS 2 runner call these helpers at the points where they open
a file, a group or a node; what they share (node items made from the declarations a
handler added, a condition's record) lives here once.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

from ..model.launch_tree import LaunchCondition, LaunchItem
from ..model.values import Value
from .model import LaunchModel

_ROS1_ARG = re.compile(r"\$\(\s*arg\s+([^\s)]+)\s*\)|\barg\(\s*['\"]([^'\"]+)['\"]\s*\)")
_ROS1_ENV = re.compile(r"\$\(\s*(?:opt)?env\s+([^\s)]+)")
MAX_SKIPPED = 100


def ros1_condition(text: str, statement: str, args: Mapping[str, Value | None],
                   holds: bool | None, environment: Mapping[str, str]) -> LaunchCondition:
    """The record of an ``if=``/``unless=``: the ``$(arg)``s it reads and their values,
    and the environment variables (``$NAME``; None when unset)."""
    values: dict[str, str | None] = {}
    for match in _ROS1_ARG.finditer(text):
        name = match.group(1) or match.group(2)
        value = args.get(name)
        values[name] = value.text if value is not None else None
    for match in _ROS1_ENV.finditer(text):
        values["$" + match.group(1)] = environment.get(match.group(1))
    return LaunchCondition(text, statement, values, holds)


def node_items(model: LaunchModel, nodes_before: int, params_before: int,
               condition: LaunchCondition | None) -> list[LaunchItem]:
    """One item per node declaration added since ``nodes_before``, with the names of
    the parameters given to it since ``params_before``."""
    added = range(nodes_before, len(model.nodes))
    items = []
    for index in added:
        decl = model.nodes[index]
        params = [p.name for p in model.params[params_before:] if p.pattern is None
                  and (p.owner == index or (p.owner is None and len(added) == 1))]
        items.append(LaunchItem(
            "node", decl.name, decl.location, namespace=decl.namespace,
            detail=f"{decl.package}/{decl.executable}", condition=condition,
            remaps=list(decl.remaps), params=params))
    return items


def param_names(model: LaunchModel, params_before: int) -> list[str]:
    return [p.name for p in model.params[params_before:] if p.pattern is None]
