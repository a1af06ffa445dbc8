"""A query finding: what a catalogue or user query matched, as a value."""

from __future__ import annotations

from dataclasses import dataclass, field

from .diagnostic import Severity
from .location import NOWHERE, Location


@dataclass(frozen=True)
class Finding:
    """One problem a query found, in one or more configurations.

    ``configuration`` is the first configuration it was found in and ``configurations``
    all of them (the same finding in several configurations is one finding);
    ``also`` lists other places where the same problem shows (a second call site);
    ``entities`` holds the ``id``s of the runtime entities involved ("node:/talker",
    "topic:/chatter", ...), so a report can highlight them; ``location`` is the most
    useful place to look (a source line or a launch file line).
    """

    rule: str
    severity: Severity
    title: str
    message: str
    configuration: str | None = None
    entities: tuple[str, ...] = ()
    location: Location = field(default=NOWHERE)
    configurations: tuple[str, ...] = ()
    also: tuple[Location, ...] = ()  # other places of the same problem (call sites)

    def __post_init__(self) -> None:
        if not self.configurations and self.configuration is not None:
            object.__setattr__(self, "configurations", (self.configuration,))
