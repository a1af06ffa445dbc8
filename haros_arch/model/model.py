"""The whole analysis result: packages (source side) and configurations (runtime side)."""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from itertools import chain

from .diagnostic import Diagnostic
from .location import Location
from .runtime import Configuration
from .source import Node, Package


@dataclass(eq=False)
class Model:
    project: str
    packages: list[Package] = field(default_factory=list)
    configurations: list[Configuration] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)

    # the names the HAROS queries use
    @property
    def configs(self) -> list[Configuration]:
        return self.configurations

    @property
    def nodes(self) -> list[Node]:
        return [node for package in self.packages for node in package.nodes]

    @property
    def files(self) -> list[str]:
        return sorted({src for node in self.nodes for src in node.sources})

    def package(self, name: str) -> Package | None:
        return next((p for p in self.packages if p.name == name), None)

    def configuration(self, name: str) -> Configuration | None:
        return next((c for c in self.configurations if c.name == name), None)

    @property
    def all_diagnostics(self) -> list[Diagnostic]:
        """Every diagnostic once (configurations that share launch files repeat them);
        one said at the same place by several configurations, each with other places
        (``also``: an unset argument's other uses), once with all of them."""
        found: dict[tuple[str, str, str, Location], Diagnostic] = {}
        for item in chain(self.diagnostics, *(c.diagnostics for c in self.configurations)):
            key = (item.code, item.severity, item.message, item.location)
            had = found.setdefault(key, item)
            if had is not item and item.also and item.also != had.also:
                found[key] = replace(had, also=tuple(dict.fromkeys((*had.also, *item.also))))
        return list(found.values())
