"""Places in C++ sources whose lines moved: a kept run's text renumbered.

An edit of a C++ source that changes no call (a comment, a log line, a body's logic)
moves the lines of every call below it: the nodes a run extracts again are those of the
kept run but for the line numbers in that file, and so are the graph and the findings
built from them. ``Files`` names the changed files; its ``line_maps`` tells whether two
texts (the JSON of the nodes and diagnostics of two runs) are the same but for the lines
of places in those files, and gives, per file, the map from each old line to its new
one; ``renumbered`` writes another text of the old run (its model, its findings) with
those lines.

A place is a location (``"file": "<path>", "line": <n>``, as the model's JSON writes a
``Location``) or a path and line within a string (``<path>:<n>``, as messages and
conditions quote them), the path absolute or relative to the workspace root. A map is
used only when it keeps the order of the places it moves: it is one to one and
increasing, and a line quoted in a string keeps its number of digits (a list sorted by
such strings keeps its order); every place of a changed file in a renumbered text must
be one the map knows. Anything else, a place at a byte offset or written another way,
differs between the two texts and no map is given: the run is made again.
"""

from __future__ import annotations

import functools
import itertools
import json
import os
import re
from collections.abc import Iterable, Iterator

# what may come before a path: the path is not the end of a longer one
_BOUNDARY = frozenset(' \t\n"(<[{,:;=`\'')
Place = tuple[str, int, bool]  # file (absolute), line, whether quoted in a string
# after a location's file, before its line: in a compact text (``json.dumps``), and in an
# indented one (``extract``'s document: ``json.dumps(..., indent=2)``)
_LINE = re.compile(r'(?:(", "line": )|:)(\d+)')
_LINE_INDENTED = re.compile(r'(?:(",\n *"line": )|:)(\d+)')
# and in the report page's (``viz.html.json_for_script``: no blanks, escapes for HTML)
_LINE_PAGE = re.compile(r'(?:(","line":)|:)(\d+)')
Maps = dict[str, dict[int, int]]  # per file (absolute): old line -> new line


