"""Source conditions in Python: the control statements a call sits in.

One ``Condition`` per enclosing construct: ``if`` (its test), ``else`` (the test of its
``if``; an ``elif`` is an ``else`` and an ``if``), ``for`` (``target in iterable``),
``while`` (its test), ``try`` (empty text), ``except`` (the exception caught),
``match`` + ``case``. ``if __name__ == '__main__':`` is the script's entry, not a
condition; ``with`` and ``finally`` blocks always run. Texts are the source as written,
whitespace collapsed.
"""

from __future__ import annotations

import ast
import re

from ...model.conditions import Condition
from ...model.location import Location

_SPACE = re.compile(r"\s+")
MAX_TEXT = 200


def source_text(lines: list[str], node: ast.AST) -> str:
    """The source of ``node`` from the module's ``lines`` (offsets are UTF-8 bytes)."""
    text = _segment(lines, node)
    if text is None:
        try:
            text = ast.unparse(node)
        except (ValueError, RecursionError):
            text = "?"
    text = _SPACE.sub(" ", text).strip()
    return text if len(text) <= MAX_TEXT else text[: MAX_TEXT - 3] + "..."


def is_main_guard(test: ast.expr) -> bool:
    """``__name__ == '__main__'``, either way round."""
    if not (isinstance(test, ast.Compare) and len(test.ops) == 1
            and isinstance(test.ops[0], ast.Eq)):
        return False
    sides = [test.left, test.comparators[0]]
    names = [s for s in sides if isinstance(s, ast.Name) and s.id == "__name__"]
    mains = [s for s in sides if isinstance(s, ast.Constant) and s.value == "__main__"]
    return bool(names and mains)


def condition(statement: str, text: str, location: Location,
              parameters: tuple[tuple[str, str], ...] | None = None) -> Condition:
    """A source condition; ``parameters``: what its text reads that holds a parameter's
    value (``Condition.parameters``)."""
    return Condition(text, "source", statement, location, parameters=parameters)


def _segment(lines: list[str], node: ast.AST) -> str | None:
    first, last = getattr(node, "lineno", None), getattr(node, "end_lineno", None)
    start, end = getattr(node, "col_offset", None), getattr(node, "end_col_offset", None)
    if first is None or last is None or start is None or end is None or last > len(lines) \
            or last - first > 20:
        return None
    chunk = [line.encode("utf-8") for line in lines[first - 1:last]]
    if len(chunk) == 1:
        return chunk[0][start:end].decode("utf-8", "replace")
    chunk[0], chunk[-1] = chunk[0][start:], chunk[-1][:end]
    return b"".join(chunk).decode("utf-8", "replace")
