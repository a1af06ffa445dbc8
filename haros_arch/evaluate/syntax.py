"""``ast.parse`` for code read from the workspace: the compiler's warnings about it
(``SyntaxWarning: invalid decimal literal``, invalid escape sequences) are not ours to
print, so they are not printed.

Code written for Python 3.12 (Ubuntu 24.04, ROS 2 Jazzy and later) may use the
f-strings of PEP 701, which an older interpreter's parser refuses: a replacement field
of a single-quoted f-string that runs over several lines (``f'... {\\n value}'``), or a
string inside a field quoted as the f-string itself is (``f"{d["key"]}"``). When the
text does not parse and holds such an f-string, each one is written triple-quoted
(``f'''...'''``: its fields may then span lines and hold strings in either quote, as
3.6 to 3.11 allow) and the text parsed again; the columns of the tree are put back on
the file's own lines. A string in a field whose escapes (also new in 3.12 there) stand
for characters a quoted string may hold as they are (nova's ``f"{'\\033[1;32m'}..."``, a
terminal colour) is written with those characters and padded with blanks to its own
width, so its value and every column stay. Any other backslash in a field (an escape of
a line break, a quote or a backslash: ``{'\\n'.join(...)}``), or a comment there, is not
rewritten: the file's syntax error stands.

Python 3.12 also brings type parameter lists (PEP 695): ``class Task[T, U](Base):``,
``def first[T](items: list[T]) -> T:`` and the ``type Name[T] = ...`` statement
(duty's task_planning). Their parameters mean nothing to a ROS call: the list is
blanked, each character a space (a line break in it ends a backslash continuation), so
every other column stays where it is; ``type Name = value`` is read as the assignment
``Name = value``, the name moved to where ``type`` was."""

from __future__ import annotations

import ast
import io
import sys
import tokenize
import warnings
from typing import Any

# the string prefixes (any case) a quote may follow
_PREFIXES = frozenset({"r", "u", "f", "b", "br", "rb", "fr", "rf"})
_QUOTES = "'\""


def parse(text: str, filename: str = "<unknown>", mode: str = "exec") -> Any:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            return ast.parse(text, filename=filename, mode=mode)
        except SyntaxError:
            if sys.version_info >= (3, 12):
                raise
            blanked = _type_parameters_blanked(text)
            if blanked is not None:
                try:
                    return ast.parse(blanked, filename=filename, mode=mode)
                except (SyntaxError, ValueError):
                    text = blanked  # maybe a new f-string too, rewritten below
            rewritten = _nested_f_strings(text)
            if rewritten is None:
                raise
            try:
                tree = ast.parse(rewritten[0], filename=filename, mode=mode)
            except (SyntaxError, ValueError):
                pass
            else:
                _shift_back(tree, rewritten[1])
                return tree
            raise


def _type_parameters_blanked(text: str) -> str | None:
    """``text`` with the type parameter lists of its classes and functions blanked and
    its ``type`` statements written as assignments (PEP 695), every other character in
    its place; None when it has none, or its tokens cannot be read."""
    starts = [0]  # the offset of each line (tokenize's rows split at "\n")
    for index, char in enumerate(text):
        if char == "\n":
            starts.append(index + 1)
    try:
        tokens = [t for t in tokenize.generate_tokens(io.StringIO(text).readline)
                  if t.type not in (tokenize.COMMENT, tokenize.NL)]
    except (tokenize.TokenError, SyntaxError):
        return None
    chars = list(text)
    changed = False
    statement_start = True
    for i, token in enumerate(tokens):
        at_start, statement_start = statement_start, token.type in (
            tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT) or token.string == ";"
        if token.type != tokenize.NAME or i + 2 >= len(tokens):
            continue
        name, after = tokens[i + 1], tokens[i + 2]
        if name.type != tokenize.NAME:
            continue
        if token.string in ("class", "def") and after.string == "[":
            pass
        elif token.string == "type" and at_start and after.string in ("[", "="):
            # ``type Name = v`` read as ``Name = v``: the name where ``type`` was
            first = starts[token.start[0] - 1] + token.start[1]
            last = starts[name.end[0] - 1] + name.end[1]
            if token.start[0] != name.end[0]:
                continue
            chars[first:last] = list(name.string.ljust(last - first))
            changed = True
            if after.string != "[":
                continue
        else:
            continue
        close = _closing(tokens, i + 2)
        if close is None:
            return None
        first = starts[after.start[0] - 1] + after.start[1]
        last = starts[tokens[close].end[0] - 1] + tokens[close].end[1]
        for place in range(first, last):
            if chars[place] not in "\r\n":
                chars[place] = " "
            elif chars[place] == "\n":  # the bracket's line break: a continuation now
                before = place - 2 if place >= 2 and chars[place - 1] == "\r" else place - 1
                chars[before] = "\\"
        changed = True
    return "".join(chars) if changed else None


