"""The ``check`` and ``query`` commands' work, called by the thin CLI.

Each function takes parsed arguments and consoles and returns the exit code, so tests
and scripts can call them without a subprocess.
"""

from __future__ import annotations

import json
import os
from collections.abc import Callable
from typing import Any

from rich.console import Console
from rich.markup import escape

from ..autoproject import open_project
from ..model.diagnostic import SEVERITY_RANK, Diagnostic
from ..model.finding import Finding
from ..model.model import Model
from ..model.serialise import model_to_data, to_data
from ..project import Project, ProjectError
from . import CONFIG_NAMES, QueryError, compile, config_scope, model_scope
from .catalogue import absorbed, load_catalogue, project_rules, run_catalogue
from .results import entities, label, location_of, plain

EXIT_OK, EXIT_FINDINGS, EXIT_USAGE = 0, 1, 2
Analyse = Callable[[str, Console], "Model | None"]


def _write(text: str, output: str | None) -> None:
    if output:
        with open(output, "w", encoding="utf-8") as handle:
            handle.write(text)
    else:
        import sys
        sys.stdout.write(text)


def document(model: Model, project: Project | None) -> dict[str, Any]:
    """The JSON model with a top-level ``findings`` list (what ``extract`` writes)."""
    data = model_to_data(model)
    data["findings"] = to_data(run_catalogue(model, project))
    return data


def check(args: Any, out: Console, err: Console, analyse: Analyse) -> int:
    """Diagnostics and catalogue findings, in text, JSON, SARIF or JUnit."""
    try:
        project = open_project(args.project)
    except ProjectError as error:
        err.print(f"haros-arch: {error}", highlight=False)
        return EXIT_USAGE
    model = analyse(args.project, err)
    if model is None:
        return EXIT_USAGE
    seconds: dict[str, float] = {}
    findings = run_catalogue(model, project, seconds=seconds)
    said = absorbed(model)  # what catalogue rules report as findings
    diagnostics = [d for d in model.all_diagnostics if d not in said]
    fmt = getattr(args, "format", "text")
    if fmt == "json":
        _write(json.dumps({"diagnostics": to_data(diagnostics),
                           "findings": to_data(findings)}, indent=2) + "\n", args.output)
    elif fmt == "sarif":
        from ..report.sarif import dumps as sarif

        rules = {r.id: (r.title, r.description.strip())
                 for r in [*load_catalogue(), *project_rules(project)]}
        _write(sarif(findings, diagnostics, rules, project.workspace[0]
                     if project.workspace else None), args.output)
    elif fmt == "junit":
        from ..report.junit import to_junit

        checked = [r.id for r in [*load_catalogue(), *project_rules(project)]]
        _write(to_junit(findings, diagnostics, checked), args.output)
    else:
        console = out
        handle = None
        if args.output:
            handle = open(args.output, "w", encoding="utf-8")  # noqa: SIM115
            console = Console(file=handle, soft_wrap=True, no_color=True)
        try:
            _print_text(findings, diagnostics, console, getattr(args, 'verbose', True))
            if getattr(args, "verbose", False):
                _print_seconds(seconds, console)
        finally:
            if handle:
                handle.close()
    return _exit_code(findings, diagnostics, args.fail_on)


def _print_text(findings: list[Finding], diagnostics: list[Diagnostic],
                console: Console, verbose: bool = True) -> None:
    from ..report.findings import count, print_findings
    from ..report.text import count_by_severity, print_diagnostics

    if diagnostics:
        console.print("[bold]Diagnostics[/bold] (problems reading the workspace)",
                      highlight=False)
        print_diagnostics(diagnostics, console, verbose)
        console.print()
    print_findings(findings, console, verbose)
    counts = count(findings)
    diag_counts = count_by_severity(diagnostics)
    console.print(", ".join(f"{n} {k}(s)" for k, n in counts.items())
                  + f" from {len(load_catalogue())} shipped queries; "
                  + ", ".join(f"{n} {k}(s)" for k, n in diag_counts.items())
                  + " in diagnostics", highlight=False)


