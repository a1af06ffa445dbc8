"""Source conditions in Python: the control statements a call sits in.

One ``Condition`` per enclosing construct: ``if`` (its test), ``else`` (the test of its
``if``; an ``elif`` is an ``else`` and an ``if``), ``for`` (``target in iterable``),
``while`` (its test), ``try`` (empty text), ``except`` (the exception caught),
``match`` + ``case``. ``if __name__ == '__main__':`` is the script's entry, not a
condition, and a test of ``__name__`` against a name the module cannot have is decided
(``name_test``); ``with`` and ``finally`` blocks always run. Texts are the source as written,
whitespace collapsed; a presence test of a parameter named by a variable is written with
the name the variable holds (``tested_text``).
"""

from __future__ import annotations

import ast
import os
import re
from collections.abc import Callable

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


def name_test(test: ast.expr, path: str) -> bool | None:
    """The value of ``__name__ == 'text'`` (or ``!=``, either way round) in the module at
    ``path``, where no module name it may have is ``text``: ``__name__`` is ``'__main__'``
    when the file runs as a script and its import name (``pkg.module``) when imported, as
    an entry point's module is before its function is called. So ``if __name__ ==
    "main":`` never runs (drone_autonomous_landing_on_ugv's nodes, which their entry
    points start through ``main``), unless the file is ``main.py``. None for any other
    test, and for ``'__main__'`` (``is_main_guard``)."""
    if not (isinstance(test, ast.Compare) and len(test.ops) == 1
            and isinstance(test.ops[0], ast.Eq | ast.NotEq)):
        return None
    sides = [test.left, test.comparators[0]]
    names = [s for s in sides if isinstance(s, ast.Name) and s.id == "__name__"]
    texts = [s.value for s in sides if isinstance(s, ast.Constant) and isinstance(s.value, str)]
    if not names or not texts or texts[0] == "__main__":
        return None
    stem = os.path.splitext(os.path.basename(path))[0]
    if os.path.basename(path) == "__init__.py":
        stem = os.path.basename(os.path.dirname(path))  # a package's module is its folder
    if texts[0].rsplit(".", 1)[-1] == stem:
        return None  # its import name may be that
    return isinstance(test.ops[0], ast.NotEq)


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


# the functions that tell whether a parameter is set (rospy's ``has_param``)
_PRESENCE_CALLS = frozenset({"has_param"})


def tested_text(lines: list[str], test: ast.expr, name_of: Callable[[ast.expr], str | None]
                ) -> str:
    """The text of ``test``, each presence test of a parameter whose name is not a
    literal (``rospy.has_param(private)``) written with the name its argument holds
    where ``name_of`` knows it (``rospy.has_param('~source_list')``): a helper that
    tests the private parameter, then the global one, tests one name per call, and the
    graph decides the test by it (``graph.conditions``)."""
    text = source_text(lines, test)
    for node in ast.walk(test):
        func = node.func if isinstance(node, ast.Call) else None
        called = func.attr if isinstance(func, ast.Attribute) else (
            func.id if isinstance(func, ast.Name) else None)
        if called not in _PRESENCE_CALLS or not isinstance(node, ast.Call) or len(
                node.args) != 1 or node.keywords or isinstance(node.args[0], ast.Constant):
            continue
        name = name_of(node.args[0])
        if name:
            written = source_text(lines, node.args[0])
            text = text.replace(f"{called}({written})", f"{called}({name!r})")
    return text
