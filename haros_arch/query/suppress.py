"""Inline suppressions: ``// haros-arch: ignore <id>`` in source files and
``<!-- haros-arch: ignore <id> -->`` in launch files, on the finding's line or the line
above it. Several ids may be given, separated by commas or spaces; ``all`` ignores every
rule there.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterable

from ..model.location import Location

_MARK = re.compile(r"haros-arch:\s*ignore\s+([A-Za-z0-9_\-, ]+)")
MAX_BYTES = 4 * 1024 * 1024


class Suppressions:
    """Reads each file at most once; files are found under the workspace roots."""

    def __init__(self, roots: Iterable[str]) -> None:
        self.roots = [str(r) for r in roots]
        self.lines: dict[str, list[str]] = {}

    def _file(self, relative: str) -> list[str]:
        if relative in self.lines:
            return self.lines[relative]
        text: list[str] = []
        candidates = [relative] if os.path.isabs(relative) else [
            os.path.join(root, relative) for root in self.roots]
        for path in candidates:
            try:
                if os.path.isfile(path) and os.path.getsize(path) <= MAX_BYTES:
                    with open(path, encoding="utf-8", errors="replace") as handle:
                        text = handle.read().splitlines()
                    break
            except OSError:
                continue
        self.lines[relative] = text
        return text

    def ids_at(self, where: Location) -> set[str]:
        if not where.file or where.line <= 0:
            return set()
        lines = self._file(where.file)
        ids: set[str] = set()
        for number in (where.line, where.line - 1):
            if 0 < number <= len(lines):
                for found in _MARK.finditer(lines[number - 1]):
                    ids.update(x for x in re.split(r"[,\s]+", found.group(1)) if x)
        return ids

    def applies(self, rule: str, places: Iterable[Location]) -> bool:
        return any(rule in ids or "all" in ids for ids in map(self.ids_at, places))
