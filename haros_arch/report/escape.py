"""Any name from the workspace written safely in every output: control characters (a
terminal escape sequence, NUL, DEL, ...) and lone surrogates (a Python string literal
``'\\udc80'``) become visible ``\\xNN`` / ``\\uNNNN`` escapes, which UTF-8, XML 1.0 and
terminals all accept; tabs and newlines stay."""

from __future__ import annotations

import re

from rich.markup import escape as rich_escape

_UNPRINTABLE = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\ud800-\udfff\ufffe\uffff]")


def _code(match: re.Match[str]) -> str:
    point = ord(match.group())
    return f"\\x{point:02x}" if point < 0x100 else f"\\u{point:04x}"


def printable(text: str) -> str:
    """``text`` with control characters and lone surrogates written as escapes."""
    return _UNPRINTABLE.sub(_code, text)


def escape(text: str) -> str:
    """For rich's console: printable, and its markup (``[bold]``) escaped."""
    return rich_escape(printable(text))
