"""Plain-text output for terminals and CI logs."""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable

from rich.console import Console
from rich.table import Table

from ..model.diagnostic import SEVERITY_RANK, Diagnostic
from ..model.model import Model


def print_diagnostics(diagnostics: Iterable[Diagnostic], console: Console) -> None:
    """Diagnostics grouped by file, each with line:col, severity, message and code."""
    by_file: dict[str, list[Diagnostic]] = defaultdict(list)
    for item in diagnostics:
        by_file[item.location.file or "<project>"].append(item)
    colours = {"error": "red", "warning": "yellow", "info": "blue"}
    for file in sorted(by_file):
        console.print(f"[bold]{file}[/bold]", highlight=False)
        for item in sorted(by_file[file], key=lambda d: (d.location.line, d.location.column)):
            where = f"{file}:{item.location.line}:{item.location.column}"
            colour = colours.get(item.severity, "white")
            console.print(f"  {where}: [{colour}]{item.severity}[/{colour}]: "
                          f"{item.message} [dim]\\[{item.code}][/dim]", highlight=False)


def print_summary(model: Model, console: Console) -> None:
    nodes = model.nodes
    calls = sum(len(node.calls) for node in nodes)
    console.print(f"[bold]{model.project}[/bold]: {len(model.packages)} package(s), "
                  f"{len(nodes)} node(s), {calls} ROS call(s) found in source",
                  highlight=False)
    for config in model.configurations:
        table = Table(title=f"configuration {config.name}", title_justify="left",
                      show_lines=False)
        table.add_column("kind")
        table.add_column("name")
        table.add_column("type")
        table.add_column("links")
        for instance in config.nodes:
            table.add_row("node", instance.name,
                          instance.node.name if instance.node else "? (not found)", "")
        for kind, resources in (("topic", config.topics), ("service", config.services),
                                ("action", config.actions),
                                ("parameter", config.parameters)):
            for resource in resources:
                links = ", ".join(f"{link.kind} {link.node.name}" for link in resource.links)
                if kind == "parameter" and getattr(resource, "set_by_launch", False):
                    links = ", ".join(x for x in ("set by launch", links) if x)
                table.add_row(kind, resource.name, ", ".join(resource.types) or "?", links)
        console.print(table)


def count_by_severity(diagnostics: Iterable[Diagnostic]) -> dict[str, int]:
    counts = dict.fromkeys(SEVERITY_RANK, 0)
    for item in diagnostics:
        counts[item.severity] += 1
    return counts
