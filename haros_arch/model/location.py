"""Where something was found: package, workspace-relative file, line and column."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Location:
    """A place in the analysed workspace.

    ``file`` is relative to the workspace root when the file lies inside it, and
    absolute otherwise. ``line`` and ``column`` are 1-based; 0 means unknown.
    """

    package: str | None = None
    file: str | None = None
    line: int = 0
    column: int = 0

    def __str__(self) -> str:
        if not self.file:
            return self.package or "<unknown>"
        text = self.file
        if self.line:
            text += f":{self.line}"
            if self.column:
                text += f":{self.column}"
        return text


NOWHERE = Location()


# how the path of a file of an installed package upstream begins, as its model names it
# (``models.launch_files.upstream``: ``github:owner/name@commit/path``)
UPSTREAM_SCHEMES = ("github:", "model:")


def is_upstream(path: str) -> bool:
    """Whether ``path`` names a file of an installed package upstream, as its model keeps
    it (a launch or parameter file read from the model), not one of the workspace."""
    return path.startswith(UPSTREAM_SCHEMES)
