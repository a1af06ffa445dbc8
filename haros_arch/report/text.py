"""Plain-text output for terminals and CI logs."""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable
from typing import Protocol

from ..model.diagnostic import SEVERITY_RANK, Diagnostic
from ..model.location import Location
from ..model.model import Model
from ..model.runtime import LAUNCH_WRITER, Configuration, NodeInstance, Parameter, Resource
from ..query.absence import unread_launch
from .escape import escape


class Printer(Protocol):
    """Where the text output goes: a rich ``Console``, or ``Lines``."""

    def print(self, text: str, /, *, highlight: bool | None = None) -> None: ...


class Lines:
    """A printer that keeps the lines printed to it (rich markup), to print later: the
    summary a kept run prints again (``summary_lines``)."""

    def __init__(self) -> None:
        self.lines: list[str] = []

    def print(self, text: str, /, *, highlight: bool | None = None) -> None:
        self.lines.append(text)


def summary_lines(model: Model, verbose: bool = False) -> list[str]:
    """What ``extract`` prints of a model: its summary, then its diagnostics."""
    lines = Lines()
    print_summary(model, lines, verbose=verbose)
    print_diagnostics(model.all_diagnostics, lines, verbose=verbose)
    return lines.lines


def print_diagnostics(diagnostics: Iterable[Diagnostic], console: Printer,
                      verbose: bool = True) -> None:
    """Diagnostics grouped by file, each with line:col, severity, message and code.

    Without ``verbose``, info-level diagnostics (mostly gaps of the C++ stand-in headers:
    there can be hundreds on a real workspace) are not listed one by one but counted per
    code at the end, with the first place each code was seen; and a diagnostic said
    again in the same file with the same message (an unset argument at each of its
    uses in one file) is listed once, at its first place, with the others as ``also
    at``. A diagnostic said once for several places (``Diagnostic.also``: an unset
    argument, once per configuration) lists them as ``also at`` too, all of them with
    ``verbose``.
    """
    items = list(diagnostics)
    shown = items if verbose else [d for d in items if d.severity != "info"]
    by_file: dict[str, list[Diagnostic]] = defaultdict(list)
    for item in shown:
        by_file[item.location.file or "<project>"].append(item)
    colours = {"error": "red", "warning": "yellow", "info": "blue"}
    for file in sorted(by_file):
        console.print(f"[bold]{escape(file)}[/bold]", highlight=False)
        ordered = sorted(by_file[file], key=lambda d: (d.location.line, d.location.column))
        repeats: dict[tuple[str, str, str], list[Diagnostic]] = {}
        for item in ordered:
            repeats.setdefault((item.severity, item.code, item.message), []).append(item)
        for item in ordered:
            group = repeats[(item.severity, item.code, item.message)]
            if not verbose and group[0] is not item:
                continue
            where = f"{file}:{item.location.line}:{item.location.column}"
            colour = colours.get(item.severity, "white")
            console.print(f"  {escape(where)}: [{colour}]{item.severity}[/{colour}]: "
                          f"{escape(item.message)} [dim]\\[{item.code}][/dim]",
                          highlight=False)
            # its own other places (an unset argument's other uses), and without
            # ``verbose`` those of the same said again in this file
            others = _places([*item.also] if verbose else [
                place for d in group for place in (d.location, *d.also)],
                exclude=item, limit=None if verbose else ALSO_AT_LISTED)
            if others:
                console.print(f"{_ALSO_AT}{escape(others)}[/dim]", highlight=False)
    if not verbose:
        _print_info_counts([d for d in items if d.severity == "info"], console)


ALSO_AT_LISTED = 8  # places of a repeated diagnostic listed before "and N more"
_ALSO_AT = "      [dim]also at: "


def bare_places(lines: Iterable[str], files: Iterable[str]) -> bool:
    """Whether ``print_diagnostics``, in ``lines``, lists other places of one of
    ``files`` (as the model names them) by ``line:col`` alone, under the file's name
    (``also at``): places a renumbering of ``path:line`` ones (``relocate``) does not
    see."""
    headers = {f"[bold]{escape(file)}[/bold]" for file in files}
    under = False
    for line in lines:
        if line.startswith("[bold]") and line.endswith("[/bold]"):
            under = line in headers
        elif under and line.startswith(_ALSO_AT):
            return True
    return False


def _places(places: list[Location], exclude: Diagnostic, limit: int | None) -> str:
    """``line:col`` of each place (``file:line:col`` in another file than ``exclude``'s;
    distinct, in order, not ``exclude``'s own), the first ``limit``, then how many more;
    empty when none is left."""
    file = exclude.location.file
    texts = list(dict.fromkeys(
        f"{'' if where.file == file else f'{where.file}:'}{where.line}:{where.column}"
        for where in places if where != exclude.location))
    text = ", ".join(texts[:limit])
    if limit is not None and len(texts) > limit:
        text += f" and {len(texts) - limit} more"
    return text


