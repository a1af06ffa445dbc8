"""The HTML report's Python side: escaping, embedded source lines, the CLI command."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from haros_arch.cli import main
from haros_arch.model.finding import Finding
from haros_arch.model.location import Location
from haros_arch.viz import ReportError, render_report, write_report
from haros_arch.viz.html import json_for_script
from haros_arch.viz.sources import CONTEXT_LINES, collect_snippets

HOSTILE = "<img src=x onerror=alert(1)></script><!--\u2028&amp;"


@pytest.fixture
def fake_d3(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A stand-in d3.min.js so these tests do not need npm."""
    path = tmp_path / "d3.min.js"
    path.write_text("window.d3 = {};\n")
    monkeypatch.setenv("HAROS_ARCH_D3", str(path))
    return path


def small_model(topic: str = "/chatter") -> dict:
    where = {"package": "demo", "file": "demo/src/talker.cpp", "line": 3, "column": 5}
    return {"schema": "haros-arch/1", "project": "demo", "packages": [], "diagnostics": [],
            "configurations": [{
                "name": "main", "launch": [], "args": {},
                "nodes": [{"name": "/talker", "id": "node:/talker", "node": None,
                           "namespace": "/", "remaps": [], "args": "", "conditions": [],
                           "location": where}],
                "topics": [{"name": topic, "id": f"topic:{topic}", "types": ["std_msgs/String"],
                            "publishers": ["/talker"], "subscribers": [], "conditions": []}],
                "services": [], "actions": [], "parameters": [],
                "links": [{"kind": "publish", "node": "/talker", "name": topic, "given": topic,
                           "type": "std_msgs/String", "queue_size": 1, "qos": None,
                           "conditions": [], "location": where}],
                "diagnostics": []}]}


def data_of(page: str) -> dict:
    match = re.search(r'<script type="application/json" id="haros-data">(.*?)</script>',
                      page, re.S)
    assert match
    return json.loads(match.group(1))


def test_json_for_script_escapes_markup_and_line_separators() -> None:
    text = json_for_script({"name": HOSTILE})
    for raw in ("<", ">", "&", "\u2028"):
        assert raw not in text
    assert json.loads(text) == {"name": HOSTILE}


def test_hostile_names_stay_inside_the_data_element(fake_d3: Path, tmp_path: Path) -> None:
    finding = Finding("probe", "warning", HOSTILE, HOSTILE, "main", (f"topic:{HOSTILE}",),
                      Location("demo", "demo/src/talker.cpp", 3, 5))
    page = render_report(small_model(HOSTILE), [finding], str(tmp_path))
    assert "<img" not in page
    assert page.count("</script>") == 3  # the data element, D3, our code
    data = data_of(page)
    assert data["model"]["configurations"][0]["topics"][0]["name"] == HOSTILE
    assert data["findings"][0]["title"] == HOSTILE
    assert data["findings"][0]["entities"] == [f"topic:{HOSTILE}"]


def test_the_page_forbids_network_and_foreign_scripts(fake_d3: Path, tmp_path: Path) -> None:
    page = render_report(small_model(), [], str(tmp_path))
    csp = re.search(r'http-equiv="Content-Security-Policy" content="([^"]*)"', page)
    assert csp
    assert "default-src 'none'" in csp.group(1)
    assert "unsafe-inline" not in csp.group(1).split("script-src")[1].split(";")[0]
    assert "window.d3 = {};" in page


def test_source_lines_around_each_location_are_embedded(write_tree, fake_d3: Path) -> None:
    lines = [f"line {n} <b>" for n in range(1, 21)]
    root = write_tree({"demo/src/talker.cpp": "\n".join(lines) + "\n"})
    page = render_report(small_model(), [], str(root))
    shown = data_of(page)["sources"]["demo/src/talker.cpp"]
    expected = range(max(1, 3 - CONTEXT_LINES), 3 + CONTEXT_LINES + 1)
    assert sorted(map(int, shown)) == list(expected)
    assert shown["3"] == "line 3 <b>"


def test_only_files_inside_the_workspace_are_read(write_tree) -> None:
    root = write_tree({"ws/a.cpp": "inside\n", "secret.txt": "outside\n"})
    data = {"x": [{"file": "a.cpp", "line": 1}, {"file": "../secret.txt", "line": 1},
                  {"file": str(root / "secret.txt"), "line": 1}]}
    assert collect_snippets(data, str(root / "ws")) == {"a.cpp": {"1": "inside"}}


def test_sources_of_a_package_linked_into_the_workspace_are_read(write_tree) -> None:
    # a workspace whose src links to checkouts elsewhere: their packages' files are
    # embedded; a link to a folder that holds no package is not followed
    root = write_tree({"checkouts/repo/pkg/package.xml": "<package/>\n",
                       "checkouts/repo/pkg/src/a.cpp": "in the package\n",
                       "private/notes.txt": "not a package\n", "ws/src/.keep": ""})
    (root / "ws/src/repo").symlink_to(root / "checkouts/repo")
    (root / "ws/src/private").symlink_to(root / "private")
    data = {"x": [{"file": "src/repo/pkg/src/a.cpp", "line": 1},
                  {"file": "src/private/notes.txt", "line": 1},
                  {"file": "src/repo/../../../private/notes.txt", "line": 1}]}
    assert collect_snippets(data, str(root / "ws")) == {
        "src/repo/pkg/src/a.cpp": {"1": "in the package"}}


def test_missing_d3_is_a_clear_error(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("HAROS_ARCH_D3", str(tmp_path / "none.js"))
    with pytest.raises(ReportError, match="D3 is not installed"):
        write_report(small_model(), [], str(tmp_path), str(tmp_path / "r.html"))


def test_cli_renders_a_saved_model(fake_d3: Path, tmp_path: Path, capsys) -> None:
    saved = tmp_path / "model.json"
    saved.write_text(json.dumps(small_model()))
    out = tmp_path / "report.html"
    assert main(["report", "--model", str(saved), "--workspace", str(tmp_path),
                 "-o", str(out)]) == 0
    assert data_of(out.read_text())["model"]["project"] == "demo"


@pytest.mark.parametrize("argv", [["report", "-o", "x.html"],
                                  ["report", "--model", "missing.json", "-o", "x.html"]])
def test_cli_report_usage_errors_exit_2(argv: list[str], fake_d3: Path, tmp_path: Path,
                                        monkeypatch: pytest.MonkeyPatch, capsys) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 2
    assert "haros-arch:" in capsys.readouterr().err
    assert not (tmp_path / "x.html").exists()
