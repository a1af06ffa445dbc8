"""C/C++ text with what is not code blanked, shared by the readers that scan whole files
with patterns (the CMake source choice, the plugin scans, the C++ extractor's spreads)."""

from __future__ import annotations

import functools
import re
from typing import AnyStr

# a comment, or a string or character literal (a comment mark may sit in one)
_PATTERN = r"\"(?:\\.|[^\"\\\n])*\"|'(?:\\.|[^'\\\n])*'|//[^\n]*|/\*.*?(?:\*/|\Z)"
_TEXT = re.compile(_PATTERN, re.DOTALL)
_BYTES = re.compile(_PATTERN.encode(), re.DOTALL)
_TEXT_INSIDE = re.compile(r"[^\r\n]")
_BYTES_INSIDE = re.compile(rb"[^\r\n]")


@functools.lru_cache(maxsize=256)  # a file's text is asked again by each reader
def code_only(text: AnyStr, literals: bool = False) -> AnyStr:
    """``text`` (``str`` or ``bytes``) with its comments blanked and, unless
    ``literals``, the insides of its string and character literals (their quotes kept),
    every character at its offset and every line break kept, so lines and offsets stay
    where they were. A comment's or a message's words name nothing the code uses:
    laser_filters' scan_to_cloud_filter_chain.cpp describes itself as ``@b
    ScanShadowsFilter`` in a comment and runs no filter; an export macro commented out
    exports nothing. ``literals`` keeps what a reader needs from strings (a behaviour
    tree node's registered name)."""
    if isinstance(text, bytes):
        pattern, inside, space, quotes = _BYTES, _BYTES_INSIDE, b" ", (b'"', b"'")
    else:
        pattern, inside, space, quotes = _TEXT, _TEXT_INSIDE, " ", ('"', "'")

    def blank(match: re.Match[AnyStr]) -> AnyStr:
        found = match.group(0)
        if found[:1] in quotes:
            if literals:
                return found
            return found[:1] + inside.sub(space, found[1:-1]) + found[-1:]
        return inside.sub(space, found)
    return pattern.sub(blank, text)
