"""The ``Diagnostic`` value: a problem found in the analysed input.

Codes and their explanations live in ``haros_arch.diagnostics.CATALOGUE``.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from typing import Literal

from .location import NOWHERE, Location

Severity = Literal["error", "warning", "info"]
SEVERITY_RANK = {"info": 0, "warning": 1, "error": 2}


@dataclass(frozen=True)
class Diagnostic:
    """``also`` lists the other places of the same problem, said once (an unset launch
    argument at each of its uses: ``said_once``)."""

    code: str
    severity: Severity
    message: str
    location: Location = field(default=NOWHERE)
    also: tuple[Location, ...] = field(default=(), metadata={"optional": True})

    def __str__(self) -> str:
        return f"{self.location}: {self.severity}: {self.message} [{self.code}]"


# what is said once per configuration, at its first place, the others in ``also``: an
# argument left without a value is one thing to give (``name:=value`` on the command
# line), whatever number of uses shows it (osrf/subt's ``name``, a thousand of them), and
# so is an argument an included file requires and its include does not pass (the message
# names that file: each use of the argument in it said it again)
SAID_ONCE = frozenset({"LAUNCH_ARG_UNSET", "LAUNCH_ARG_REQUIRED"})


def said_once(diagnostics: Iterable[Diagnostic], codes: frozenset[str] = SAID_ONCE
              ) -> list[Diagnostic]:
    """``diagnostics`` with those of ``codes`` that say the same (code, severity and
    message) merged into the first, the places of the others in its ``also`` (each
    once, in order, not the first's own); every other diagnostic as it is."""
    items = list(diagnostics)
    places: dict[tuple[str, str, str], list[Location]] = {}
    for item in items:
        if item.code in codes:
            places.setdefault((item.code, item.severity, item.message), []).extend(
                (item.location, *item.also))
    out: list[Diagnostic] = []
    for item in items:
        key = (item.code, item.severity, item.message)
        if item.code not in codes:
            out.append(item)
        elif key in places:
            first, *others = dict.fromkeys(places.pop(key))
            out.append(replace(item, location=first, also=tuple(others)))
    return out
