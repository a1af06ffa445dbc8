"""Findings as text: grouped by severity, each with file:line, what, why and the entities."""

from __future__ import annotations

from collections.abc import Iterable

from rich.console import Console
from rich.markup import escape

from ..model.diagnostic import SEVERITY_RANK
from ..model.finding import Finding

_COLOURS = {"error": "red", "warning": "yellow", "info": "blue"}


def print_findings(findings: Iterable[Finding], console: Console) -> None:
    """Errors first, then warnings, then infos; one block per finding."""
    items = sorted(findings, key=lambda f: (-SEVERITY_RANK[f.severity],
                                            f.location.file or "", f.location.line, f.rule))
    for severity in sorted(SEVERITY_RANK, key=lambda s: -SEVERITY_RANK[s]):
        group = [f for f in items if f.severity == severity]
        if not group:
            continue
        colour = _COLOURS[severity]
        console.print(f"[bold {colour}]{severity.upper()}S ({len(group)})[/bold {colour}]",
                      highlight=False)
        for finding in group:
            where = str(finding.location) if finding.location.file else "<no location>"
            config = f" [dim]\\[{escape(finding.configuration)}][/dim]" \
                if finding.configuration else ""
            console.print(f"  {escape(where)}: [{colour}]{severity}[/{colour}]: "
                          f"{escape(finding.title)} [dim]\\[{escape(finding.rule)}][/dim]"
                          f"{config}", highlight=False)
            console.print(f"      {escape(finding.message)}", highlight=False)
            if finding.entities:
                console.print(f"      [dim]involves: {escape(', '.join(finding.entities))}"
                              "[/dim]", highlight=False)


def count(findings: Iterable[Finding]) -> dict[str, int]:
    counts = dict.fromkeys(SEVERITY_RANK, 0)
    for finding in findings:
        counts[finding.severity] += 1
    return counts
