"""What ``haros-arch report`` does, as library calls: model from a project or a saved file."""

from __future__ import annotations

import json
import os
from typing import Any

from .. import SCHEMA
from ..model.model import Model
from ..model.serialise import to_data
from ..project import Project
from .html import ReportError


def read_model(path: str) -> dict[str, Any]:
    """A saved ``haros-arch extract`` document; ReportError if it is not one."""
    try:
        with open(path, encoding="utf-8") as handle:
            data = json.load(handle)
    except OSError as err:
        raise ReportError(f"cannot read {path}: {err.strerror or err}") from err
    except (ValueError, RecursionError) as err:
        raise ReportError(f"{path} is not JSON (or nested too deeply): {err}") from err
    if not isinstance(data, dict) or not isinstance(data.get("configurations"), list):
        raise ReportError(f"{path} is not a haros-arch model (schema {SCHEMA})")
    return data


def project_findings(model: Model, project: Project) -> list[Any]:
    """The findings of the query catalogue and the project's queries, once queries exist."""
    try:
        from ..query import run_catalogue

        return [to_data(f) for f in run_catalogue(model, project)]
    except ImportError:  # the catalogue has not landed in this checkout
        return []


def model_data(model: Model) -> dict[str, Any]:
    from ..runcache import model_data as data_of

    return data_of(model)


def workspace_root(project: Project | None, given: str | None) -> list[str]:
    """The folders whose files the report quotes, the first where the model's relative
    file paths start: --workspace, the project's (files of its later folders are
    absolute in the model), or here."""
    if given:
        return [given]
    if project is not None and project.workspace:
        return list(project.workspace)
    return [os.getcwd()]


def report_page(model: Model, findings: list[Any], root: list[str], project: Project) -> str:
    """The report page of an analysed ``model``: read back when the same unchanged run
    rendered it before with the same findings and workspace root (``runcache.page``; the
    model's document is then not even made), else rendered. Only a root inside the
    project's workspace is covered by the run's key (the page quotes its sources), so any
    other is rendered."""
    from .. import runcache
    from .html import render_report

    full = [os.path.abspath(folder) for folder in root]
    tops = [os.path.abspath(os.path.join(project.folder, w)) for w in project.workspace]
    if not all(any(folder == top or folder.startswith(top.rstrip(os.sep) + os.sep)
                   for top in tops) for folder in full):
        return render_report(model_data(model), findings, root)
    inputs = json.dumps([full[0] if len(full) == 1 else full, findings], sort_keys=True,
                        default=str)
    return runcache.page(model, inputs,
                         lambda: render_report(model_data(model), findings, root))
