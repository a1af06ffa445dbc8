"""Python launch files, statically (placeholder)."""

from __future__ import annotations

from ...diagnostics import Diagnostic
from ...workspace import Workspace
from . import entities as e


def parse_python(text: str, path: str,
                 workspace: Workspace) -> tuple[list[e.Action] | None, list[Diagnostic]]:
    return [], []
