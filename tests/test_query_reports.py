"""check and query from the command line; SARIF validates against the 2.1.0 schema."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from xml.etree import ElementTree as ET

import pytest
import yaml
from conftest import FIXTURES, ROOT

from haros_arch.model.load import from_data
from haros_arch.query.catalogue import run_catalogue
from haros_arch.report.junit import to_junit
from haros_arch.report.sarif import to_sarif

SCHEMA = ROOT / "tests" / "schemas" / "sarif-2.1.0-rtm.5.json"


def run(*args: str) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "COLUMNS": "200"}
    env.pop("HAROS_ARCH_DEBUG", None)
    return subprocess.run([sys.executable, "-m", "haros_arch.cli", *args], cwd=ROOT,
                          capture_output=True, text=True, env=env, timeout=300)


@pytest.fixture(scope="module")
def findings():
    # the paper's example with its /chatter subscriber made unconditional: a mismatch
    # with a side that may not exist is undecided, not an error
    doc = yaml.safe_load((FIXTURES / "queries/paper.yaml").read_text())
    for link in doc["configurations"][0]["links"]:
        if link["node"] == "/listener":
            link.pop("conditions", None)
    return run_catalogue(from_data(doc))


def test_sarif_validates_and_points_at_the_source_line(findings, tmp_path):
    jsonschema = pytest.importorskip("jsonschema")
    log = to_sarif(findings, [], {"topic-type-mismatch": ("Topic type mismatch", "why")},
                   str(tmp_path))
    jsonschema.validate(log, json.loads(SCHEMA.read_text()))
    results = log["runs"][0]["results"]
    mismatch = next(r for r in results if r["ruleId"] == "topic-type-mismatch")
    physical = mismatch["locations"][0]["physicalLocation"]
    assert physical["artifactLocation"]["uri"] == "example/src/active.cpp"
    assert physical["region"] == {"startLine": 20, "startColumn": 25}
    assert mismatch["level"] == "error"
    assert log["runs"][0]["originalUriBaseIds"]["WORKSPACE"]["uri"].startswith("file://")


def test_junit_has_a_failing_case_per_finding(findings):
    root = ET.fromstring(to_junit(findings, [], ["topic-type-mismatch", "qos-incompatible"]))
    suites = {s.get("name"): s for s in root.iter("testsuite")}
    assert suites["topic-type-mismatch"].get("failures") == "1"
    assert suites["qos-incompatible"].get("failures") == "0"
    assert int(root.get("failures")) == len(findings)


def test_check_text_groups_findings_by_rule_with_what_where_why():
    result = run("check", str(FIXTURES / "paper_minimal/project.yaml"), "--fail-on", "info",
                 "-v")
    assert result.returncode == 1, result.stderr
    assert re.search(r"queries: [0-9.]+ s; .*parameter-set-not-read [0-9.]+ s", result.stdout)
    # the talker reads a parameter whose name it reads from stdin: it may read
    # /frequency, so "set but never read" is not decided, one info that says why
    assert "info Parameter set but never read: not decided " \
        "[parameter-set-not-read-undecided]: 1" in result.stdout
    assert "example/launch/minimal.launch:2: 1 possible finding(s)" in result.stdout
    assert "/talker (1)" in result.stdout
    assert "Traceback" not in result.stderr


def test_check_formats_and_fail_on(tmp_path):
    project = str(FIXTURES / "paper_minimal/project.yaml")
    assert run("check", project, "--fail-on", "never").returncode == 0
    assert run("check", project, "--fail-on", "error").returncode == 0
    out = tmp_path / "out.sarif"
    assert run("check", project, "--format", "sarif", "-o", str(out),
               "--fail-on", "never").returncode == 0
    log = json.loads(out.read_text())
    assert log["version"] == "2.1.0"
    assert {r["ruleId"] for r in log["runs"][0]["results"]} >= {
        "parameter-set-not-read-undecided"}
    data = json.loads(run("check", project, "--format", "json").stdout)
    assert {f["rule"] for f in data["findings"]} >= {"parameter-set-not-read-undecided"}
    assert data["findings"][0]["configurations"] == ["minimal"]
    junit = run("check", project, "--format", "junit").stdout
    assert ET.fromstring(junit).tag == "testsuites"


def test_extract_writes_findings_into_the_json_model(tmp_path):
    out = tmp_path / "model.json"
    assert run("extract", str(FIXTURES / "paper_minimal/project.yaml"), "-o", str(out),
               "-q").returncode == 0
    data = json.loads(out.read_text())
    assert any(f["rule"] == "parameter-set-not-read-undecided" for f in data["findings"])
    assert set(data["findings"][0]) >= {"rule", "severity", "title", "message",
                                        "configuration", "entities", "location"}


def test_query_on_a_saved_model_prints_matches_and_locations(tmp_path):
    model = tmp_path / "model.json"
    model.write_text(json.dumps(yaml.safe_load((FIXTURES / "queries/paper.yaml").read_text())))
    text = ("for p in <configs/nodes/publishers>, s in <configs/nodes/subscribers> "
            "where p.topic_name == s.topic_name and p.type != s.type return p, s")
    result = run("query", "--model", str(model), text)
    assert result.returncode == 0, result.stderr
    assert "/talker publishes /chatter (std_msgs/String)" in result.stdout
    assert "example/src/active.cpp:20:25" in result.stdout
    data = json.loads(run("query", "--model", str(model), "topics[len(self.types) > 1]",
                          "--format", "json").stdout)
    assert data == [{"configuration": "minimal", "value": "topic:/chatter",
                     "locations": ["example/src/active.cpp:20:25"]}]


def test_query_errors_exit_2_with_a_caret(tmp_path):
    model = tmp_path / "model.json"
    model.write_text(json.dumps(yaml.safe_load((FIXTURES / "queries/paper.yaml").read_text())))
    bad = run("query", "--model", str(model), "configs/nodes[len(self.remaps) >]")
    assert bad.returncode == 2
    assert "^" in bad.stderr and "Traceback" not in bad.stderr
    unknown = run("query", "--model", str(model), "configs/nodes[self.nmae]")
    assert unknown.returncode == 2 and "no field 'nmae'" in unknown.stderr
    missing = run("query", "--model", str(tmp_path / "nope.json"), "configs")
    assert missing.returncode == 2


def test_query_on_a_project_with_config(tmp_path):
    result = run("query", str(FIXTURES / "paper_minimal/project.yaml"),
                 "nodes[len(self.remaps) > 0]", "--config", "minimal")
    assert result.returncode == 0, result.stderr
    assert "node /talker" in result.stdout
    wrong = run("query", str(FIXTURES / "paper_minimal/project.yaml"), "nodes",
                "--config", "nope")
    assert wrong.returncode == 2


def test_the_same_finding_in_two_configurations_is_one_listing_both():
    config = {"links": [{"kind": "publish", "node": "/driver", "name": "/odom",
                         "given": "/odom", "location": {"file": "a/driver.cpp", "line": 3}}],
              "nodes": [{"name": "/driver", "node": "a/driver"}]}
    model = from_data({"configurations": [{"name": "sim", **config},
                                          {"name": "robot", **config}]})
    found = [f for f in run_catalogue(model) if f.rule == "global-names"]
    assert [(f.configuration, f.configurations) for f in found] == [
        ("sim", ("sim", "robot"))]
    assert "sim, robot: a/driver.cpp:3" in to_junit(found)
    sarif = to_sarif(found)["runs"][0]["results"][0]
    assert sarif["properties"]["configurations"] == ["sim", "robot"]


def test_text_lists_the_first_few_findings_of_a_rule_and_all_with_verbose():
    from io import StringIO

    from rich.console import Console

    from haros_arch.model.finding import Finding
    from haros_arch.model.location import Location
    from haros_arch.report.findings import FIRST_FEW, print_findings

    findings = [Finding("queue-size-one", "info", "Queue size 1", f"link {i}", "c", (),
                        Location("p", "p/a.cpp", i)) for i in range(FIRST_FEW + 2)]
    findings.append(Finding("topic-type-mismatch", "error", "Topic type mismatch", "m", "c"))

    def text(verbose: bool) -> str:
        out = StringIO()
        print_findings(findings, Console(file=out, width=200), verbose)
        return out.getvalue()

    short = text(False)
    assert short.index("[topic-type-mismatch]: 1") < short.index("[queue-size-one]: 5")
    assert "link 2" in short and "link 3" not in short and "... and 2 more" in short
    assert "link 4" in text(True) and "more" not in text(True)


def test_a_finding_at_two_call_sites_keeps_both_places_in_sarif_and_junit():
    jsonschema = pytest.importorskip("jsonschema")
    links = [{"kind": "subscribe", "node": "/safety", "name": "/bumper", "type": "a/B",
              "queue_size": 1, "location": {"file": "s/safety.cpp", "line": line}}
             for line in (7, 9)]
    model = from_data({"configurations": [{"name": "c", "links": links, "nodes": [
        {"name": "/safety", "node": "s/safety"}]}]})
    (found,) = [f for f in run_catalogue(model) if f.rule == "queue-size-one"]
    assert found.location.line == 7 and [str(p) for p in found.also] == ["s/safety.cpp:9"]
    log = to_sarif([found], [], {}, "/ws")
    jsonschema.validate(log, json.loads(SCHEMA.read_text()))
    related = log["runs"][0]["results"][0]["relatedLocations"]
    assert related[0]["physicalLocation"]["region"]["startLine"] == 9
    assert "also at: s/safety.cpp:9" in to_junit([found])


def test_sarif_gives_a_file_of_a_later_workspace_folder_its_own_uri():
    """A project of several workspace folders: files beyond the first are absolute in
    the model, and a URI relative to the first folder would point nowhere."""
    jsonschema = pytest.importorskip("jsonschema")
    links = [{"kind": "subscribe", "node": "/safety", "name": "/bumper", "type": "a/B",
              "queue_size": 1, "location": {"file": "/other/ws/s/safety.cpp", "line": 7}}]
    model = from_data({"configurations": [{"name": "c", "links": links, "nodes": [
        {"name": "/safety", "node": "s/safety"}]}]})
    (found,) = [f for f in run_catalogue(model) if f.rule == "queue-size-one"]
    log = to_sarif([found], [], {}, "/ws")
    jsonschema.validate(log, json.loads(SCHEMA.read_text()))
    artifact = log["runs"][0]["results"][0]["locations"][0]["physicalLocation"][
        "artifactLocation"]
    assert artifact == {"uri": "file:///other/ws/s/safety.cpp"}