def _closing(tokens: list[tokenize.TokenInfo], opening: int) -> int | None:
    """The index of the token that closes the bracket at ``opening``."""
    depth = 0
    for index in range(opening, len(tokens)):
        string = tokens[index].string
        if tokens[index].type == tokenize.OP and string in "([{":
            depth += 1
        elif tokens[index].type == tokenize.OP and string in ")]}":
            depth -= 1
            if depth == 0:
                return index
    return None


class _Unreadable(Exception):
    """A string this scan does not rewrite (the text is left as it is)."""


def _nested_f_strings(text: str) -> tuple[str, dict[int, list[int]]] | None:
    """``text`` with every single-quoted f-string whose fields need Python 3.12 written
    triple-quoted, and, per line (1-based), the columns of the rewritten text where two
    quote characters were added; None when there is none, or one cannot be rewritten."""
    edits: list[tuple[int, int, str]] = []  # opening quote, closing quote, new quote
    swaps: list[tuple[int, str]] = []  # a string in a field, written without escapes
    i, n = 0, len(text)
    try:
        while i < n:
            char = text[i]
            if char == "#":
                end = text.find("\n", i)
                i = n if end == -1 else end
            elif char in _QUOTES:
                i = _top_string(text, i, "", edits, swaps)
            elif char.isalpha() or char == "_":
                start = i
                while i < n and (text[i].isalnum() or text[i] == "_"):
                    i += 1
                word = text[start:i]
                if i < n and text[i] in _QUOTES and word.lower() in _PREFIXES:
                    i = _top_string(text, i, word.lower(), edits, swaps)
            else:
                i += 1
    except _Unreadable:
        return None
    if not edits and not swaps:
        return None
    for start, written in swaps:  # each as wide as the string it replaces
        text = text[:start] + written + text[start + len(written):]
    pieces: list[str] = []
    added: dict[int, list[int]] = {}
    last = 0
    for opening, closing, quote in edits:
        pieces += [text[last:opening], quote * 3, text[opening + 1:closing], quote * 3]
        last = closing + 1
    pieces.append(text[last:])
    rewritten = "".join(pieces)
    # where each added pair of quotes is in the rewritten text, for the columns
    shift = 0
    for opening, closing, _ in edits:
        for place in (opening + shift, closing + shift + 2):
            line = rewritten.count("\n", 0, place) + 1
            column = place - (rewritten.rfind("\n", 0, place) + 1)
            added.setdefault(line, []).append(column)
        shift += 4
    return rewritten, added


def _top_string(text: str, at: int, prefix: str, edits: list[tuple[int, int, str]],
                swaps: list[tuple[int, str]]) -> int:
    """Scan the string whose quote is at ``at``; record it in ``edits`` when it is a
    single-quoted f-string that needs rewriting, and in ``swaps`` each string of its
    fields to be written without escapes. The index after it."""
    end, needs = _string(text, at, prefix, swaps)
    if needs:
        body = text[at + 1:end - 1]
        quote = next((q for q in (text[at], *_QUOTES) if q * 3 not in body
                      and not body.endswith(q)), None)
        if quote is None:
            raise _Unreadable
        edits.append((at, end - 1, quote))
    return end


