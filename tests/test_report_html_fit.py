"""The report's views fit what they show. The first view of a configuration shows all of
its graph: every vertex and every edge inside the stage and below the hint, long edges of
the layered layout too (dingo's twist_mux -> /diagnostics ran above every vertex, under the
hint, out of sight); the package view's tables fit the view.
In headless Chromium, on models of bench/report_scale.py's generator and a pipeline."""

from __future__ import annotations

import importlib.util
from pathlib import Path
from typing import Any

import pytest
from conftest import ROOT
from test_report_html_browser import REASON, Watched, browser  # noqa: F401 (fixture)

from haros_arch.viz import write_report

pytestmark = pytest.mark.skipif(REASON is not None, reason=REASON or "")

_spec = importlib.util.spec_from_file_location("report_scale", ROOT / "bench" / "report_scale.py")
assert _spec and _spec.loader
report_scale = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(report_scale)

WHERE = {"package": "demo", "file": "demo/src/node.cpp", "line": 3, "column": 1}


def pipeline_model(stages: int) -> dict[str, Any]:
    """A pipeline of ``stages`` nodes (/s0 -> /t0 -> /s1 -> ...), each node also reading
    a parameter, and the first node publishing /diagnostics, which the last one also
    publishes: an edge from the first layer to the last."""
    nodes = [f"/s{i}" for i in range(stages)]
    pubs = {f"/t{i}": [nodes[i]] for i in range(stages - 1)}
    subs = {f"/t{i}": [nodes[i + 1]] for i in range(stages - 1)}
    pubs["/diagnostics"], subs["/diagnostics"] = [nodes[0], nodes[-1]], []
    links = [{"kind": kind, "node": n, "name": t, "given": t, "type": "std_msgs/String",
              "queue_size": 10, "qos": None, "conditions": [], "location": WHERE}
             for t in pubs for kind, users in (("publish", pubs[t]), ("subscribe", subs[t]))
             for n in users]
    params = [{"name": f"{n}/rate", "id": f"parameter:{n}/rate", "type": "double",
               "value": 1.0, "readers": [n], "writers": ["<launch>"], "conditions": []}
              for n in nodes]
    links += [{"kind": "read", "node": n, "name": f"{n}/rate", "given": "~rate",
               "type": "double", "queue_size": None, "qos": None, "conditions": [],
               "location": WHERE} for n in nodes]
    config = {
        "name": "pipeline", "launch": ["demo/launch/demo.launch"], "args": {},
        "nodes": [{"name": n, "id": f"node:{n}", "node": "demo/node", "namespace": "/",
                   "remaps": [], "args": "", "conditions": [], "location": WHERE}
                  for n in nodes],
        "topics": [{"name": t, "id": f"topic:{t}", "types": ["std_msgs/String"],
                    "publishers": pubs[t], "subscribers": subs[t], "conditions": []}
                   for t in pubs],
        "services": [], "actions": [], "parameters": params, "links": links,
        "diagnostics": []}
    return {"schema": "haros-arch/1", "project": "demo", "packages": [], "diagnostics": [],
            "configurations": [config]}


MODELS = {
    "pipeline": lambda: pipeline_model(6),
    # small flat ones whose layered layout runs a long edge above every vertex
    "flat-2": lambda: report_scale.scale_model(10, 20, seed=2, shape="flat"),
    "flat-4": lambda: report_scale.scale_model(10, 20, seed=4, shape="flat"),
    "flat": lambda: report_scale.scale_model(30, 60, shape="flat"),
    "nested": lambda: report_scale.scale_model(30, 60, shape="nested"),
    "robots": lambda: report_scale.scale_model(40, 90, seed=3),
}


@pytest.mark.parametrize("name", sorted(MODELS))
def test_the_first_view_shows_every_vertex_and_edge(browser: Any, tmp_path: Path,  # noqa: F811
                                                      name: str) -> None:
    path = tmp_path / "report.html"
    write_report(MODELS[name](), [], str(tmp_path), str(path))
    watched = Watched(browser, path)
    outside = watched.page.evaluate("""() => {
      const stage = document.querySelector('svg#graph').getBoundingClientRect();
      const hint = document.querySelector('#hint');
      const top = hint.hidden ? stage.top : hint.getBoundingClientRect().bottom;
      const out = [];
      for (const e of document.querySelectorAll('#graph .vertex, #graph .edge')) {
        const r = e.getBoundingClientRect();
        if (r.top < top - 1 || r.left < stage.left - 1 || r.right > stage.right + 1)
          out.push([e.getAttribute('data-id') || e.getAttribute('data-source') + ' -> ' +
                    e.getAttribute('data-target'), Math.round(r.top), Math.round(top)]);
      }
      return out;
    }""")
    assert outside == []
    assert watched.problems == []
    watched.page.close()


def test_the_package_view_fits_long_names_types_and_paths(browser: Any,  # noqa: F811
                                                          tmp_path: Path) -> None:
    """A node's interface table wraps its long names, types and file paths between their
    parts ('/', '_') and stays inside the package view (the 'where' column of
    robot_localization's ekf node ran under the side panel)."""
    model = pipeline_model(3)
    long_file = "include/a_rather_long_package_name/a_rather_long_file_name_of_a_filter.h"
    where = {"package": "demo", "file": long_file, "line": 755, "column": 5}
    calls = [{"kind": kind, "name": f"~a_long_parameter_name_of_the_filter_{i}",
              "type": "diagnostic_msgs/DiagnosticArrayOfAVeryLongName", "conditions": [],
              "location": where} for i, kind in enumerate(("publish", "read", "subscribe"))]
    model["packages"] = [{"name": "demo", "build_type": "catkin", "path": "demo", "nodes": [
        {"package": "demo", "executable": "node", "kind": "executable", "language": "cpp",
         "sources": [long_file], "calls": calls}]}]
    path = tmp_path / "report.html"
    write_report(model, [], str(tmp_path), str(path))
    watched = Watched(browser, path)
    watched.page.click("#tab-packages")
    sizes = watched.page.evaluate("""() => {
      const pane = document.querySelector('#packages');
      const table = pane.querySelector('table.calls');
      return [pane.scrollWidth, pane.clientWidth, table.textContent];
    }""")
    assert sizes[0] <= sizes[1]
    assert long_file + ":755:5" in sizes[2]  # the text itself unchanged
    assert watched.problems == []
    watched.page.close()
