"""The JSON model's contract (DESIGN.md, "The JSON model"): the fields that the report, CI
tools and users' scripts may rely on are present, with their types, in what ``extract``
writes for the bundled example (a ROS 1 robot and a ROS 2 rover)."""

from __future__ import annotations

import json
import os

from conftest import ROOT

from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

LOCATION = {"package", "file", "line", "column"}
CONDITION = {"text", "kind", "statement", "location"}
REQUIRED = {
    "package": {"name", "path", "build_type", "nodes"},
    "node": {"name", "kind", "language", "sources", "calls", "completeness"},
    "call": {"kind", "name", "type", "queue_size", "qos", "conditions", "location"},
    "configuration": {"name", "launch", "args", "nodes", "topics", "services", "actions",
                      "parameters", "links", "diagnostics"},
    "instance": {"name", "node", "namespace", "remaps", "args", "conditions", "location",
                 "completeness", "id"},
    "topic": {"name", "types", "publishers", "subscribers", "conditions", "id"},
    "service": {"name", "types", "servers", "clients", "conditions", "id"},
    "action": {"name", "types", "servers", "clients", "conditions", "id"},
    "parameter": {"name", "type", "value", "readers", "writers", "conditions", "id"},
    "link": {"kind", "node", "name", "given", "type", "queue_size", "qos", "conditions",
             "location", "resource"},
    "diagnostic": {"code", "severity", "message", "location"},
}


def missing(kind: str, item: dict) -> set[str]:
    return REQUIRED[kind] - set(item)


def test_extract_document_keeps_the_contract() -> None:
    project = load(str(ROOT / "examples" / "project.yaml"))
    data = json.loads(json.dumps(model_to_data(analyse(
        project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None)))))
    assert data["schema"] == "haros-arch/1" and isinstance(data["project"], str)
    problems = []
    for package in data["packages"]:
        problems += [("package", package["name"], missing("package", package))]
        for node in package["nodes"]:
            assert node["name"] == f"{node['package']}/{node['executable']}"
            assert node["completeness"] in ("complete", "partial", "model", "unknown")
            problems.append(("node", node["name"], missing("node", node)))
            for call in node["calls"]:
                problems.append(("call", node["name"], missing("call", call)))
                problems.append(("location", node["name"], LOCATION - set(call["location"])))
                for cond in call["conditions"]:
                    problems.append(("condition", node["name"], CONDITION - set(cond)))
    assert data["configurations"], "the example has configurations"
    for config in data["configurations"]:
        problems.append(("configuration", config["name"], missing("configuration", config)))
        for key, kind in (("nodes", "instance"), ("topics", "topic"), ("services", "service"),
                          ("actions", "action"), ("parameters", "parameter"),
                          ("links", "link"), ("diagnostics", "diagnostic")):
            for item in config[key]:
                problems.append((kind, item.get("name") or item.get("code"),
                                 missing(kind, item)))
        for instance in config["nodes"]:
            assert instance["completeness"] in ("complete", "partial", "model", "unknown")
            assert instance["node"] is None or isinstance(instance["node"], str)
    for diagnostic in data["diagnostics"]:
        problems.append(("diagnostic", diagnostic["code"], missing("diagnostic", diagnostic)))
    assert [p for p in problems if p[2]] == []