def _string(text: str, at: int, prefix: str,
            swaps: list[tuple[int, str]]) -> tuple[int, bool]:
    """The index after the string whose quote is at ``at`` (``prefix`` before it), and
    whether it is a single-quoted f-string that only Python 3.12 reads (``swaps``: as
    ``_top_string``)."""
    quote = text[at]
    width = 3 if text.startswith(quote * 3, at) else 1
    fmt = "f" in prefix
    needs = False
    i, n = at + width, len(text)
    while i < n:
        char = text[i]
        if char == "\\":
            i += 2
            continue
        if text.startswith(quote * width, i):
            return i + width, needs
        if char == "\n" and width == 1:
            raise _Unreadable  # unterminated: not ours to mend
        if fmt and char == "{":
            if text.startswith("{{", i):
                i += 2
                continue
            i, field = _field(text, i + 1, quote, width, swaps)
            needs = needs or (field and width == 1)
            continue
        i += 1
    raise _Unreadable


def _field(text: str, at: int, quote: str, width: int,
           swaps: list[tuple[int, str]]) -> tuple[int, bool]:
    """The index after the replacement field that starts at ``at`` (after its ``{``) of
    an f-string quoted by ``quote`` ``width`` times, and whether the field needs Python
    3.12 (a line break in it, or a string quoted as the f-string). A string in the field
    with a backslash goes to ``swaps``, written without escapes (``_unescaped``)."""
    depth, needs = 0, False
    i, n = at, len(text)
    while i < n:
        char = text[i]
        if char in "([{":
            depth += 1
        elif char in ")]":
            depth -= 1
        elif char == "}":
            if depth == 0:
                return i + 1, needs
            depth -= 1
        elif char == "\n":
            needs = True
        elif char in "\\#":
            raise _Unreadable  # new in 3.12 too, and not written otherwise here
        elif char in _QUOTES or char.isalpha() or char == "_":
            start = i
            while i < n and (text[i].isalnum() or text[i] == "_"):
                i += 1
            word = text[start:i].lower()
            if i < n and text[i] in _QUOTES and (not word or word in _PREFIXES):
                inner = text[i]
                if inner == quote and (width == 3 or text.startswith(inner * 3, i)):
                    raise _Unreadable  # the f-string's own quotes, tripled
                end, inner_needs = _string(text, i, word, swaps)
                if inner_needs:
                    raise _Unreadable  # one level of rewriting only
                if "\\" in text[i:end]:
                    swaps.append((start, _unescaped(text[start:end], quote)))
                needs = needs or inner == quote
                i = end
            continue
        i += 1
    raise _Unreadable


def _unescaped(literal: str, quote: str) -> str:
    """The string ``literal`` (a plain or ``u`` string, on one line, in a field of an
    f-string quoted by ``quote``) written without backslashes, the characters its
    escapes stand for as they are and blanks after it to its width: an escape is two
    characters or more for one. ``_Unreadable`` when a character it stands for cannot
    be written so (a line break, a backslash, a NUL, a quote of both kinds)."""
    if literal[:1].lower() not in _QUOTES + "u" or "\n" in literal:
        raise _Unreadable  # raw, bytes or f-strings: their backslashes are themselves
    try:
        value = ast.literal_eval(literal)
    except (SyntaxError, ValueError):
        raise _Unreadable from None
    if not isinstance(value, str) or any(c in value for c in "\\\n\r\0"):
        raise _Unreadable
    new = next((q for q in _QUOTES if q != quote and q not in value), None)
    if new is None:
        raise _Unreadable
    return (new + value + new).ljust(len(literal))


def _shift_back(tree: ast.AST, added: dict[int, list[int]]) -> None:
    """Put the columns of a tree parsed from the rewritten text back on the file's own
    lines: two characters less for each pair of quotes added before the column."""
    for node in ast.walk(tree):
        for line_key, column_key in (("lineno", "col_offset"),
                                     ("end_lineno", "end_col_offset")):
            line, column = getattr(node, line_key, None), getattr(node, column_key, None)
            if line in added and isinstance(column, int):
                before = sum(2 for place in added[line] if place < column)
                setattr(node, column_key, max(column - before, 0))
