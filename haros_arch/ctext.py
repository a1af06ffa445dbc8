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


# an integer literal as C++ writes it: hexadecimal, binary, octal (a leading 0) or
# decimal, with digit separators (``1'000``) and any suffix (``u``, ``UL``, ``ll``, ``z``)
_INTEGER = re.compile(
    r"([-+]?)(0[xX][0-9a-fA-F][0-9a-fA-F']*|0[bB][01][01']*|\d[\d']*)[uUlLzZ]*")


def integer_literal(text: str) -> int | None:
    """The value of the C++ integer literal ``text``, signed or not; None when ``text``
    is none (``09``, whose leading 0 makes it octal, is none either: clang refuses it).
    Python's ``int(text, 0)`` refuses the octal ``03`` a C++ source writes for 3."""
    match = _INTEGER.fullmatch(text)
    if match is None:
        return None
    digits = match.group(2).replace("'", "")
    prefix = digits[:2].lower()
    base = 16 if prefix == "0x" else 2 if prefix == "0b" else 8 if (
        len(digits) > 1 and digits[0] == "0") else 10
    try:
        value = int(digits[2:] if base in (16, 2) else digits, base)
    except ValueError:  # ``09``
        return None
    return -value if match.group(1) == "-" else value


# a function-like macro's ``#define``: the name (``{name}`` filled in), the parameters,
# the body with its continued lines (a backslash ending a line, blanks after it allowed)
_FUNCTION_MACRO = (r"^[ \t]*#[ \t]*define[ \t]+({name})\(([^)]*)\)"
                   r"((?:[^\n]*\\[ \t]*\r?\n)*[^\n]*)")
_CONTINUED = re.compile(r"\\[ \t]*(\r?\n)")
_CONTINUED_BYTES = re.compile(_CONTINUED.pattern.encode())


def function_macros(text: AnyStr, name: AnyStr) -> list[tuple[int, list[AnyStr], AnyStr]]:
    """Each ``#define name(parameters) body`` of ``text`` (``str`` or ``bytes``), in
    order: the offset of its name, its parameters, and its body with its continued
    lines joined (each backslash that continues a line dropped, the line break kept, so
    the body has the lines it has in the file). Callers choose which definition counts:
    the first, the only one, or the one the parse says an invocation expands."""
    if isinstance(text, bytes):
        assert isinstance(name, bytes)
        pattern = re.compile(_FUNCTION_MACRO.encode().replace(b"{name}", re.escape(name)),
                             re.MULTILINE)
        continued, comma = _CONTINUED_BYTES, b","
    else:
        assert isinstance(name, str)
        pattern = re.compile(_FUNCTION_MACRO.replace("{name}", re.escape(name)),
                             re.MULTILINE)
        continued, comma = _CONTINUED, ","
    found = []
    for match in pattern.finditer(text):
        parameters = [p.strip() for p in match.group(2).split(comma) if p.strip()]
        found.append((match.start(1), parameters, continued.sub(_line_break, match.group(3))))
    return found


def _line_break(match: re.Match[AnyStr]) -> AnyStr:
    return match.group(1)


def closing(text: bytes, at: int, span: int = 2000, backwards: bool = False,
            literals: bool = False) -> int | None:
    """The offset of the ``)`` that closes the ``(`` at ``at``, looked for within ``span``
    bytes; None when it does not close there. ``backwards``: of the ``(`` that the ``)``
    at ``at`` closes. ``literals`` (forwards only): string and character literals and
    comments are read over, so a ``)`` in ``ROS_INFO("a) b")`` or after ``//`` closes
    nothing (a ``'`` after a digit is a digit separator, ``1'000``); an unclosed ``/*``
    gives None."""
    if backwards and literals:
        raise ValueError("literals are read forwards only")
    opens, closes = (0x29, 0x28) if backwards else (0x28, 0x29)
    depth = 0
    step = -1 if backwards else 1
    end = max(-1, at - span) if backwards else min(len(text), at + span)
    index = min(at, len(text) - 1) if backwards else at  # past the end: nothing there
    while index > end if backwards else index < end:
        char = text[index]
        if literals and char in (0x22, 0x27):  # a string or a character literal
            if char == 0x27 and index > 0 and text[index - 1:index].isdigit():
                index += 1
                continue
            index += 1
            while index < end and text[index] != char:
                index += 2 if text[index] == 0x5C else 1  # a backslash escapes the next byte
            index += 1
            continue
        if literals and text.startswith(b"//", index):
            newline = text.find(b"\n", index, end)
            index = end if newline < 0 else newline
            continue
        if literals and text.startswith(b"/*", index):
            close = text.find(b"*/", index + 2, end)
            if close < 0:
                return None
            index = close + 2
            continue
        if char == opens:
            depth += 1
        elif char == closes:
            depth -= 1
            if depth == 0:
                return index
        index += step
    return None
