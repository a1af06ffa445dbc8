"""Findings as text: grouped by rule (errors first), each rule with its title and count,
then its first findings with file:line, the message, the configurations and entities."""

from __future__ import annotations

from collections.abc import Iterable

from rich.console import Console

from ..model.diagnostic import SEVERITY_RANK
from ..model.finding import Finding
from .escape import escape

_COLOURS = {"error": "red", "warning": "yellow", "info": "blue"}
FIRST_FEW = 3  # findings listed per rule without --verbose


def by_rule(findings: Iterable[Finding]) -> list[tuple[str, list[Finding]]]:
    """(rule, its findings) with the most severe rules first, then by id; inside a rule
    by place."""
    groups: dict[str, list[Finding]] = {}
    for finding in findings:
        groups.setdefault(finding.rule, []).append(finding)
    for items in groups.values():
        items.sort(key=lambda f: (f.location.file or "~", f.location.line, f.message))
    return sorted(groups.items(), key=lambda kv: (
        -max(SEVERITY_RANK[f.severity] for f in kv[1]), kv[0]))


def print_findings(findings: Iterable[Finding], console: Console,
                   verbose: bool = False) -> None:
    """One block per rule: severity, title, id and count, then the first few findings
    (all of them with ``verbose``)."""
    for rule, items in by_rule(findings):
        severity = max((f.severity for f in items), key=lambda s: SEVERITY_RANK[s])
        colour = _COLOURS[severity]
        console.print(f"[bold {colour}]{severity}[/bold {colour}] [bold]"
                      f"{escape(items[0].title)}[/bold] [dim]\\[{escape(rule)}][/dim]: "
                      f"{len(items)}", highlight=False)
        shown = items if verbose else items[:FIRST_FEW]
        for finding in shown:
            where = str(finding.location) if finding.location.file else "<no location>"
            configs = f" [dim]\\[{escape(', '.join(finding.configurations))}][/dim]" \
                if finding.configurations else ""
            console.print(f"  {escape(where)}: {escape(finding.message)}{configs}",
                          highlight=False)
            if finding.also:
                console.print(f"      [dim]also at: {escape(', '.join(map(str, finding.also)))}"
                              "[/dim]", highlight=False)
            if finding.entities:
                console.print(f"      [dim]involves: {escape(', '.join(finding.entities))}"
                              "[/dim]", highlight=False)
        if len(items) > len(shown):
            console.print(f"  [dim]... and {len(items) - len(shown)} more (-v lists "
                          "all)[/dim]", highlight=False)


def count(findings: Iterable[Finding]) -> dict[str, int]:
    counts = dict.fromkeys(SEVERITY_RANK, 0)
    for finding in findings:
        counts[finding.severity] += 1
    return counts
