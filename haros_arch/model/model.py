"""The whole analysis result: packages (source side) and configurations (runtime side)."""

from __future__ import annotations

from dataclasses import dataclass, field

from .diagnostic import Diagnostic
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
        """Every diagnostic once (configurations that share launch files repeat them)."""
        found = dict.fromkeys(self.diagnostics)
        for config in self.configurations:
            found.update(dict.fromkeys(config.diagnostics))
        return list(found)
