"""The ``check`` and ``query`` commands' work as library calls returning results.

Nothing here prints: the CLI picks a reporter (``haros_arch/report``) for the results.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from .. import runcache
from ..model.diagnostic import SEVERITY_RANK, Diagnostic
from ..model.finding import Finding
from ..model.model import Model
from ..model.serialise import to_data
from ..project import Project
from . import CONFIG_NAMES, Query, config_scope, model_scope
from .catalogue import Rule, absorbed, load_catalogue, project_rules, run_catalogue

EXIT_OK, EXIT_FINDINGS, EXIT_USAGE = 0, 1, 2


def document(model: Model, project: Project | None) -> dict[str, Any]:
    """The JSON model with a top-level ``findings`` list (what ``extract`` writes)."""
    from ..runcache import model_data

    data = model_data(model)
    data["findings"] = to_data(run_catalogue(model, project))
    return data


@dataclass
class Checked:
    """What ``check`` found: the catalogue's findings, the diagnostics no rule reports,
    the rules that ran (shipped and the project's) and each rule's time in seconds."""

    findings: list[Finding]
    diagnostics: list[Diagnostic]
    rules: list[Rule]
    shipped: int
    seconds: dict[str, float] = field(default_factory=dict)

    def exit_code(self, fail_on: str) -> int:
        return _exit_code(self.findings, self.diagnostics, fail_on)


def check(model: Model, project: Project) -> Checked:
    """Run the query catalogue and the project's rules over ``model``."""
    seconds: dict[str, float] = {}
    findings = run_catalogue(model, project, seconds=seconds)
    def unsaid() -> list[Diagnostic]:
        said = absorbed(model)  # what catalogue rules report as findings
        return [d for d in model.all_diagnostics if d not in said]

    diagnostics = runcache.diagnostics(model, unsaid)  # a kept run's, read back
    shipped = load_catalogue()
    return Checked(findings, diagnostics, [*shipped, *project_rules(project)],
                   len(shipped), seconds)


def _exit_code(findings: list[Finding], diagnostics: list[Diagnostic], fail_on: str) -> int:
    if fail_on == "never":
        return EXIT_OK
    threshold = SEVERITY_RANK[fail_on]
    severities = [f.severity for f in findings] + [d.severity for d in diagnostics]
    return EXIT_FINDINGS if any(SEVERITY_RANK[s] >= threshold for s in severities) else EXIT_OK


class NoConfiguration(Exception):
    """``query --config NAME`` names no configuration of the model."""


@dataclass
class Match:
    configuration: str | None  # None: the query ran over the whole model
    value: Any


def query(model: Model, compiled: Query, config: str | None = None) -> list[Match]:
    """The matches of ``compiled`` in one configuration, in each (when it uses their
    names) or over the model. QueryError when it fails; NoConfiguration for a bad name."""
    scopes: list[tuple[str | None, dict[str, Any]]]
    if config:
        found = model.configuration(config)
        if found is None:
            names = ", ".join(c.name for c in model.configurations) or "none"
            raise NoConfiguration(f"no configuration {config} (have: {names})")
        scopes = [(found.name, config_scope(found, model))]
    elif compiled.names & CONFIG_NAMES:
        scopes = [(c.name, config_scope(c, model)) for c in model.configurations]
    else:
        scopes = [(None, model_scope(model))]
    return [Match(name, match) for name, scope in scopes for match in compiled.run(scope)]
