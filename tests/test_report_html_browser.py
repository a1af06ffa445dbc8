"""The HTML report in a real headless Chromium (Debian's), driven by Playwright.

One report of the example workspace (two configurations) with findings made here, and one
report with hostile names. Each test opens a fresh page and fails on any console error,
page error or network request.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from conftest import ROOT

from haros_arch.model.finding import Finding
from haros_arch.model.location import Location
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.viz import write_report
from haros_arch.viz.browser import CHROMIUM_ARGS, chromium_path, why_no_browser

REASON = why_no_browser()
pytestmark = pytest.mark.skipif(REASON is not None, reason=REASON or "")
EXAMPLE = ROOT / "examples" / "project.yaml"
XSS = "<img src=x onerror=alert(1)>"


@pytest.fixture(scope="module")
def example(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    project = load(str(EXAMPLE))
    data = model_to_data(analyse(project))
    first = data["configurations"][0]
    topic = next(t for t in first["topics"] if t["publishers"] and not t["subscribers"])
    finding = Finding("no-subscriber", "warning", "Published but never subscribed",
                      f"{topic['name']} has no subscriber", first["name"],
                      (topic["id"], "node:" + topic["publishers"][0]))
    path = tmp_path_factory.mktemp("report") / "example.html"
    write_report(data, [finding], project.workspace[0], str(path))
    return {"path": path, "data": data, "finding": finding, "root": Path(project.workspace[0])}


@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    from playwright.sync_api import sync_playwright

    with sync_playwright() as driver:
        chromium = driver.chromium.launch(executable_path=chromium_path(), args=CHROMIUM_ARGS)
        yield chromium
        chromium.close()


class Watched:
    """A page that records console errors, page errors, dialogs and network requests."""

    def __init__(self, browser: Any, path: Path) -> None:
        self.problems: list[str] = []
        self.dialogs: list[str] = []
        self.page = browser.new_page(viewport={"width": 1400, "height": 800})
        self.page.on("console", lambda m: self.problems.append(f"console {m.type}: {m.text}")
                     if m.type in ("error", "warning") else None)
        self.page.on("pageerror", lambda e: self.problems.append(f"page error: {e}"))
        self.page.on("dialog", self._dialog)
        url = path.as_uri()
        self.page.on("request", lambda r: r.url == url or self.problems.append(f"request {r.url}"))
        self.page.goto(url)
        self.page.wait_for_function("window.harosReport && window.harosReport.ready")

    def _dialog(self, dialog: Any) -> None:
        self.dialogs.append(dialog.message)
        dialog.dismiss()

    def ids(self, selector: str) -> set[str]:
        return set(self.page.eval_on_selector_all(
            selector, "els => els.map(e => e.getAttribute('data-id'))"))

    def vertex(self, entity_id: str) -> str:
        return f'#graph .vertex[data-id="{entity_id}"]'


@pytest.fixture
def page(browser: Any, example: dict[str, Any]) -> Iterator[Watched]:
    watched = Watched(browser, example["path"])
    yield watched
    assert watched.problems == []
    watched.page.close()


def entity_ids(config: dict[str, Any]) -> set[str]:
    """What the graph draws by default: all but the topics and services inside actions."""
    wire = {link["resource"] for link in config["links"] if link["origin"] == "action"}
    wire -= {link["resource"] for link in config["links"] if link["origin"] != "action"}
    return {item["id"] for key in ("nodes", "topics", "services", "actions", "parameters")
            for item in config[key]} - wire


def test_actions_fold_their_topics_until_asked(page: Watched, example) -> None:
    drawn = page.ids("#graph .vertex")
    assert "action:/robot1/dock" in drawn
    assert "topic:/robot1/dock/goal" not in drawn
    page.page.check('input[data-filter="hideActionWire"]')
    drawn = page.ids("#graph .vertex")
    assert {"topic:/robot1/dock/goal", "topic:/robot1/dock/feedback"} <= drawn


def test_every_entity_of_the_first_configuration_is_drawn(page: Watched, example) -> None:
    assert page.ids("#graph .vertex") == entity_ids(example["data"]["configurations"][0])


def test_picking_a_configuration_draws_its_graph(page: Watched, example) -> None:
    second = example["data"]["configurations"][1]
    page.page.select_option("#config", label=second["name"])
    assert page.ids("#graph .vertex") == entity_ids(second)
    assert second["name"] in page.page.inner_text("#panel")


def test_a_finding_highlights_its_entities_and_dims_the_rest(page: Watched, example) -> None:
    finding = example["finding"]
    page.page.click(f'#findings .item[data-rule="{finding.rule}"]')
    assert page.page.eval_on_selector("#graph", "svg => svg.classList.contains('focus')")
    assert page.ids("#graph .vertex.hl") == set(finding.entities)
    assert finding.message in page.page.inner_text("#panel")


def test_clicking_a_node_shows_its_location_and_code(page: Watched, example) -> None:
    node = example["data"]["configurations"][0]["nodes"][0]
    page.page.click(page.vertex(node["id"]))
    panel = page.page.inner_text("#panel")
    where = node["location"]
    assert f"{where['file']}:{where['line']}" in panel
    source = (example["root"] / where["file"]).read_text().splitlines()[where["line"] - 1]
    assert source.strip() in panel
    links = [link for link in example["data"]["configurations"][0]["links"]
             if link["node"] == node["name"]]
    for link in links:
        assert f"{link['location']['file']}:{link['location']['line']}" in panel
    assert page.ids("#graph .vertex.selected") == {node["id"]}


def test_conditional_links_are_dashed_with_their_condition(page: Watched, example) -> None:
    config = example["data"]["configurations"][0]
    link = next(link for link in config["links"] if link["conditions"])
    edges = page.page.eval_on_selector_all(
        "#graph .edge.conditional", "els => els.map(e => e.textContent)")
    assert any(link["conditions"][0]["text"] in title and link["name"] in title
               for title in edges)


def test_filters_and_namespace_collapse(page: Watched, example) -> None:
    config = example["data"]["configurations"][0]
    page.page.uncheck('input[data-filter="hideParameters"]')
    drawn = page.ids("#graph .vertex")
    assert not any(i.startswith("parameter:") for i in drawn)
    assert drawn == {i for i in entity_ids(config) if not i.startswith("parameter:")}
    namespace = next(n["namespace"] for n in config["nodes"] if n["namespace"] != "/")
    page.page.check(f'input[data-namespace="{namespace}"]')
    drawn = page.ids("#graph .vertex")
    assert f"namespace:{namespace}" in drawn
    assert not any(i.startswith("node:" + namespace) for i in drawn)


def test_search_lights_matching_names(page: Watched, example) -> None:
    topic = example["data"]["configurations"][0]["topics"][0]
    page.page.fill("#search", topic["name"])
    assert topic["id"] in page.ids("#graph .vertex.hl")
    assert all(topic["name"] in i for i in page.ids("#graph .vertex.hl"))


def test_package_view_lists_nodes_and_interfaces(page: Watched, example) -> None:
    page.page.click("#tab-packages")
    text = page.page.inner_text("#packages")
    for package in example["data"]["packages"]:
        for node in package["nodes"]:
            assert f"{node['package']}/{node['executable']}" in text
            for call in node["calls"]:
                assert call["name"] in text


def test_hostile_names_are_text_and_candidates_light_up(browser: Any, tmp_path: Path) -> None:
    where = {"package": "demo", "file": "demo/src/a.cpp", "line": 1, "column": 1}

    def topic(name: str, tid: str, **extra: Any) -> dict[str, Any]:
        return {"name": name, "id": tid, "types": [XSS], "publishers": ["/a"],
                "subscribers": [], "conditions": [], **extra}

    config = {
        "name": XSS, "launch": [], "args": {}, "services": [], "actions": [],
        "parameters": [], "diagnostics": [],
        "nodes": [{"name": "/a", "id": "node:/a", "node": XSS, "namespace": "/",
                   "remaps": [[XSS, XSS]], "args": XSS, "conditions": [], "location": where,
                   "remapped": [[XSS, XSS, XSS]]}],
        "topics": [topic(XSS, "topic:x"), topic("/?", "topic:/?", candidates=["topic:x"])],
        "links": [{"kind": "publish", "node": "/a", "name": name, "given": XSS, "type": XSS,
                   "queue_size": 1, "qos": None, "conditions": [
                       {"text": XSS, "kind": "source", "statement": "if", "location": where}],
                   "location": where} for name in (XSS, "/?")],
        "launch_tree": [{"kind": "file", "name": XSS, "location": where,
                         "args": [{"name": XSS, "value": XSS, "origin": XSS}], "children": [
                             {"kind": "node", "name": "/a", "detail": XSS, "location": where,
                              "remaps": [[XSS, XSS]], "condition": {
                                  "text": XSS, "values": {XSS: XSS}, "holds": None}}]}]}
    (tmp_path / "demo/src").mkdir(parents=True)
    (tmp_path / "demo/src/a.cpp").write_text(f'pub("{XSS}");\n')
    finding = Finding("probe", "error", XSS, XSS, None, ("topic:x",),
                      Location("demo", "demo/src/a.cpp", 1, 1))
    path = tmp_path / "xss.html"
    write_report({"schema": "haros-arch/1", "project": XSS, "packages": [],
                  "configurations": [config], "diagnostics": []}, [finding], str(tmp_path),
                 str(path))
    watched = Watched(browser, path)
    page = watched.page
    assert page.text_content('#graph .vertex[data-id="topic:x"] .label') == XSS
    page.click('#graph .vertex[data-id="topic:x"]')
    page.click("#findings .item")
    page.click('#graph .vertex[data-id="topic:/?"]')
    assert watched.ids("#graph .vertex.candidate") == {"topic:x"}
    assert XSS in page.inner_text("#panel")
    page.click("#tab-packages")
    page.click("#tab-launch")
    assert XSS in page.inner_text("#launch")
    page.click("#launch .lt-file > .lt-head")
    assert XSS in page.inner_text("#panel")
    assert page.eval_on_selector_all("img", "els => els.length") == 0
    assert watched.dialogs == []
    assert watched.problems == []


def test_findings_by_rule_incomplete_nodes_and_diagnostics_per_configuration(
        browser: Any, tmp_path: Path) -> None:
    def where(file: str, line: int = 1) -> dict[str, Any]:
        return {"package": "demo", "file": file, "line": line, "column": 1}

    def config(name: str, launch: str) -> dict[str, Any]:
        return {
            "name": name, "launch": [launch], "args": {}, "services": [], "actions": [],
            "parameters": [], "diagnostics": [], "topics": [
                {"name": "/scan", "id": "topic:/scan", "types": ["a/B"], "publishers": [],
                 "subscribers": ["/slam"], "conditions": []}],
            "nodes": [
                {"name": "/slam", "id": "node:/slam", "node": "demo/slam", "namespace": "/",
                 "remaps": [], "args": "", "conditions": [], "location": where(launch),
                 "completeness": "partial"},
                {"name": "/driver", "id": "node:/driver", "node": None, "namespace": "/",
                 "remaps": [], "args": "", "conditions": [], "location": where(launch),
                 "completeness": "unknown"}],
            "links": [{"kind": "subscribe", "node": "/slam", "name": "/scan", "given": "scan",
                       "type": "a/B", "queue_size": 5, "qos": None, "conditions": [],
                       "location": where("demo/src/slam.cpp", 2)}]}

    long_line = "x = " + "y" * 400
    (tmp_path / "demo/src").mkdir(parents=True)
    (tmp_path / "demo/src/slam.cpp").write_text(f"int a;\n{long_line}\n")
    model = {"schema": "haros-arch/1", "project": "p", "packages": [{
        "name": "demo", "path": "demo", "build_type": "catkin", "nodes": [{
            "name": "demo/slam", "package": "demo", "executable": "slam", "kind": "executable",
            "language": "cpp", "sources": ["demo/src/slam.cpp"], "calls": [],
            "completeness": "partial",
            "completeness_reasons": ["demo/src/slam.cpp:9: C++ error: unknown type"]}]}],
        "configurations": [config("sim", "demo/launch/sim.launch"),
                           config("real", "demo/launch/real.launch")],
        "diagnostics": [
            {"code": "LAUNCH_X", "severity": "warning", "message": "in sim only",
             "location": where("demo/launch/sim.launch", 3),
             "also": [where("demo/launch/sim.launch", 7)]},
            {"code": "CPP_X", "severity": "info", "message": "in the slam source",
             "location": where("demo/src/slam.cpp", 2)}]}
    findings = [Finding("queue-size-one", "info", "Queue size 1", f"link {i}", "sim",
                        ("node:/slam", "topic:/scan"), Location("demo", "demo/src/slam.cpp", 2),
                        configurations=("sim", "real")) for i in range(4)]
    findings.append(Finding("topic-type-mismatch", "error", "Topic type mismatch", "m",
                            "sim", ("topic:/scan",)))
    path = tmp_path / "r.html"
    write_report(model, findings, str(tmp_path), str(path))
    watched = Watched(browser, path)
    page = watched.page
    # findings grouped by rule, most severe first, with counts; entries name entities
    groups = page.eval_on_selector_all(
        "#findings .finding-group", "els => els.map(e => [e.dataset.rule, "
        "e.querySelector('summary .count').textContent])")
    assert groups == [["topic-type-mismatch", "1"], ["queue-size-one", "4"]]
    assert "/slam" in page.inner_text('#findings .finding-group[data-rule="queue-size-one"]')
    # nodes of partial or unknown interface are drawn apart, with why on hover
    assert watched.ids("#graph .vertex.incomplete") == {"node:/slam", "node:/driver"}
    title = page.text_content('#graph .vertex[data-id="node:/slam"] title') or ""
    assert "interface partial" in title and "slam.cpp:9: C++ error" in title
    assert "no source" in (page.text_content('#graph .vertex[data-id="node:/driver"] title')
                           or "")
    # diagnostics of this configuration's files only
    text = page.inner_text("#diagnostics")
    assert "in sim only" in text and "in the slam source" in text
    # a diagnostic said once for several places (an unset argument's uses) lists them
    page.click('#diagnostics .item.diagnostic[data-code="LAUNCH_X"]')
    panel = page.inner_text("#panel")
    assert "the same problem at (1)" in panel.lower() and "sim.launch:7" in panel
    page.select_option("#config", label="real")
    text = page.inner_text("#diagnostics")
    assert "in sim only" not in text and "in the slam source" in text
    assert page.eval_on_selector_all("#findings .item.finding", "els => els.length") == 4
    # the source panel wraps long lines
    page.click('#findings .finding-group[data-rule="queue-size-one"] .item')
    width = page.eval_on_selector(".code-lines", "e => [e.scrollWidth, e.clientWidth]")
    assert width[0] <= width[1] + 1
    assert watched.problems == []


def launch_items(config: dict[str, Any]) -> list[dict[str, Any]]:
    out, stack = [], list(reversed(config["launch_tree"]))
    while stack:
        item = stack.pop()
        out.append(item)
        stack.extend(reversed(item.get("children", [])))
    return out


def test_launch_view_draws_the_tree_as_nested_boxes(page: Watched, example) -> None:
    config = example["data"]["configurations"][0]
    items = launch_items(config)
    page.page.click("#tab-launch")
    assert page.page.is_hidden("#graph")
    files = page.page.eval_on_selector_all(
        "#launch .lt-file", "els => els.map(e => e.dataset.name)")
    assert files == [i["name"] for i in items if i["kind"] == "file"]
    rows = page.ids("#launch .lt-node")
    assert rows == {"node:" + i["name"] for i in items if i["kind"] == "node"}
    # a node inside a group is drawn inside that group's box, inside its file's box
    group = next(i for i in items if i["kind"] == "group" and i.get("children"))
    child = group["children"][0]
    inside = page.page.eval_on_selector(
        f'#launch .lt-node[data-id="node:{child["name"]}"]',
        "e => [e.parentElement.closest('.lt').dataset.kind,"
        " e.parentElement.closest('.lt-file') !== null]")
    assert inside == ["group", True]
    text = page.page.inner_text("#launch")
    for arg in items[0]["args"]:
        assert arg["name"] in text and str(arg["value"]) in text and arg["origin"] in text
    # a remap is drawn from the name in the node's code to the name it resolves to
    remapped = next(i for i in items if i.get("remaps"))
    [instance] = [n for n in config["nodes"] if n["name"] == remapped["name"]]
    [[given, _, full]] = instance["remapped"]  # demo_robot: scan -> /robot1/base_scan
    selector = f'#launch .lt-node[data-id="node:{remapped["name"]}"] .lt-remap-code'
    assert page.page.inner_text(f"{selector} .lt-code-name") == given == "scan"
    assert page.page.inner_text(f"{selector} .lt-resolved-name") == full
    assert full.endswith("/base_scan")
    conditional = next(i for i in items if i.get("condition"))
    box = f'#launch .lt[data-id="node:{conditional["name"]}"]'
    assert page.page.eval_on_selector(box, "e => getComputedStyle(e).borderStyle") == "dashed"
    assert conditional["condition"]["text"] in page.page.inner_text(box)
    assert "holds" in page.page.inner_text(box)


def test_launch_view_and_graph_select_each_other(page: Watched, example) -> None:
    config = example["data"]["configurations"][0]
    node = config["nodes"][1]
    # graph -> launch: the node chosen in the graph is marked when the view opens
    page.page.click(page.vertex(node["id"]))
    page.page.click("#tab-launch")
    assert page.ids("#launch .lt-node.chosen") == {node["id"]}
    # launch -> graph: a node row switches to the graph with that node selected
    other = config["nodes"][2]
    page.page.click(f'#launch .lt-node[data-id="{other["id"]}"]')
    assert page.page.is_visible("#graph")
    assert page.ids("#graph .vertex.selected") == {other["id"]}
    where = other["location"]
    assert f"{where['file']}:{where['line']}" in page.page.inner_text("#panel")


def test_a_launch_file_box_shows_its_lines(page: Watched, example) -> None:
    top = example["data"]["configurations"][0]["launch_tree"][0]
    page.page.click("#tab-launch")
    page.page.click(f'#launch .lt-file[data-name="{top["name"]}"] > .lt-head')
    panel = page.page.inner_text("#panel")
    assert top["name"] in panel
    first = min(a["location"]["line"] for a in top["args"] if a["location"]["line"])
    source = (example["root"] / top["name"]).read_text().splitlines()[first - 1]
    assert source.strip() in panel
    assert page.page.eval_on_selector_all("#launch .lt.chosen", "els => els.length") == 1


def test_launch_rows_find_nodes_named_in_code_and_leave_out_skipped(
        browser: Any, tmp_path: Path) -> None:
    def where(line: int) -> dict[str, Any]:
        return {"package": "demo", "file": "demo/launch/a.launch.py", "line": line, "column": 1}

    config = {
        "name": "c", "launch": ["demo/launch/a.launch.py"], "args": {}, "topics": [],
        "services": [], "actions": [], "parameters": [], "diagnostics": [], "links": [],
        "nodes": [{"name": name, "id": "node:" + name, "node": "demo/rsp", "namespace": "/",
                   "remaps": [], "args": "", "conditions": [], "location": where(3)}
                  for name in ("/rsp", "/ddc")],  # one executable, two nodes
        "launch_tree": [{"kind": "file", "name": "demo/launch/a.launch.py", "children": [
            {"kind": "node", "name": "/?", "detail": "demo/rsp", "location": where(3)},
            {"kind": "node", "name": "/rsp", "detail": "demo/other", "location": where(5),
             "skipped": True, "condition": {"text": "use_sim", "values": {"use_sim": "false"},
                                            "holds": False}}]}]}
    (tmp_path / "demo/launch").mkdir(parents=True)
    (tmp_path / "demo/launch/a.launch.py").write_text(
        "".join(f"line_{n} = {n}\n" for n in range(1, 8)))
    path = tmp_path / "r.html"
    write_report({"schema": "haros-arch/1", "project": "p", "packages": [],
                  "configurations": [config], "diagnostics": []}, [], str(tmp_path), str(path))
    watched = Watched(browser, path)
    page = watched.page
    page.click('#graph .vertex[data-id="node:/ddc"]')
    page.click("#tab-launch")
    assert watched.ids("#launch .lt-node") == {"node:/rsp", None}
    assert watched.ids("#launch .lt-node.chosen") == {"node:/rsp"}
    assert "/rsp, /ddc" in page.inner_text("#launch .lt-node.chosen")
    skipped = page.inner_text('#launch .lt-node.skipped').lower()
    assert "not started" in skipped and "use_sim" in skipped and "false" in skipped
    page.click("#launch .lt-node.skipped")
    assert page.is_hidden("#graph")
    assert "line_5 = 5" in page.inner_text("#panel")
    page.click('#launch .lt-node[data-id="node:/rsp"]')
    assert watched.ids("#graph .vertex.selected") == {"node:/rsp"}
    assert "line_3 = 3" in page.inner_text("#panel")
    assert watched.problems == []


def test_launch_rows_draw_remaps_from_code_name_to_resolved_name(
        browser: Any, tmp_path: Path) -> None:
    """A node whose code is known shows each name a remap changed (code name -> resolved
    name, the rules as written in the tooltip); one without code shows the rules as
    the launch file wrote them, said so."""
    where = {"package": "demo", "file": "demo/launch/a.launch", "line": 2, "column": 1}

    def node(name: str, remapped: list[list[str]]) -> dict[str, Any]:
        return {"name": name, "id": "node:" + name, "node": "demo/x", "namespace": "/r/",
                "remaps": [["scan", "base_scan"]], "args": "", "conditions": [],
                "location": where, "remapped": remapped}

    config = {
        "name": "c", "launch": ["demo/launch/a.launch"], "args": {}, "topics": [],
        "services": [], "actions": [], "parameters": [], "diagnostics": [], "links": [],
        "nodes": [node("/r/known", [["scan", "/r/scan", "/r/base_scan"]]),
                  node("/r/unknown", [])],
        "launch_tree": [{"kind": "file", "name": "demo/launch/a.launch", "children": [
            {"kind": "node", "name": name, "detail": "demo/x", "location": where,
             "remaps": [["scan", "base_scan"]]} for name in ("/r/known", "/r/unknown")]}]}
    (tmp_path / "demo/launch").mkdir(parents=True)
    (tmp_path / "demo/launch/a.launch").write_text("<launch>\n<node/>\n</launch>\n")
    path = tmp_path / "r.html"
    write_report({"schema": "haros-arch/1", "project": "p", "packages": [],
                  "configurations": [config], "diagnostics": []}, [], str(tmp_path), str(path))
    watched = Watched(browser, path)
    page = watched.page
    page.click("#tab-launch")
    known = '#launch .lt-node[data-id="node:/r/known"]'
    assert page.inner_text(f"{known} .lt-remap-code .lt-code-name") == "scan"
    assert page.inner_text(f"{known} .lt-remap-code .lt-resolved-name") == "/r/base_scan"
    assert page.get_attribute(f"{known} .lt-remaps", "title") == (
        "remaps as written: scan \u2192 base_scan")
    unknown = page.inner_text('#launch .lt-node[data-id="node:/r/unknown"] .lt-remaps')
    assert "remaps as written" in unknown and "scan \u2192 base_scan" in unknown
    assert page.eval_on_selector_all(
        '#launch .lt-node[data-id="node:/r/unknown"] .lt-remap-code', "els => els.length") == 0
    assert watched.problems == []


def test_a_live_capture_shows_beside_the_graph(browser: Any, tmp_path: Path) -> None:
    """report --live: the capture's lists in the side bar, what it did not see dashed."""
    from conftest import FIXTURES

    from haros_arch.cli import main

    project = load(str(FIXTURES / "live_ros2" / "project.yaml"))
    model = model_to_data(analyse(project, {"PATH": ""}))
    chatter = {"name": "/chatter", "types": ["std_msgs/msg/String"],
               "publishers": ["/talker"], "subscribers": ["/listener", "/spy"]}
    live = {"schema": "haros-arch-live/1", "ros": 2, "observed": ["nodes", "topics"],
            "nodes": ["/talker", "/listener", "/spy"], "topics": [chatter],
            "services": [], "parameters": None}
    (tmp_path / "model.json").write_text(json.dumps(model))
    (tmp_path / "live.json").write_text(json.dumps(live))
    path = tmp_path / "r.html"
    assert main(["report", "--model", str(tmp_path / "model.json"), "--workspace",
                 str(tmp_path), "--live", str(tmp_path / "live.json"), "-o", str(path)]) == 0
    watched = Watched(browser, path)
    side = watched.page.inner_text("#live")
    assert "nodes 2 both, 1 only live, 1 only in the model" in side
    assert "/spy" in side and "/monitor" in side
    assert watched.ids("#graph .vertex.static-only") == {
        "node:/monitor", "topic:/count", "topic:/status"}
    assert watched.problems == []


