"""The lines of source around every location of the model, to embed in the report.

Only files inside the workspace folders are read (a saved model could name any path), or
in a ROS package that a link inside one leads to (linked checkouts), each through
``files.read_text`` with a size bound, and the total embedded text is bounded too.
"""

from __future__ import annotations

import os
from collections.abc import Iterator, Sequence
from typing import Any

from ..files import read_text
from ..model.location import Location

CONTEXT_LINES = 4          # lines shown above and below a location
MAX_LINE_CHARS = 300       # longer lines are cut (minified or generated code)
MAX_FILE_BYTES = 2 * 1024 * 1024
MAX_TOTAL_CHARS = 4 * 1024 * 1024


def locations(data: Any) -> Iterator[tuple[str, int]]:
    """Every ``{"file", "line"}`` location anywhere in JSON data, as (file, line)."""
    stack = [data]
    while stack:
        item = stack.pop()
        if isinstance(item, dict):
            file, line = item.get("file"), item.get("line")
            if isinstance(file, str) and isinstance(line, int) and line > 0 and file:
                yield file, line
            stack.extend(v for v in item.values() if isinstance(v, dict | list))
        elif isinstance(item, list):
            stack.extend(v for v in item if isinstance(v, dict | list))


def inside(root: str, file: str) -> str | None:
    """The real path of ``file`` (relative to ``root``) when it lies inside ``root``, or
    in a ROS package that a link inside ``root`` leads to (a workspace whose ``src``
    links to checkouts elsewhere); never a path that climbs out with ``..``."""
    if os.path.isabs(file):
        return None
    base = os.path.realpath(root)
    path = os.path.realpath(os.path.join(base, file))
    if not os.path.isfile(path):
        return None
    if path != base and path.startswith(base + os.sep):
        return path
    lexical = os.path.normpath(os.path.join(root, file))
    if not lexical.startswith(os.path.normpath(root) + os.sep):
        return None
    return path if _linked_package(lexical, os.path.normpath(root), path) else None


def _linked_package(lexical: str, root: str, real: str) -> bool:
    """A link inside the workspace, on the way to the file, leads to a folder that holds
    the file's ROS package (a package.xml above the file, at or below the link's target)."""
    folder = os.path.dirname(lexical)
    while folder.startswith(root + os.sep):
        if os.path.islink(folder):
            target = os.path.realpath(folder)
            above = os.path.dirname(real)
            while above == target or above.startswith(target + os.sep):
                if os.path.isfile(os.path.join(above, "package.xml")):
                    return True
                above = os.path.dirname(above)
            return False
        folder = os.path.dirname(folder)
    return False


def in_folders(folders: Sequence[str], file: str) -> str | None:
    """``inside`` the first of ``folders`` (where relative paths start) for a relative
    ``file``; an absolute one (the model's path of a file beyond the first workspace
    folder) inside the folder of the others that holds it."""
    if not folders:
        return None
    if not os.path.isabs(file):
        return inside(folders[0], file)
    lexical = os.path.normpath(file)
    for folder in folders[1:]:
        top = os.path.normpath(folder)
        if lexical.startswith(top + os.sep):
            return inside(top, lexical[len(top) + 1:])
    return None


def folder_labels(workspace_root: str | Sequence[str]) -> list[list[str]]:
    """``[folder, label]`` for each workspace folder after the first (whose files the
    model names by absolute path): the report shows such a file as the label, the
    folder's name (with its parent's where two share it), and its path below it."""
    folders = [] if isinstance(workspace_root, str) else [
        os.path.normpath(os.path.abspath(f)) for f in workspace_root[1:]]
    names = [os.path.basename(f) for f in folders]
    return [[folder, name if names.count(name) == 1 else os.path.join(
        os.path.basename(os.path.dirname(folder)), name)]
        for folder, name in zip(folders, names, strict=True)]


def collect_snippets(data: Any, workspace_root: str | Sequence[str]
                     ) -> dict[str, dict[str, str]]:
    """``{file: {"line number": text}}`` for the lines around each location in ``data``;
    ``workspace_root``: the workspace folder, or the project's folders in order."""
    folders = [workspace_root] if isinstance(workspace_root, str) else list(workspace_root)
    wanted: dict[str, set[int]] = {}
    for file, line in locations(data):
        wanted.setdefault(file, set()).add(line)
    snippets: dict[str, dict[str, str]] = {}
    budget = MAX_TOTAL_CHARS
    for file in sorted(wanted):
        shown, budget = file_snippets(folders, file, wanted[file], budget)
        if shown:
            snippets[file] = shown
        if budget < 0:
            break
    return snippets


def file_snippets(folders: Sequence[str], file: str, lines: set[int], budget: int
                  ) -> tuple[dict[str, str], int]:
    """``{"line number": text}`` of ``file`` (as the model names it) around ``lines``, and
    what is left of ``budget`` (characters): below 0 when it ran out, the lines after
    then left out."""
    path = in_folders(folders, file)
    if path is None:
        return {}, budget
    text, _problems = read_text(path, Location(file=file), MAX_FILE_BYTES)
    if text is None:
        return {}, budget
    numbered = text.splitlines()
    shown: dict[str, str] = {}
    for number in sorted(_window(lines, len(numbered))):
        text_line = numbered[number - 1][:MAX_LINE_CHARS].expandtabs(4)
        budget -= shown_cost(text_line)
        if budget < 0:
            break
        shown[str(number)] = text_line
    return shown, budget


def shown_cost(text_line: str) -> int:
    """What a line shown takes of the page's budget (``MAX_TOTAL_CHARS``)."""
    return len(text_line) + 8


def _window(lines: set[int], count: int) -> set[int]:
    numbers: set[int] = set()
    for line in lines:
        numbers.update(range(max(1, line - CONTEXT_LINES), min(count, line + CONTEXT_LINES) + 1))
    return numbers
