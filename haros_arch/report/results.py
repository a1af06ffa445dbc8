"""Text of the ``check``, ``query`` and ``compare`` commands' results for a terminal."""

from __future__ import annotations

from typing import TYPE_CHECKING

from rich.console import Console
from rich.markup import escape

from .findings import count, print_findings
from .text import count_by_severity, print_diagnostics

if TYPE_CHECKING:
    from ..live.compare import Comparison
    from ..query.command import Checked, Match


def print_check(checked: Checked, console: Console, verbose: bool = True) -> None:
    """Diagnostics (problems reading the workspace), findings, then their counts."""
    if checked.diagnostics:
        console.print("[bold]Diagnostics[/bold] (problems reading the workspace)",
                      highlight=False)
        print_diagnostics(checked.diagnostics, console, verbose)
        console.print()
    print_findings(checked.findings, console, verbose)
    counts = count(checked.findings)
    diag_counts = count_by_severity(checked.diagnostics)
    console.print(", ".join(f"{n} {k}(s)" for k, n in counts.items())
                  + f" from {checked.shipped} shipped queries; "
                  + ", ".join(f"{n} {k}(s)" for k, n in diag_counts.items())
                  + " in diagnostics", highlight=False)


def print_seconds(seconds: dict[str, float], console: Console) -> None:
    """Each rule's time, slowest first (``check -v``); none when the findings were read
    back from the run cache."""
    if not seconds:
        console.print("queries: not run (the findings of an earlier run were kept: "
                      "nothing changed, or only lines of C++ sources moved)",
                      highlight=False)
        return
    console.print(f"queries: {sum(seconds.values()):.2f} s; "
                  + ", ".join(f"{rule} {spent:.3f} s" for rule, spent in sorted(
                      seconds.items(), key=lambda kv: -kv[1])), highlight=False)


def print_matches(matches: list[Match], console: Console) -> None:
    """Each match (``[configuration] ``, the entities involved) with their locations."""
    from ..query.results import entities, label, location_of, plain

    for match in matches:
        prefix = f"[{match.configuration}] " if match.configuration else ""
        involved = entities(match.value)
        text = "; ".join(label(e) for e in involved) if involved else str(plain(match.value))
        places = sorted({str(location_of(e)) for e in involved if location_of(e).file})
        console.print(escape(prefix + text), highlight=False)
        for place in places:
            console.print(f"    {escape(place)}", highlight=False)
    console.print(f"{len(matches)} match(es)", highlight=False)


def print_comparison(result: Comparison, console: Console, both: bool = False) -> None:
    """Precision and recall per kind, with what is missing (only live) and extra (only in
    the model); with ``both``, also what is in both."""
    from ..live.compare import show

    console.print(f"configuration {result.configuration}", highlight=False)
    for score in result.scores:
        console.print(f"  {score.kind:<20} precision {score.precision:.3f}  recall "
                      f"{score.recall:.3f}  ({len(score.matched)} matched, {len(score.ours)} "
                      f"ours, {len(score.live)} live)", highlight=False)
        if score.differs is not None:
            for text in score.differs:
                console.print(f"      differs: {escape(text)}", highlight=False)
        else:
            for item in score.missing:
                console.print(f"      missing: {escape(show(item))}", highlight=False)
            for item in score.extra:
                console.print(f"      extra:   {escape(show(item))}", highlight=False)
        if both:
            for item in sorted(score.matched, key=str):
                console.print(f"      both:    {escape(show(item))}", highlight=False)
