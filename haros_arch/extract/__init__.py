"""Source extraction: the ROS primitive calls in each node's sources.

Entry point: ``extract_node(node, workspace)`` fills ``node.calls`` and
``node.rosname`` and returns the diagnostics; C++ goes through libclang.
"""

from __future__ import annotations

import os

from ..diagnostics import Diagnostic
from ..model.source import Node
from ..workspace import Workspace


def extract_node(node: Node, workspace: Workspace) -> list[Diagnostic]:
    sources = [os.path.join(workspace.root, s) if not os.path.isabs(s) else s
               for s in node.sources]
    if node.language == "cpp" and sources:
        from .cpp import extract_cpp  # libclang loads only when there is C++ to parse

        result = extract_cpp(sources, workspace)
        node.calls = result.calls
        node.rosname = result.rosname
        return result.diagnostics
    if node.language == "python" and sources:
        from .python import extract_python

        found = extract_python(sources, workspace, package=node.package)
        node.calls = found.calls
        node.rosname = found.rosname
        return found.diagnostics
    return []
