"""YAML text with unknown substitutions in it (``subst_value`` / ``allow_substs``).

A substitution whose value cannot be known is written into the text as ``MARK``; the
text is then read as YAML, and ``unknown_parts`` turns what holds a mark into what the
model says for "not known": a value becomes ``None``, a key gets ``?`` for that part.
"""

from __future__ import annotations

from typing import Any

from ..model.values import Value

MARK = "\u2047haros_unknown\u2047"


def marked_text(value: Value) -> str:
    """The text of ``value`` with ``MARK`` where a part is unknown."""
    return "".join(p if isinstance(p, str) else MARK for p in value.parts)


def unknown_parts(value: Any) -> Any:
    """``value`` read from marked YAML: marked strings unknown (None), a list with an
    unknown item unknown, marked keys with ``?``."""
    if isinstance(value, str) and MARK in value:
        return None
    if isinstance(value, list):
        items = [unknown_parts(v) for v in value]
        return None if any(i is None and v is not None for i, v in zip(items, value,
                                                                         strict=True)) \
            else items
    if isinstance(value, dict):
        return {(k.replace(MARK, "?") if isinstance(k, str) else k): unknown_parts(v)
                for k, v in value.items()}
    return value
