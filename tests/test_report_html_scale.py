"""The HTML report of a big configuration, in headless Chromium: it opens with its
namespaces collapsed into boxes that count what they hold, opening one lays out its
content, long edges run between vertices, and dimmed edges have dimmed arrowheads.

The model comes from bench/report_scale.py's generator (robots of ten nodes, each in its
own namespace), at a third of the benchmark's size.
"""

from __future__ import annotations

import importlib.util
from collections import Counter
from collections.abc import Iterator
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

KINDS = (("node", "nodes"), ("topic", "topics"), ("service", "services"),
         ("parameter", "parameters"))


@pytest.fixture(scope="module")
def fleet(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    model = report_scale.scale_model(100, 330)
    config = model["configurations"][0]
    topic = config["topics"][0]
    finding = {"rule": "probe", "severity": "warning", "title": "probe", "message": "m",
               "configuration": config["name"],
               "entities": [topic["id"], "node:" + topic["publishers"][0]],
               "location": {"file": None, "line": 0}}
    path = tmp_path_factory.mktemp("scale") / "fleet.html"
    write_report(model, [finding], str(path.parent), str(path))
    return {"path": path, "config": config, "finding": finding}


@pytest.fixture
def page(browser: Any, fleet: dict[str, Any]) -> Iterator[Watched]:  # noqa: F811
    watched = Watched(browser, fleet["path"])
    yield watched
    assert watched.problems == []
    watched.page.close()


def namespace_of(kind: str, name: str) -> str:
    return "/" + name.split("/")[1] + "/"


def counts(config: dict[str, Any]) -> dict[str, Counter[str]]:
    """What each namespace holds, by kind, as the model says."""
    held: dict[str, Counter[str]] = {}
    for kind, key in KINDS:
        for item in config[key]:
            held.setdefault(namespace_of(kind, item["name"]), Counter())[kind] += 1
    return held


def said(count: Counter[str], *kinds: str) -> str:
    """'10 nodes · 1 topic': the kinds present, singular for one."""
    return " \u00b7 ".join(f"{count[k]} {k}{'s' if count[k] > 1 else ''}"
                            for k in kinds if count[k])


def test_a_big_configuration_opens_with_namespaces_collapsed(page: Watched, fleet) -> None:
    held = counts(fleet["config"])
    assert page.ids("#graph .vertex") == {f"namespace:{name}" for name in held}
    hint = page.page.inner_text("#hint")
    assert "Click a namespace to open it" in hint
    assert page.page.is_hidden("#legend svg")  # folded, not over the boxes
    page.page.click("#legend-fold")
    assert page.page.is_visible("#legend svg")
    assert f"{len(held)} namespaces" in hint
    for name, count in held.items():
        text = page.page.text_content(f'#graph .vertex[data-id="namespace:{name}"]')
        assert name in text
        assert said(count, "node", "topic") in text
        assert said(count, "service", "parameter") in text


def test_edges_between_boxes_count_their_links(page: Watched, fleet) -> None:
    config = fleet["config"]
    resource_space = {item["name"]: namespace_of("", item["name"])
                      for key in ("topics", "services", "parameters") for item in config[key]}
    into_node = {"subscribe", "server", "read"}
    between: Counter[tuple[str, str]] = Counter()
    for link in config["links"]:
        node, resource = namespace_of("", link["node"]), resource_space[link["name"]]
        if node != resource:
            between[(resource, node) if link["kind"] in into_node else (node, resource)] += 1
    edges = page.page.eval_on_selector_all("#graph .edge", """els => els.map(e => [
        e.getAttribute('data-source'), e.getAttribute('data-target'), e.textContent])""")
    assert len(edges) == len(between)
    for source, target, title in edges:
        a, b = source.removeprefix("namespace:"), target.removeprefix("namespace:")
        n = between[(a, b)]
        assert title.startswith(f"{n} link{'s' if n > 1 else ''} from {a} to {b}")


def test_clicking_a_namespace_opens_it_and_leaves_the_rest_collapsed(page: Watched,
                                                                     fleet) -> None:
    held = counts(fleet["config"])
    first, *others = sorted(held)
    page.page.click(f'#graph .vertex[data-id="namespace:{first}"]')
    drawn = page.ids("#graph .vertex")
    inside = {item["id"] for kind, key in KINDS for item in fleet["config"][key]
              if namespace_of(kind, item["name"]) == first}
    assert inside <= drawn
    assert drawn - inside == {f"namespace:{name}" for name in others}
    assert not page.page.is_checked(f'input[data-namespace="{first}"]')
    page.page.click("#open-all")
    assert not any(i.startswith("namespace:") for i in page.ids("#graph .vertex"))
    assert page.page.is_hidden("#hint")


def test_search_enter_opens_the_namespace_of_the_name(page: Watched, fleet) -> None:
    node = fleet["config"]["nodes"][42]
    page.page.fill("#search", node["name"])
    page.page.press("#search", "Enter")
    assert page.ids("#graph .vertex.selected") == {node["id"]}
    assert f"namespace:{node['namespace']}" not in page.ids("#graph .vertex")
    assert node["name"] in page.page.inner_text("#panel")


def test_long_edges_inside_a_namespace_go_around_vertices(page: Watched, fleet) -> None:
    name = sorted(counts(fleet["config"]))[1]
    page.page.click(f'#graph .vertex[data-id="namespace:{name}"]')
    report = page.page.evaluate(CROSSINGS, name)
    assert report["bent"] > 0  # some edges span several layers and have dummy points
    assert report["crossing"] == []


# For every edge with both ends in the namespace: points along its path that fall inside
# a vertex other than its own ends, and how many paths have more than one segment.
CROSSINGS = """name => {
  const boxes = [...document.querySelectorAll('#graph .vertex')].map(g => {
    const m = g.getAttribute('transform').match(/translate\\(([-\\d.e]+),([-\\d.e]+)\\)/);
    const b = g.querySelector('.shape').getBBox();
    return {id: g.getAttribute('data-id'), x0: +m[1] + b.x + 2, x1: +m[1] + b.x + b.width - 2,
            y0: +m[2] + b.y + 2, y1: +m[2] + b.y + b.height - 2};
  });
  const within = id => id.includes(':' + name);
  const crossing = [];
  let bent = 0;
  for (const e of document.querySelectorAll('#graph .edge')) {
    const s = e.getAttribute('data-source'), t = e.getAttribute('data-target');
    if (!within(s) || !within(t)) continue;
    if ((e.getAttribute('d').match(/C/g) || []).length > 1) bent++;
    const length = e.getTotalLength();
    for (let i = 1; i < 40; i++) {
      const p = e.getPointAtLength(length * i / 40);
      const hit = boxes.find(b => b.id !== s && b.id !== t &&
                             p.x > b.x0 && p.x < b.x1 && p.y > b.y0 && p.y < b.y1);
      if (hit) { crossing.push([s, t, hit.id]); break; }
    }
  }
  return {bent, crossing};
}"""


def test_dimmed_edges_have_dimmed_arrowheads(page: Watched, fleet) -> None:
    name = namespace_of("", fleet["config"]["topics"][0]["name"])
    page.page.click(f'#graph .vertex[data-id="namespace:{name}"]')
    page.page.click("#findings .item")
    markers = page.page.eval_on_selector_all("#graph .edge", """els => els.map(e =>
        [e.classList.contains('hl'), getComputedStyle(e).markerEnd])""")
    lit = [marker for hl, marker in markers if hl]
    dim = [marker for hl, marker in markers if not hl]
    assert lit and dim
    assert all("-dim" not in marker for marker in lit)
    assert all("-dim" in marker for marker in dim)
    opacity = page.page.eval_on_selector(
        "#arrow-topic-dim path", "p => getComputedStyle(p).fillOpacity")
    assert float(opacity) < 0.5


def test_small_configurations_open_expanded(browser: Any, tmp_path: Path) -> None:  # noqa: F811
    model = report_scale.scale_model(10, 10)
    path = tmp_path / "small.html"
    write_report(model, [], str(tmp_path), str(path))
    watched = Watched(browser, path)
    assert not any(i.startswith("namespace:") for i in watched.ids("#graph .vertex"))
    assert watched.page.is_hidden("#hint")
    assert watched.page.is_visible("#legend svg")
    assert watched.problems == []
