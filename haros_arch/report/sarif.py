"""SARIF 2.1.0: one run, one rule per catalogue id, one result per finding or diagnostic.

Locations are relative to the workspace root, given as ``originalUriBaseIds`` so that
code-scanning UIs point at the source line; a file of a later workspace folder (absolute
in the model) is a ``file:`` URI of its own.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import Any

from .. import __version__
from ..model.diagnostic import Diagnostic
from ..model.finding import Finding
from ..model.location import Location
from ..model.serialise import json_text

SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
LEVELS = {"error": "error", "warning": "warning", "info": "note"}
ROOT = "WORKSPACE"


def _location(where: Location, message: str | None = None) -> dict[str, Any]:
    # a file beyond the first workspace folder is absolute in the model: its own URI
    file = where.file or ""
    artifact = ({"uri": Path(file).as_uri()} if Path(file).is_absolute()
                else {"uri": where.file, "uriBaseId": ROOT})
    physical: dict[str, Any] = {"artifactLocation": artifact}
    if where.line > 0:
        region: dict[str, Any] = {"startLine": where.line}
        if where.column > 0:
            region["startColumn"] = where.column
        physical["region"] = region
    location: dict[str, Any] = {"physicalLocation": physical}
    if message:
        location["message"] = {"text": message}
    return location


def to_sarif(findings: Iterable[Finding], diagnostics: Iterable[Diagnostic] = (),
             rules: dict[str, tuple[str, str]] | None = None,
             workspace: str | None = None) -> dict[str, Any]:
    """The SARIF log; ``rules`` maps ids to (title, description) for ``tool.driver``."""
    rules = dict(rules or {})
    results: list[dict[str, Any]] = []
    for finding in findings:
        result: dict[str, Any] = {
            "ruleId": finding.rule, "level": LEVELS[finding.severity],
            "message": {"text": f"{finding.title}: {finding.message}"},
            "properties": {"entities": list(finding.entities),
                           "configuration": finding.configuration,
                           "configurations": list(finding.configurations)},
        }
        if finding.location.file:
            result["locations"] = [_location(finding.location)]
        _related(result, finding.also)
        rules.setdefault(finding.rule, (finding.title, ""))
        results.append(result)
    for diagnostic in diagnostics:
        result = {"ruleId": diagnostic.code, "level": LEVELS[diagnostic.severity],
                  "message": {"text": diagnostic.message}}
        if diagnostic.location.file:
            result["locations"] = [_location(diagnostic.location)]
        _related(result, diagnostic.also)
        rules.setdefault(diagnostic.code, (diagnostic.code, ""))
        results.append(result)
    run: dict[str, Any] = {
        "tool": {"driver": {
            "name": "haros-arch", "version": __version__, "informationUri":
            "https://pypi.org/project/haros-arch/",
            "rules": [{"id": rule_id, "shortDescription": {"text": title},
                       **({"fullDescription": {"text": text}} if text else {})}
                      for rule_id, (title, text) in sorted(rules.items())]}},
        "results": results,
    }
    if workspace:
        run["originalUriBaseIds"] = {ROOT: {"uri": Path(workspace).resolve().as_uri() + "/"}}
    return {"$schema": SCHEMA, "version": "2.1.0", "runs": [run]}


def _related(result: dict[str, Any], also: tuple[Location, ...]) -> None:
    """The other places of a result's problem (``also``), as its related locations."""
    related = [_location(where, "the same problem") for where in also if where.file]
    if related:
        result["relatedLocations"] = [{"id": i + 1, **place}
                                      for i, place in enumerate(related)]


def dumps(*args: Any, **kwargs: Any) -> str:
    return json_text(to_sarif(*args, **kwargs), indent=2) + "\n"
