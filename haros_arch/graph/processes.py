"""Several ROS 2 nodes in one process: one node instance each.

An rclpy executable that creates two nodes (two ``Node`` subclasses added to one
executor, ``create_node`` called twice) has them in ``Node.rosnames``, and each of its
calls names the node it is made on (``PrimitiveCall.node_name``). A launch ``Node`` that
starts it gives one node instance per ROS node, named as ROS 2 names them: without
``name=`` each keeps the name its code gives it, in the launch namespace; with
``name=`` (``__node:=``) every node of the process takes that name, as rcl renames them
all. Namespace, remaps and arguments apply to all of them. Parameters the launch file
gives the unnamed node (``/ns/?``) are given to each, as launch_ros passes them to the
whole process.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from dataclasses import replace

from ..launch.model import LaunchModel, NodeDecl, ParamDecl
from ..model.source import Node
from ..model.values import UNKNOWN_MARK


def node_key(decl: NodeDecl) -> str:
    return f"{decl.package}/{decl.executable}"


def process_nodes(decls: Sequence[NodeDecl], nodes: Mapping[str, Node]
                  ) -> Iterator[tuple[NodeDecl, str | None]]:
    """Each declaration, or one per ROS node of its process, with the name the code
    gives that node (None: the executable's only node)."""
    for decl in decls:
        owns = _own_names(decl, nodes)
        if not owns:
            yield decl, None
            continue
        for own in owns:
            name = _renamed(decl, own)
            yield (decl if name == decl.name else replace(decl, name=name)), own


def process_params(launch: LaunchModel, nodes: Mapping[str, Node]) -> list[ParamDecl]:
    """The launch parameters, those of an unnamed several-node process given to each of
    its nodes."""
    renamed: dict[str, list[str]] = {}
    kept: set[str] = set()
    for decl in launch.nodes:
        owns = _own_names(decl, nodes)
        names = [_renamed(decl, own) for own in owns]
        if owns and names[0] != decl.name:
            renamed.setdefault(decl.name, []).extend(names)
        else:
            kept.add(decl.name)
    if not renamed:
        return list(launch.params)
    params: list[ParamDecl] = []
    for param in launch.params:
        targets = renamed.get(param.node or "")
        if targets is None or param.node in kept:
            params.append(param)
        if targets is None or param.node is None:
            continue
        rest = param.name[len(param.node):]
        params.extend(replace(param, name=target + rest, node=target)
                      for target in dict.fromkeys(targets))
    return params


def _own_names(decl: NodeDecl, nodes: Mapping[str, Node]) -> list[str]:
    node = nodes.get(node_key(decl))
    if node is None or decl.ros_version != 2 or len(node.rosnames) < 2:
        return []
    return list(node.rosnames)


def _renamed(decl: NodeDecl, own: str) -> str:
    """A node of the process: the launch name when one is given, else its own name."""
    if decl.name.rsplit("/", 1)[-1] != UNKNOWN_MARK:
        return decl.name
    return decl.namespace.rstrip("/") + "/" + own
