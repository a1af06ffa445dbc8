"""``ast.parse`` for code read from the workspace: the compiler's warnings about it
(``SyntaxWarning: invalid decimal literal``, invalid escape sequences) are not ours to
print, so they are not printed."""

from __future__ import annotations

import ast
import warnings
from typing import Any


def parse(text: str, filename: str = "<unknown>", mode: str = "exec") -> Any:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return ast.parse(text, filename=filename, mode=mode)
