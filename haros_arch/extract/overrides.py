"""Whether a ROS 2 node may declare the parameter overrides it is given.

rclpy's ``Node(..., automatically_declare_parameters_from_overrides=True)`` and rclcpp's
``NodeOptions().automatically_declare_parameters_from_overrides(true)`` declare every
parameter the configuration sets on the node (its YAML files, the launch file's values);
without it (the default of both) a node has only the parameters it declares, and a read
of what it has under a prefix (rclpy's ``get_parameters_by_prefix``, rclcpp's
``get_parameters(prefix, map)`` and ``list_parameters``) gives only those: an override
the node never declares is refused by name and read by nothing.

The extractor marks such reads ``PrimitiveCall.declared_only``; ``clear_where_declared``
takes the mark off again wherever the node's code may turn the option on: the option
written with anything but a literal false in the node's own sources or in the files of
its package in that language (a header or module of the package may build the node),
and for a plugin or nodelet class, whose node (and its options) is its host's.
"""

from __future__ import annotations

import os
import re
from dataclasses import replace

from ..ctext import code_only
from ..model.source import Node
from ..workspace import Workspace

OPTION = "automatically_declare_parameters_from_overrides"
# the option and what is written after it: ``(true)`` in C++, ``=True`` in Python
_WRITTEN = re.compile(OPTION + r"\s*(?:\(\s*(\w*)\s*\)|=\s*(\w+))?")
_LITERAL_FALSE = ("false", "False")
_EXTENSIONS = {
    "cpp": (".cpp", ".cc", ".cxx", ".c++", ".hpp", ".h", ".hh", ".hxx", ".ipp", ".tpp"),
    "python": (".py",),
}
# files of a package read at most (a package of generated code)
_MAX_FILES = 400
_MAX_BYTES = 2_000_000
_SKIPPED = {".git", "build", "install", "log", "__pycache__", "node_modules"}


def may_declare(text: str) -> bool:
    """Whether ``text`` turns the option on, or may: written anywhere with a value that
    is not a literal false (a variable, ``true``, or no value seen)."""
    for found in _WRITTEN.finditer(text):
        value = found.group(1) if found.group(1) is not None else found.group(2)
        if value not in _LITERAL_FALSE:
            return True
    return False


def _files(node: Node, workspace: Workspace) -> list[str]:
    paths = [s if os.path.isabs(s) else os.path.join(workspace.root, s) for s in node.sources]
    root = workspace.find(node.package) if node.package in workspace.packages else None
    extensions = _EXTENSIONS.get(node.language, ())
    if root and os.path.isdir(root):
        for folder, dirs, names in os.walk(root):
            dirs[:] = sorted(d for d in dirs if d not in _SKIPPED and not d.startswith("."))
            paths.extend(os.path.join(folder, name) for name in sorted(names)
                         if name.endswith(extensions))
            if len(paths) > _MAX_FILES:
                break
    return list(dict.fromkeys(paths))


def _declares(node: Node, workspace: Workspace) -> bool:
    """Whether the node may declare its overrides (``True`` when it cannot be told)."""
    if node.kind in ("plugin", "nodelet"):
        return True
    files = _files(node, workspace)
    if len(files) > _MAX_FILES:
        return True
    for path in files:
        try:
            with open(path, encoding="utf-8", errors="replace") as handle:
                text = handle.read(_MAX_BYTES)
        except OSError:
            return True  # a file not read may set it
        if OPTION in text and may_declare(code_only(text) if node.language == "cpp" else text):
            return True
    return False


def clear_where_declared(node: Node, workspace: Workspace) -> None:
    """Take ``declared_only`` off the node's reads where it may declare its overrides."""
    if not any(call.declared_only for call in node.calls):
        return
    if _declares(node, workspace):
        node.calls = [replace(call, declared_only=False) if call.declared_only else call
                      for call in node.calls]