def _print_info_counts(infos: list[Diagnostic], console: Printer) -> None:
    if not infos:
        return
    by_code: dict[str, list[Diagnostic]] = defaultdict(list)
    for item in infos:
        by_code[item.code].append(item)
    console.print(f"[blue]{len(infos)} info diagnostic(s)[/blue], not listed "
                  "(--verbose lists them):", highlight=False)
    for code, group in sorted(by_code.items(), key=lambda kv: (-len(kv[1]), kv[0])):
        first = min(group, key=lambda d: (d.location.file or "", d.location.line,
                                          d.location.column))
        where = f"{first.location.file or '<project>'}:{first.location.line}:" \
                f"{first.location.column}"
        console.print(f"  {len(group):>5} {escape(code)}  [dim]first at {escape(where)}: "
                      f"{escape(first.message)}[/dim]", highlight=False)


INCOMPLETE_LISTED = 10  # nodes of partial or unknown interface named without --verbose


def print_summary(model: Model, console: Printer, verbose: bool = False) -> None:
    """Per configuration: counts per kind and the node instances whose interface is
    partial or unknown (with why); ``verbose`` lists every node instance and resource
    with who uses it."""
    nodes = model.nodes
    calls = sum(len(node.calls) for node in nodes)
    console.print(f"[bold]{escape(model.project)}[/bold]: {len(model.packages)} package(s), "
                  f"{len(nodes)} node(s), {calls} ROS call(s) found in source",
                  highlight=False)
    for config in model.configurations:
        counts = ", ".join(f"{len(items)} {label}" for label, items in (
            ("nodes", config.nodes), ("topics", config.topics),
            ("services", config.services), ("actions", config.actions),
            ("parameters", config.parameters), ("links", config.links)))
        console.print(f"\n[bold]configuration {escape(config.name)}[/bold]: {counts}",
                      highlight=False)
        _print_incomplete(config.incomplete_nodes, console, verbose,
                          len(unread_launch(config)))
        if verbose:
            _print_everything(config, console)
    if not verbose and model.configurations:
        console.print("[dim](-v lists every node, topic, service, action and parameter)"
                      "[/dim]", highlight=False)


def _print_incomplete(incomplete: list[NodeInstance], console: Printer,
                      verbose: bool, unread: int = 0) -> None:
    if unread:
        # what an include or action the launch stage could not read starts is not known
        console.print(f"  {unread} launch include(s) or action(s) not read: the nodes "
                      "they start are not seen, so checks that claim an absence do not "
                      "decide", highlight=False)
    if not incomplete:
        console.print("  every node's interface is known" if not unread else
                      "  every node seen has a known interface", highlight=False)
        return
    by_kind: dict[str, int] = defaultdict(int)
    for instance in incomplete:
        by_kind[instance.completeness] += 1
    console.print(f"  {len(incomplete)} node(s) whose interface is not fully known ("
                  + ", ".join(f"{n} {kind}" for kind, n in sorted(by_kind.items()))
                  + "): checks that claim an absence do not decide where they could be "
                  "the missing side", highlight=False)
    shown = incomplete if verbose else incomplete[:INCOMPLETE_LISTED]
    for instance in shown:
        runs = instance.node.name if instance.node else "?"
        reasons = "; ".join(instance.completeness_reasons[:2])
        console.print(f"    {escape(instance.name)}  [dim]{escape(runs)}, "
                      f"{instance.completeness}: {escape(reasons)}[/dim]", highlight=False)
    if len(incomplete) > len(shown):
        console.print(f"    [dim]... and {len(incomplete) - len(shown)} more[/dim]",
                      highlight=False)


def _print_everything(config: Configuration, console: Printer) -> None:
    for instance in config.nodes:
        runs = instance.node.name if instance.node else "? (not in the workspace)"
        conditional = " [dim](conditional)[/dim]" if instance.conditions else ""
        console.print(f"  node  {escape(instance.name)}  [dim]{escape(runs)}[/dim]"
                      f"{conditional}",
                      highlight=False)
    folded = 0
    for label, resources in (("topic", config.topics), ("service", config.services),
                             ("action", config.actions),
                             ("param", config.parameters)):
        for resource in resources:
            if resource.links and all(link.origin == "action" for link in resource.links):
                folded += 1  # the topics and services an action is made of
                continue
            types = ", ".join(resource.types) or "?"
            console.print(f"  {label:<7} {escape(resource.name)}  "
                          f"[dim]{escape(types)}[/dim]",
                          highlight=False)
            for line in _uses(resource):
                console.print(f"            {escape(line)}", highlight=False)
    if folded:
        console.print(f"  [dim](and {folded} topics and services inside its actions)[/dim]",
                      highlight=False)


def _uses(resource: Resource) -> list[str]:
    by_kind: dict[str, list[str]] = defaultdict(list)
    if isinstance(resource, Parameter) and resource.set_by_launch:
        by_kind["set by"].append(LAUNCH_WRITER)
    for link in resource.links:
        by_kind[_VERBS.get(link.kind, link.kind)].append(link.node.name)
    return [f"{verb}: {', '.join(dict.fromkeys(names))}" for verb, names in by_kind.items()]


_VERBS = {"publish": "published by", "subscribe": "subscribed by", "server": "served by",
          "client": "called by", "action-server": "served by", "action-client": "called by",
          "read": "read by", "write": "set by"}


def count_by_severity(diagnostics: Iterable[Diagnostic]) -> dict[str, int]:
    counts = dict.fromkeys(SEVERITY_RANK, 0)
    for item in diagnostics:
        counts[item.severity] += 1
    return counts
