"""Values that may be only partly known statically.

A ``Value`` is a sequence of parts; each part is either literal text or an ``Unknown``
that remembers where the unknown came from (an unset launch argument, an environment
variable, a string read at run time). Names built from such values keep every known part
and show ``?`` where a part is unknown.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any, Literal

from .location import Location

UNKNOWN_MARK = "?"


UnknownKind = Literal["unknown", "unsupported", "undefined", "error", "syntax", "limit"]


@dataclass(frozen=True)
class Unknown:
    """A value, or a part of one, that cannot be known statically: the one spelling of
    "unknown" every reader and evaluator uses. ``origin`` says where it came from; ``kind``
    why it is not known: ``unknown`` (it depends on a value nobody knows, e.g. an unset
    argument), ``unsupported`` (a construct outside the safe subset, never run),
    ``undefined`` (a name that is not defined), ``error`` (Python would raise, e.g. a
    division by zero), ``syntax`` (not Python), ``limit`` (a work bound was reached).
    ``causes``: the origins of the unknowns it was computed from, when there are several
    (an expression over two unset arguments is one unknown with both as causes); not
    saved in models. ``where``: the place that made it, when a reader knows it (a call a
    launch file's interpreter did not run); not compared, not saved in models."""

    origin: str = ""
    kind: UnknownKind = "unknown"
    causes: tuple[str, ...] = field(default=(), metadata={"json": False})
    where: Location | None = field(default=None, compare=False, metadata={"json": False})

    @property
    def reason(self) -> str:
        return self.origin

    def __str__(self) -> str:
        return UNKNOWN_MARK


Part = str | Unknown


@dataclass(frozen=True)
class Value:
    parts: tuple[Part, ...] = ()
    # the rewritten parameter file (a launch ``ParamFile``) this path stands for, when
    # the value is that file's path passed on as it is (nav2's ``RewrittenYaml`` given to
    # an included launch file as its ``params_file`` argument); text made of it has none
    file: Any = field(default=None, compare=False, hash=False, repr=False)

    @classmethod
    def of(cls, *parts: Part | Value) -> Value:
        """Concatenate literals, unknowns and other values, merging adjacent literals."""
        merged: list[Part] = []
        for item in parts:
            pieces: Iterable[Part] = item.parts if isinstance(item, Value) else (item,)
            for piece in pieces:
                if isinstance(piece, str):
                    if not piece:
                        continue
                    if merged and isinstance(merged[-1], str):
                        merged[-1] = merged[-1] + piece
                        continue
                merged.append(piece)
        return cls(tuple(merged))

    @classmethod
    def unknown(cls, origin: str = "") -> Value:
        return cls((Unknown(origin),))

    @property
    def is_known(self) -> bool:
        return all(isinstance(p, str) for p in self.parts)

    @property
    def text(self) -> str:
        """The value as text, with ``?`` for each unknown part."""
        return "".join(str(p) for p in self.parts)

    @property
    def literal(self) -> str | None:
        """The text when fully known, else None."""
        return self.text if self.is_known else None

    @property
    def origins(self) -> tuple[str, ...]:
        """Where each unknown part comes from, in order (an unknown computed from several:
        its causes)."""
        return tuple(origin for p in self.parts if isinstance(p, Unknown)
                     for origin in (p.causes or (p.origin,)))

    def __add__(self, other: Value | str) -> Value:
        return Value.of(self, other)

    def __str__(self) -> str:
        return self.text


def scalar_type(value: object) -> str | None:
    """The ROS parameter type of a Python scalar: bool, int, double or str (None if not one).

    ``bool`` is tested before ``int``, which it subclasses in Python.
    """
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "int"
    if isinstance(value, float):
        return "double"
    if isinstance(value, str):
        return "str"
    return None