class Files:
    """The changed files (absolute paths), as a model's JSON text writes them: absolute,
    or relative to the workspace ``root`` when inside it (``Workspace.relpath``)."""

    def __init__(self, paths: Iterable[str], root: str, indented: bool = False,
                 page: bool = False) -> None:
        """``indented``: the texts are ``json.dumps(..., indent=N, ensure_ascii=False)``'s
        (``extract``'s document), not compact with escapes for characters beyond ASCII;
        ``page``: the report page's data (``viz.html.json_for_script``)."""
        top = os.path.abspath(root).rstrip(os.sep) + os.sep
        self.line = _LINE_PAGE if page else _LINE_INDENTED if indented else _LINE
        spell = _page_string if page else functools.partial(
            json.dumps, ensure_ascii=not indented)
        self.spelt: dict[str, str] = {}
        for path in paths:
            full = os.path.abspath(path)
            spellings = [full] + ([full[len(top):]] if full.startswith(top) else [])
            for spelling in spellings:
                self.spelt[spell(spelling)[1:-1]] = full
        # each spelling's shortest tail among them (a relative path is the end of the
        # absolute one): the text is searched for those, a plain search, far faster
        # than a regex of alternatives over a model's 50 MB
        self.tails = sorted({min((s for s in self.spelt if spelling.endswith(s)), key=len)
                             for spelling in self.spelt})
        # the spellings that end with each tail, the longest first
        self.ending = {tail: sorted((s for s in self.spelt if s.endswith(tail)), key=len,
                                    reverse=True) for tail in self.tails}

    def places(self, text: str) -> tuple[list[str], list[Place], bool]:
        """The places in the changed files, the text between them (one piece more than
        places), and whether a changed file's name and a number appear otherwise (the
        end of a longer path, or a form not read here: left as they are)."""
        pieces, found, other = self._places(text)
        return pieces, [(self.spelt[spelling], line, quoted)
                        for spelling, line, quoted in found], other

    def locations(self, text: str) -> list[tuple[str, int]]:
        """The file (as the text names it, a JSON string's content) and line of each
        location (not a place quoted in a string) in the changed files."""
        return [(spelling, line) for spelling, line, quoted in self._places(text)[1]
                if not quoted]

    def _places(self, text: str) -> tuple[list[str], list[tuple[str, int, bool]], bool]:
        """``places``, each with the spelling of its file."""
        pieces: list[str] = []
        found: list[tuple[str, int, bool]] = []
        other = False
        last = 0
        for start, end, spelling, located, line in self._matches(text):
            before = text[start - 1] if start else ""
            if before not in _BOUNDARY or (located and before != '"'):
                other = True
                continue
            at = end + (len(located) if located else 1)
            pieces.append(text[last:at])
            found.append((spelling, int(line), not located))
            last = at + len(line)
        pieces.append(text[last:])
        return pieces, found, other

    def _matches(self, text: str) -> Iterator[tuple[int, int, str, str, str]]:
        """Each spelling of a changed file followed by a line (``", "line": n`` or
        ``:n``), left to right, not overlapping (at one place the longest spelling):
        where it begins and ends, the spelling, what is between it and the line in a
        location ("" in a string), the line's digits."""
        hits: list[tuple[int, int, str, str, str]] = []
        for tail in self.tails:
            at = text.find(tail)
            while at >= 0:
                end = at + len(tail)
                for spelling in self.ending[tail]:
                    begin = end - len(spelling)
                    if begin < 0 or not text.startswith(spelling, begin):
                        continue
                    after = self.line.match(text, end)
                    if after is not None:
                        hits.append((begin, after.end(), spelling, after.group(1) or "",
                                     after.group(2)))
                        break
                at = text.find(tail, at + 1)
        hits.sort(key=lambda hit: (hit[0], -len(hit[2])))
        last = 0
        for begin, stop, spelling, located, line in hits:
            if begin >= last:
                yield begin, begin + len(spelling), spelling, located, line
                last = stop

    def line_maps(self, old: str, new: str) -> Maps | None:
        """Per changed file, its old lines to their new ones, when ``new`` is ``old`` but
        for the lines of places in those files and the maps keep their order (above);
        else None."""
        old_pieces, old_places, _ = self.places(old)  # the others are in the pieces
        new_pieces, new_places, _ = self.places(new)
        if old_pieces != new_pieces:
            return None
        maps: Maps = {}
        backwards: Maps = {}
        for (path, line, quoted), (other, moved, _) in zip(old_places, new_places,
                                                            strict=True):
            if path != other or (quoted and len(str(line)) != len(str(moved))):
                return None
            if maps.setdefault(path, {}).setdefault(line, moved) != moved:
                return None
            if backwards.setdefault(path, {}).setdefault(moved, line) != line:
                return None
        for lines in maps.values():
            ordered = [lines[line] for line in sorted(lines)]
            if any(a >= b for a, b in itertools.pairwise(ordered)):
                return None
        return maps

    def renumbered(self, text: str, maps: Maps) -> str | None:
        """``text`` with the lines of its places in the changed files moved by ``maps``;
        None when a place is one the maps do not know, a quoted line would change its
        number of digits, or a changed file's name and a number appear in a form not read
        as a place (it might be one, which would stay as it was)."""
        pieces, found, other = self.places(text)
        if other:
            return None
        out = [pieces[0]]
        for (path, line, quoted), piece in zip(found, pieces[1:], strict=True):
            moved = maps.get(path, {}).get(line)
            if moved is None or (quoted and len(str(moved)) != len(str(line))):
                return None
            out.append(str(moved))
            out.append(piece)
        return "".join(out)


def _page_string(text: str) -> str:
    """A string as the report page's data writes it."""
    from .viz.html import json_for_script

    return json_for_script(text)
