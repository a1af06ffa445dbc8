"""Conditions under which an entity exists.

An entity's ``conditions`` is a tuple read as a conjunction; an empty tuple means the
entity exists unconditionally.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

from .location import NOWHERE, Location

ConditionKind = Literal["launch", "source", "hint"]


@dataclass(frozen=True)
class Condition:
    """One condition: ``text`` as written, where it comes from and the construct."""

    text: str
    kind: ConditionKind = "source"
    statement: str = "if"
    location: Location = field(default=NOWHERE)
    # a source condition in ``main``: its ``argc`` / ``argv`` are the program's own
    # arguments, which a launch file's ``args`` tell (graph.conditions decides it)
    program_args: bool = field(default=False, metadata={"optional": True})

    def __str__(self) -> str:
        return f"{self.statement} ({self.text})"
