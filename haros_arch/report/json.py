"""JSON of the ``extract``, ``check`` and ``query`` commands' results."""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Any

from ..model.serialise import to_data

if TYPE_CHECKING:
    from ..query.command import Checked, Match


def document_json(data: dict[str, Any]) -> str:
    """``extract``'s JSON model (with its ``findings``), as written to a file."""
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


def check_json(checked: Checked) -> str:
    return json.dumps({"diagnostics": to_data(checked.diagnostics),
                       "findings": to_data(checked.findings)}, indent=2) + "\n"


def matches_json(matches: list[Match]) -> str:
    from ..query.results import entities, location_of, plain

    data = [{"configuration": m.configuration, "value": plain(m.value),
             "locations": [str(location_of(e)) for e in entities(m.value)
                           if location_of(e).file]} for m in matches]
    return json.dumps(data, indent=2)
