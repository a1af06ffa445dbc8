"""The ``Diagnostic`` value: a problem found in the analysed input.

Codes and their explanations live in ``haros_arch.diagnostics.CATALOGUE``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

from .location import NOWHERE, Location

Severity = Literal["error", "warning", "info"]
SEVERITY_RANK = {"info": 0, "warning": 1, "error": 2}


@dataclass(frozen=True)
class Diagnostic:
    code: str
    severity: Severity
    message: str
    location: Location = field(default=NOWHERE)

    def __str__(self) -> str:
        return f"{self.location}: {self.severity}: {self.message} [{self.code}]"
