"""Nested namespace boxes in the HTML report, in headless Chromium: robots with sensors/,
base/ and arm/ inside, and a flat system grouped by the first word of its names.

Models from bench/report_scale.py's generator, small: six robots of ten nodes, each
robot's nodes in three sub-namespaces, topics named where their publisher is.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from test_report_html_browser import REASON, Watched, browser  # noqa: F401 (fixture)
from test_report_html_scale import report_scale

from haros_arch.viz import write_report

pytestmark = pytest.mark.skipif(REASON is not None, reason=REASON or "")


@pytest.fixture(scope="module")
def nested(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    model = report_scale.scale_model(60, 150, shape="nested")
    path = tmp_path_factory.mktemp("nested") / "nested.html"
    write_report(model, [], str(path.parent), str(path))
    return {"path": path, "config": model["configurations"][0]}


@pytest.fixture
def page(browser: Any, nested: dict[str, Any]) -> Iterator[Watched]:  # noqa: F811
    watched = Watched(browser, nested["path"])
    yield watched
    assert watched.problems == []
    watched.page.close()


# Drawn vertices and open boxes with their extent; edges with their ends and a sample of
# points along their path.
GEOMETRY = """() => {
  const vertices = {};
  for (const g of document.querySelectorAll('#graph .vertex')) {
    const m = g.getAttribute('transform').match(/translate\\(([-\\d.e]+),([-\\d.e]+)\\)/);
    const b = g.querySelector('.shape').getBBox();
    const x = +m[1], y = +m[2];
    vertices[g.getAttribute('data-id')] = {x, y, x0: x + b.x, x1: x + b.x + b.width,
                                          y0: y + b.y, y1: y + b.y + b.height};
  }
  const boxes = {};
  for (const g of document.querySelectorAll('#graph .group')) {
    const r = g.querySelector('rect');
    const x = +r.getAttribute('x'), y = +r.getAttribute('y');
    boxes[g.getAttribute('data-group')] = {x0: x, y0: y, x1: x + +r.getAttribute('width'),
                                           y1: y + +r.getAttribute('height')};
  }
  const edges = [...document.querySelectorAll('#graph .edge')].map(e => {
    const length = e.getTotalLength(), points = [];
    for (let i = 0; i <= 40; i++) {
      const p = e.getPointAtLength(length * i / 40);
      points.push([p.x, p.y]);
    }
    return {source: e.getAttribute('data-source'), target: e.getAttribute('data-target'), points};
  });
  return {vertices, boxes, edges};
}"""


def inside(point: list[float], box: dict[str, float], margin: float = 0) -> bool:
    x, y = point
    return (box["x0"] + margin < x < box["x1"] - margin
            and box["y0"] + margin < y < box["y1"] - margin)


def within(inner: dict[str, float], outer: dict[str, float]) -> bool:
    return (outer["x0"] <= inner["x0"] and inner["x1"] <= outer["x1"]
            and outer["y0"] <= inner["y0"] and inner["y1"] <= outer["y1"])


def test_a_big_nested_configuration_opens_at_a_readable_level(page: Watched) -> None:
    shape = page.page.evaluate(GEOMETRY)
    robots = [f"/robot{i}/" for i in range(6)]
    assert set(shape["boxes"]) == set(robots)  # the robots are open boxes ...
    expected = {f"namespace:{r}{part}/" for r in robots for part in ("sensors", "base", "arm")}
    assert set(shape["vertices"]) == expected  # ... holding their collapsed parts
    for name in expected:
        robot = "/" + name.split("/")[1] + "/"
        assert within(shape["vertices"][name], shape["boxes"][robot])
    text = page.page.text_content('#graph .vertex[data-id="namespace:/robot1/base/"]')
    assert text.startswith("base/")  # labelled relative to its box
    assert "3 nodes" in text


def test_opening_and_closing_a_nested_box_moves_the_edge_ends(page: Watched,
                                                              nested: dict[str, Any]) -> None:
    config = nested["config"]
    node = next(n for n in config["nodes"] if n["namespace"] == "/robot1/base/")
    # A link from that node to a topic outside /robot1/base/ but inside /robot1/.
    topic = next(t for t in config["topics"] if node["name"] in t["publishers"]
                 and any(s.startswith("/robot1/arm/") for s in t["subscribers"]))
    before = page.page.evaluate(GEOMETRY)
    assert node["id"] not in before["vertices"]

    page.page.click('#graph .vertex[data-id="namespace:/robot1/base/"]')
    opened = page.page.evaluate(GEOMETRY)
    assert node["id"] in opened["vertices"] and topic["id"] in opened["vertices"]
    assert "namespace:/robot1/base/" not in opened["vertices"]
    assert within(opened["boxes"]["/robot1/base/"], opened["boxes"]["/robot1/"])
    edge = next(e for e in opened["edges"]
                if e["source"] == node["id"] and e["target"] == topic["id"])
    start, end = edge["points"][0], edge["points"][-1]
    assert inside(start, grow(opened["vertices"][node["id"]], 2))
    assert inside(end, grow(opened["vertices"][topic["id"]], 8))
    # The arm's subscriber is still in a collapsed box: the topic's edge ends on it.
    assert any(e["source"] == topic["id"] and e["target"] == "namespace:/robot1/arm/"
               for e in opened["edges"])

    page.page.click('#graph .group[data-group="/robot1/base/"] .group-label')
    closed = page.page.evaluate(GEOMETRY)
    assert node["id"] not in closed["vertices"] and "/robot1/base/" not in closed["boxes"]
    box = closed["vertices"]["namespace:/robot1/base/"]
    edge = next(e for e in closed["edges"] if e["source"] == "namespace:/robot1/base/")
    assert inside(edge["points"][0], grow(box, 2))


def test_opening_a_box_keeps_the_order_around_it(page: Watched) -> None:
    # Boxes in the same box keep their places relative to each other: left of / right of
    # when in different columns, above / below in the same column (rows of boxes in
    # name order when set out as a grid).
    def places(shape: dict[str, Any]) -> dict[tuple[str, str], str]:
        items = {**shape["vertices"], **{"namespace:" + k: v for k, v in shape["boxes"].items()}}
        centre = {k: ((v["x0"] + v["x1"]) / 2, (v["y0"] + v["y1"]) / 2) for k, v in items.items()}
        parent = {k: k.rsplit("/", 2)[0] for k in items}
        return {(a, b): ("left" if centre[a][0] < centre[b][0] - 1 else "right"
                         if centre[a][0] > centre[b][0] + 1 else "above"
                         if centre[a][1] < centre[b][1] else "below")
                for a in items for b in items if a < b and parent[a] == parent[b]
                and a.startswith("namespace:/robot1/") and a != "namespace:/robot1/"}

    def reading_order(shape: dict[str, Any]) -> list[str]:
        boxes = shape["boxes"]
        robots = [name for name in boxes if name.count("/") == 2]
        return sorted(robots, key=lambda n: (round(boxes[n]["y0"]), boxes[n]["x0"]))

    first = page.page.evaluate(GEOMETRY)
    page.page.click('#graph .vertex[data-id="namespace:/robot1/base/"]')
    then = page.page.evaluate(GEOMETRY)
    before, after = places(first), places(then)
    kept = set(before) & set(after)
    assert len(kept) >= 2
    assert {k: after[k] for k in kept} == {k: before[k] for k in kept}
    assert reading_order(then) == reading_order(first) == [f"/robot{i}/" for i in range(6)]


def test_edges_between_boxes_go_around_other_boxes(page: Watched) -> None:
    for part in ("sensors", "base", "arm"):  # from the sidebar: opened boxes fill the view
        page.page.uncheck(f'input[data-namespace="/robot3/{part}/"]')
    shape = page.page.evaluate(GEOMETRY)
    assert {"/robot3/sensors/", "/robot3/base/", "/robot3/arm/"} <= set(shape["boxes"])
    checked = 0
    for edge in shape["edges"]:
        ends = (edge["source"], edge["target"])
        if not all(":/robot3/" in end for end in ends):
            continue
        own = {name for name in shape["boxes"] if any(name in end for end in ends)}
        checked += 1
        for point in edge["points"][1:-1]:
            for name, box in shape["boxes"].items():
                if name not in own and name.startswith("/robot3/"):
                    assert not inside(point, box, 1), (edge["source"], edge["target"], name)
            for vid, v in shape["vertices"].items():
                if vid not in ends:
                    assert not inside(point, v, 2), (edge["source"], edge["target"], vid)
    assert checked > 20


def grow(box: dict[str, float], by: float) -> dict[str, float]:
    return {"x0": box["x0"] - by, "y0": box["y0"] - by, "x1": box["x1"] + by, "y1": box["y1"] + by}


def test_a_flat_big_namespace_is_grouped_by_first_word(browser: Any,  # noqa: F811
                                                       tmp_path: Path) -> None:
    model = report_scale.scale_model(100, 330, shape="flat")
    path = tmp_path / "flat.html"
    write_report(model, [], str(tmp_path), str(path))
    watched = Watched(browser, path)
    drawn = watched.ids("#graph .vertex")
    words = {n["name"][1:].split("_")[0] for n in model["configurations"][0]["nodes"]}
    assert drawn == {f"namespace:/{w}*" for w in words}
    assert "first word" in watched.page.inner_text("#hint")
    watched.page.click('#graph .vertex[data-id="namespace:/camera*"]')
    shown = watched.ids("#graph .vertex")
    assert "node:/camera_0_0" in shown and "topic:/camera/topic0" in shown
    assert watched.page.text_content('#graph .group[data-group="/camera*"]').startswith("/camera*")
    assert watched.problems == []


def test_many_private_parameters_are_one_box_collapsed_at_first(browser: Any,  # noqa: F811
                                                                 tmp_path: Path) -> None:
    where = {"package": "p", "file": "p/src/talker.cpp", "line": 3, "column": 1}
    names = [f"/talker/param{i}" for i in range(10)]

    def link(kind: str, node: str, name: str) -> dict[str, Any]:
        return {"kind": kind, "node": node, "name": name, "given": name, "type": "int",
                "queue_size": None, "qos": None, "conditions": [], "location": where}

    config = {
        "name": "c", "launch": [], "args": {}, "diagnostics": [], "services": [], "actions": [],
        "nodes": [{"name": n, "id": f"node:{n}", "node": "p/talker", "namespace": "/",
                   "remaps": [], "args": "", "conditions": [], "location": where}
                  for n in ("/talker", "/listener")],
        "topics": [{"name": "/chatter", "id": "topic:/chatter", "types": ["std_msgs/String"],
                    "publishers": ["/talker"], "subscribers": ["/listener"], "conditions": []}],
        "parameters": [{"name": n, "id": f"parameter:{n}", "type": "int", "value": 1,
                        "readers": ["/talker"], "writers": [], "conditions": []} for n in names],
        "links": [link("publish", "/talker", "/chatter"),
                  link("subscribe", "/listener", "/chatter"),
                  *(link("read", "/talker", n) for n in names)]}
    model = {"schema": "haros-arch/1", "project": "p", "packages": [], "diagnostics": [],
             "configurations": [config]}
    path = tmp_path / "params.html"
    write_report(model, [], str(tmp_path), str(path))
    watched = Watched(browser, path)
    assert watched.ids("#graph .vertex") == {"node:/talker", "node:/listener", "topic:/chatter",
                                             "namespace:/talker/"}
    assert "10 parameters" in watched.page.text_content(watched.vertex("namespace:/talker/"))
    watched.page.click(watched.vertex("namespace:/talker/"))
    assert {f"parameter:{n}" for n in names} <= watched.ids("#graph .vertex")
    assert watched.page.is_visible('#graph .group[data-group="/talker/"]')
    assert watched.problems == []


def test_crowded_global_names_are_boxed_by_namespace_and_unresolved_apart(
        browser: Any, tmp_path: Path) -> None:  # noqa: F811
    # Autoware's shape: a few nodes in /, and many global topics and services in
    # namespaces no node is in (/api/..., /vehicle/status/...), some named '?'.
    where = {"package": "p", "file": "p/src/node.cpp", "line": 3, "column": 1}
    nodes = [f"/adapter{i}" for i in range(70)]
    topics = ([f"/api/routing/t{i}" for i in range(20)] + [f"/api/motion/t{i}" for i in range(25)]
              + [f"/vehicle/status/s{i}" for i in range(12)] + ["/diagnostics", "/clock"]
              + ["?", "?", "/?/scan", "/?/odom"])
    links, records = [], []
    for i, name in enumerate(topics):
        node = nodes[i % len(nodes)]
        links.append({"kind": "publish", "node": node, "name": name, "given": name,
                      "type": "std_msgs/String", "queue_size": 1, "qos": None,
                      "conditions": [], "location": where})
        records.append({"name": name, "id": f"topic:{name}#{i}", "types": ["std_msgs/String"],
                        "publishers": [node], "subscribers": [], "conditions": []})
        links[-1]["resource"] = records[-1]["id"]
    config = {
        "name": "c", "launch": [], "args": {}, "diagnostics": [], "services": [], "actions": [],
        "parameters": [], "topics": records, "links": links,
        "nodes": [{"name": n, "id": f"node:{n}", "node": "p/adapter", "namespace": "/",
                   "remaps": [], "args": "", "conditions": [], "location": where}
                  for n in nodes]}
    model = {"schema": "haros-arch/1", "project": "p", "packages": [], "diagnostics": [],
             "configurations": [config]}
    path = tmp_path / "crowded.html"
    write_report(model, [], str(tmp_path), str(path))
    watched = Watched(browser, path)
    drawn = watched.ids("#graph .vertex")
    # Big: the boxes start collapsed; the nodes and the two lone global topics stay.
    assert {"namespace:/api/", "namespace:/vehicle/", "namespace:/?/"} <= drawn
    assert {"topic:/diagnostics#57", "topic:/clock#58"} <= drawn
    assert not any(v.startswith("topic:/api/") or v.startswith("topic:/vehicle/") for v in drawn)
    unresolved = watched.page.text_content(watched.vertex("namespace:/?/"))
    assert "unresolved" in unresolved and "4 topics" in unresolved
    assert "could not resolve" in watched.page.inner_text("#hint")
    # /api/ holds more than a box shows at once: its two namespaces are boxes inside it.
    watched.page.click(watched.vertex("namespace:/api/"))
    shown = watched.ids("#graph .vertex")
    assert {"namespace:/api/routing/", "namespace:/api/motion/"} <= shown
    watched.page.click(watched.vertex("namespace:/api/motion/"))
    assert "topic:/api/motion/t3#23" in watched.ids("#graph .vertex")
    # Opening a box zooms to it: the other is clicked where it is, out of view.
    watched.page.dispatch_event(watched.vertex("namespace:/?/"), "click")
    assert {"topic:?#59", "topic:?#60", "topic:/?/scan#61"} <= watched.ids("#graph .vertex")
    assert watched.problems == []


def test_a_box_of_many_names_linked_outside_it_opens_as_columns(browser: Any,  # noqa: F811
                                                                 tmp_path: Path) -> None:
    # A node's 40 private parameters, each read by the node outside their box: opened, the
    # box is a block of columns about the stage's shape, not one column 40 names tall, and
    # every read still runs between items, never across another name.
    where = {"package": "p", "file": "p/src/talker.cpp", "line": 3, "column": 1}
    names = [f"/talker/param{i:02d}" for i in range(40)]

    def link(kind: str, node: str, name: str) -> dict[str, Any]:
        return {"kind": kind, "node": node, "name": name, "given": name, "type": "int",
                "queue_size": None, "qos": None, "conditions": [], "location": where}

    config = {
        "name": "c", "launch": [], "args": {}, "diagnostics": [], "services": [], "actions": [],
        "nodes": [{"name": "/talker", "id": "node:/talker", "node": "p/talker", "namespace": "/",
                   "remaps": [], "args": "", "conditions": [], "location": where}],
        "topics": [],
        "parameters": [{"name": n, "id": f"parameter:{n}", "type": "int", "value": 1,
                        "readers": ["/talker"], "writers": [], "conditions": []} for n in names],
        "links": [link("read", "/talker", n) for n in names]}
    model = {"schema": "haros-arch/1", "project": "p", "packages": [], "diagnostics": [],
             "configurations": [config]}
    path = tmp_path / "params.html"
    write_report(model, [], str(tmp_path), str(path))
    watched = Watched(browser, path)
    watched.page.click(watched.vertex("namespace:/talker/"))
    drawn = watched.page.evaluate(GEOMETRY)
    params = {v: g for v, g in drawn["vertices"].items() if v.startswith("parameter:")}
    assert len(params) == 40
    columns = {round(g["x"]) for g in params.values()}
    assert len(columns) >= 3
    box = drawn["boxes"]["/talker/"]
    assert (box["y1"] - box["y0"]) < 2 * (box["x1"] - box["x0"])
    # Name order down each column, the columns left to right.
    order = sorted(params, key=lambda v: (round(params[v]["x"]), params[v]["y"]))
    assert order == [f"parameter:{n}" for n in names]
    reads = [e for e in drawn["edges"] if e["target"] in params or e["source"] in params]
    assert len(reads) == 40
    for e in reads:
        ends = {e["source"], e["target"]}
        for point in e["points"][2:-2]:
            assert not any(inside(point, g, 1) for v, g in drawn["vertices"].items()
                           if v not in ends), (e["source"], e["target"], point)
    assert watched.problems == []
