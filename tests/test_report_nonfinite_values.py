"""A value that is no number JSON has (a parameter's default of infinity, as
ros2_controllers' joint_trajectory_controller model declares its tolerances; NaN) is
written as the string "Infinity" / "-Infinity" / "NaN" in everything haros-arch writes
as JSON. Python's bare ``Infinity`` made the report's embedded data invalid for the
browser's JSON.parse: the page of every configuration starting that controller (MoveIt's
panda demo) was blank."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from test_report_html_browser import REASON, Watched, browser  # noqa: F401 (fixture)

from haros_arch.model.serialise import json_text
from haros_arch.viz import write_report


def _strict(text: str) -> Any:
    def refuse(word: str) -> Any:
        raise ValueError(f"not JSON: {word}")
    return json.loads(text, parse_constant=refuse)


def _model() -> dict[str, Any]:
    where = {"package": "p", "file": "p/src/controller.cpp", "line": 3, "column": 1}
    names = {"/controller/constraints.goal_time": float("inf"),
             "/controller/constraints.lower": float("-inf"),
             "/controller/constraints.unset": float("nan")}
    config = {
        "name": "c", "launch": [], "args": {}, "diagnostics": [], "services": [],
        "actions": [], "topics": [],
        "nodes": [{"name": "/controller", "id": "node:/controller", "node": "p/controller",
                   "namespace": "/", "remaps": [], "args": "", "conditions": [],
                   "location": where}],
        "parameters": [{"name": n, "id": f"parameter:{n}", "type": "double", "value": v,
                        "readers": ["/controller"], "writers": [], "conditions": []}
                       for n, v in names.items()],
        "links": [{"kind": "read", "node": "/controller", "name": n, "given": n,
                   "type": "double", "default": v, "queue_size": None, "qos": None,
                   "conditions": [], "location": where} for n, v in names.items()]}
    return {"schema": "haros-arch/1", "project": "p", "packages": [], "diagnostics": [],
            "configurations": [config]}


def test_json_text_writes_what_json_has_no_number_for_as_text() -> None:
    data = {"a": [1.5, float("inf"), {"b": float("-inf")}], "c": (float("nan"),), "d": "x"}
    assert _strict(json_text(data)) == {"a": [1.5, "Infinity", {"b": "-Infinity"}],
                                        "c": ["NaN"], "d": "x"}
    assert json_text({"plain": 1.0}, indent=2) == json.dumps({"plain": 1.0}, indent=2)


@pytest.mark.skipif(REASON is not None, reason=REASON or "")
def test_a_report_with_an_infinite_default_opens(browser: Any,  # noqa: F811
                                                 tmp_path: Path) -> None:
    path = tmp_path / "report.html"
    write_report(_model(), [], str(tmp_path), str(path))
    watched = Watched(browser, path)
    assert "node:/controller" in watched.ids("#graph .vertex")
    assert watched.problems == []
