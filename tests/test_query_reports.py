"""check and query from the command line; SARIF validates against the 2.1.0 schema."""

from __future__ import annotations

import json
import os
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
    model = from_data(yaml.safe_load((FIXTURES / "queries/paper.yaml").read_text()))
    return run_catalogue(model)


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


def test_check_text_groups_findings_by_severity_with_what_where_why():
    result = run("check", str(FIXTURES / "paper_minimal/project.yaml"), "--fail-on", "info")
    assert result.returncode == 1, result.stderr
    assert "INFOS" in result.stdout
    assert "example/launch/minimal.launch:" in result.stdout
    assert "[parameter-set-not-read]" in result.stdout
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
    assert {r["ruleId"] for r in log["runs"][0]["results"]} >= {"parameter-set-not-read"}
    data = json.loads(run("check", project, "--format", "json").stdout)
    assert {f["rule"] for f in data["findings"]} >= {"parameter-set-not-read"}
    junit = run("check", project, "--format", "junit").stdout
    assert ET.fromstring(junit).tag == "testsuites"


def test_extract_writes_findings_into_the_json_model(tmp_path):
    out = tmp_path / "model.json"
    assert run("extract", str(FIXTURES / "paper_minimal/project.yaml"), "-o", str(out),
               "-q").returncode == 0
    data = json.loads(out.read_text())
    assert any(f["rule"] == "parameter-set-not-read" for f in data["findings"])
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
