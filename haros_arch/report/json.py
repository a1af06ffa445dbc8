"""JSON of the ``extract``, ``check`` and ``query`` commands' results."""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Any

from ..model.serialise import json_text, to_data

if TYPE_CHECKING:
    from ..model.model import Model
    from ..project import Project
    from ..query.command import Checked, Match


def document_json(data: dict[str, Any]) -> str:
    """``extract``'s JSON model (with its ``findings``), as written to a file."""
    return json_text(data, indent=2, ensure_ascii=False) + "\n"


def document_text(model: Model, project: Project | None) -> str:
    """``document_json`` of ``model``: read back when the same unchanged run wrote it
    before with the same findings (``runcache.document``; the model's document is then
    not even made), else made."""
    from .. import runcache
    from ..query.catalogue import run_catalogue
    from ..query.command import document

    findings = to_data(run_catalogue(model, project))
    return runcache.document(model, json.dumps(findings, sort_keys=True, default=str),
                             lambda: document_json(document(model, project)))


def check_json(checked: Checked) -> str:
    return json_text({"diagnostics": to_data(checked.diagnostics),
                      "findings": to_data(checked.findings)}, indent=2) + "\n"


def matches_json(matches: list[Match]) -> str:
    from ..query.results import entities, location_of, plain

    data = [{"configuration": m.configuration, "value": plain(m.value),
             "locations": [str(location_of(e)) for e in entities(m.value)
                           if location_of(e).file]} for m in matches]
    return json_text(data, indent=2)