def _print_seconds(seconds: dict[str, float], console: Console) -> None:
    """Each rule's time, slowest first (``check -v``)."""
    console.print(f"queries: {sum(seconds.values()):.2f} s; "
                  + ", ".join(f"{rule} {spent:.3f} s" for rule, spent in sorted(
                      seconds.items(), key=lambda kv: -kv[1])), highlight=False)


def _exit_code(findings: list[Finding], diagnostics: list[Diagnostic], fail_on: str) -> int:
    if fail_on == "never":
        return EXIT_OK
    threshold = SEVERITY_RANK[fail_on]
    severities = [f.severity for f in findings] + [d.severity for d in diagnostics]
    return EXIT_FINDINGS if any(SEVERITY_RANK[s] >= threshold for s in severities) else EXIT_OK


def query(args: Any, out: Console, err: Console, analyse: Analyse) -> int:
    """Evaluate one expression and print its matches with their locations."""
    try:
        compiled = compile(args.expression)
    except QueryError as error:
        err.print(escape(str(error)), highlight=False)
        return EXIT_USAGE
    if args.model:
        from ..model.load import ModelDataError, from_data

        try:
            with open(args.model, encoding="utf-8") as handle:
                model = from_data(json.load(handle))
        except (OSError, ValueError, RecursionError, ModelDataError) as error:
            err.print(f"haros-arch: cannot read model {args.model}: {error}", highlight=False)
            return EXIT_USAGE
    elif args.project:
        loaded = analyse(args.project, err)
        if loaded is None:
            return EXIT_USAGE
        model = loaded
    else:
        err.print("haros-arch: query needs a PROJECT file or --model FILE", highlight=False)
        return EXIT_USAGE
    scopes: list[tuple[str | None, dict[str, Any]]]
    if args.config:
        config = model.configuration(args.config)
        if config is None:
            names = ", ".join(c.name for c in model.configurations) or "none"
            err.print(f"haros-arch: no configuration {args.config} (have: {names})",
                      highlight=False)
            return EXIT_USAGE
        scopes = [(config.name, config_scope(config, model))]
    elif compiled.names & CONFIG_NAMES:
        scopes = [(c.name, config_scope(c, model)) for c in model.configurations]
    else:
        scopes = [(None, model_scope(model))]
    results: list[dict[str, Any]] = []
    try:
        for name, scope in scopes:
            for match in compiled.run(scope):
                results.append({"configuration": name, "match": match})
    except QueryError as error:
        err.print(escape(str(error)), highlight=False)
        return EXIT_USAGE
    if args.format == "json":
        data = [{"configuration": r["configuration"], "value": plain(r["match"]),
                 "locations": [str(location_of(e)) for e in entities(r["match"])
                               if location_of(e).file]} for r in results]
        out.print(json.dumps(data, indent=2), highlight=False, markup=False, soft_wrap=True)
        return EXIT_OK
    for result in results:
        prefix = f"[{result['configuration']}] " if result["configuration"] else ""
        involved = entities(result["match"])
        text = "; ".join(label(e) for e in involved) if involved else str(
            plain(result["match"]))
        places = sorted({str(location_of(e)) for e in involved if location_of(e).file})
        out.print(escape(prefix + text), highlight=False)
        for place in places:
            out.print(f"    {escape(place)}", highlight=False)
    out.print(f"{len(results)} match(es)", highlight=False)
    return EXIT_OK


def project_file_of(path: str) -> Project | None:
    return open_project(path) if os.path.exists(path) else None


def extract_document(model: Model, project_path: str) -> str:
    """``extract``'s JSON: the model plus the catalogue's findings under ``findings``."""
    try:
        project: Project | None = open_project(project_path)
    except ProjectError:
        project = None
    return json.dumps(document(model, project), indent=2, ensure_ascii=False) + "\n"