def test_the_report_opens_on_the_first_configuration_that_starts_a_node(
        browser: Any, example: dict[str, Any], tmp_path: Path) -> None:
    # champ's ros2 branch keeps a ROS 1 laser/sim.launch that starts nothing: it sorts
    # first, and the report opened on an empty graph
    data = json.loads(json.dumps(example["data"]))
    first = data["configurations"][0]
    empty = {**first, "name": "aaa/empty", "nodes": [], "topics": [], "services": [],
             "actions": [], "parameters": [], "links": []}
    data["configurations"].insert(0, empty)
    path = tmp_path / "opening.html"
    write_report(data, [], str(example["root"]), str(path))
    watched = Watched(browser, path)
    assert watched.page.eval_on_selector("#config", "s => s.options[s.selectedIndex].text") == (
        first["name"])
    assert watched.ids("#graph .vertex") == entity_ids(first)
    watched.page.select_option("#config", label="aaa/empty")
    assert watched.ids("#graph .vertex") == set()
    assert watched.problems == []
    watched.page.close()


def test_a_later_workspace_folders_file_is_shown_under_the_folders_name(
        browser: Any, tmp_path: Path) -> None:
    first, second = tmp_path / "ws", tmp_path / "deps" / "ros2_controllers"
    source = second / "ctl" / "src" / "ctl.cpp"
    source.parent.mkdir(parents=True)
    (first / "demo").mkdir(parents=True)
    source.write_text('auto p = create_publisher<Odometry>("odom", 10);\n')
    where = {"package": "ctl", "file": str(source), "line": 1, "column": 10}
    config = {
        "name": "c", "launch": [], "args": {}, "services": [], "actions": [],
        "parameters": [], "diagnostics": [],
        "nodes": [{"name": "/ctl", "id": "node:/ctl", "node": "ctl/ctl", "namespace": "/",
                   "remaps": [], "args": "", "conditions": [], "location": where}],
        "topics": [{"name": "/odom", "id": "topic:/odom", "types": ["nav_msgs/Odometry"],
                    "publishers": ["/ctl"], "subscribers": [], "conditions": []}],
        "links": [{"kind": "publish", "node": "/ctl", "name": "/odom", "given": "odom",
                   "type": "nav_msgs/Odometry", "queue_size": 10, "qos": None,
                   "conditions": [], "location": where}]}
    path = tmp_path / "two.html"
    write_report({"schema": "haros-arch/1", "project": "two", "packages": [],
                  "configurations": [config], "diagnostics": []}, [],
                 [str(first), str(second)], str(path))
    watched = Watched(browser, path)
    watched.page.click('#graph .vertex[data-id="node:/ctl"]')
    panel = watched.page.inner_text("#panel")
    assert "ros2_controllers/ctl/src/ctl.cpp:1" in panel
    assert str(tmp_path) not in panel
    assert "create_publisher<Odometry>" in panel  # the line is quoted
    assert watched.problems == []
