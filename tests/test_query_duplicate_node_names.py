"""duplicate-node-names reports one finding per duplicated name and configuration, not
one per pair: open-rmf's battle_go.launch.xml starts dispatch_patrol four times as
/task_requester, one mistake that was six errors. The finding names every instance
that collides; it is an error when two of them certainly run together, else one entry
of the -undecided info. What makes a pair collide is as before (never_together, apart,
roslaunch's own LAUNCH_NODE_DUPLICATE)."""

from __future__ import annotations

import json
from types import SimpleNamespace

import pytest
from conftest import package_xml

from haros_arch import query
from haros_arch.cli import main
from haros_arch.model.conditions import exit_event
from haros_arch.model.load import from_data
from haros_arch.model.location import Location
from haros_arch.query.catalogue import load_catalogue, run_catalogue

RULE = next(r for r in load_catalogue() if r.id == "duplicate-node-names")
LAUNCH = "rmf_demos/launch/battle_go.launch.xml"


def node(line: int, *conditions: dict, name: str = "/task_requester") -> dict:
    return {"name": name, "location": {"file": LAUNCH, "line": line},
            "conditions": list(conditions)}


def when(text: str, statement: str = "if") -> dict:
    return {"text": text, "kind": "launch", "statement": statement}


def findings(*nodes: dict, roots: tuple[str, ...] = ("/nowhere",)) -> list:
    items = []
    for index, item in enumerate(nodes):
        items.append({**item, "id": f"node:{item['name']}" + (f"#{index + 1}" if index
                                                                else "")})
    model = from_data({"configurations": [{"name": "c", "nodes": items}]})
    return run_catalogue(model, SimpleNamespace(workspace=list(roots)), [RULE])


def lines(finding) -> list[int]:
    return [finding.location.line, *(where.line for where in finding.also)]


def test_four_instances_of_one_name_are_one_finding() -> None:
    (finding,) = findings(node(12), node(18), node(24), node(30))
    assert (finding.rule, finding.severity) == ("duplicate-node-names", "error")
    assert finding.entities == ("node:/task_requester", "node:/task_requester#2",
                                "node:/task_requester#3", "node:/task_requester#4")
    assert lines(finding) == [12, 18, 24, 30]  # SARIF: the other three are related
    assert finding.message == (
        f"4 nodes are named /task_requester ({LAUNCH} lines 12, 18, 24 and 30)")


def test_two_certainly_together_and_one_undecided_are_one_error() -> None:
    # two start for sure; a third under an argument with no value may join them: one
    # error that names all three (before: an error for the pair, an info for the others)
    found = findings(node(12), node(18), node(24, when("$(arg sim)")))
    assert [(f.rule, f.severity, lines(f)) for f in found] == [
        ("duplicate-node-names", "error", [12, 18, 24])]


def test_only_undecided_pairs_are_one_undecided_entry() -> None:
    found = findings(node(12, when("$(arg a)")), node(18, when("$(arg b)")),
                     node(24, when("$(arg c)")))
    assert [(f.rule, f.severity) for f in found] == [
        ("duplicate-node-names-undecided", "info")]
    assert found[0].message.startswith("1 possible finding(s) not reported")
    assert "/task_requester (1)" in found[0].message


def test_instances_never_together_are_left_out_and_the_rest_is_one_error() -> None:
    model_a, model_b = when("$(eval model == 'a')"), when("$(eval model == 'b')")
    # a and b never run together; two of each model do: one name, one error, four places
    found = findings(node(12, model_a), node(18, model_b), node(24, model_a),
                     node(30, model_b))
    assert [(f.severity, lines(f)) for f in found] == [("error", [12, 18, 24, 30])]
    # one of model b alone collides with nothing: named by no finding
    found = findings(node(12, model_a), node(18, model_b), node(24, model_a))
    assert [(f.severity, lines(f), f.entities) for f in found] == [
        ("error", [12, 24], ("node:/task_requester", "node:/task_requester#3"))]
    # exclusive models and nothing else: no duplicate at all
    assert findings(node(12, model_a), node(18, model_b)) == []


def test_one_started_on_the_exit_of_another_collides_with_a_third() -> None:
    # the second starts once the first's process has ended (OnProcessExit); the third
    # runs with both: one error naming the three, the first and third certainly together
    first = Location(None, LAUNCH, 12)
    found = findings(node(12), node(18, when(exit_event(first), "event")), node(24))
    assert [(f.severity, lines(f)) for f in found] == [("error", [12, 18, 24])]


def test_names_apart_are_findings_apart() -> None:
    found = findings(node(12), node(18), node(24, name="/other"), node(30, name="/other"))
    assert sorted((f.message.split()[4], lines(f)) for f in found) == [
        ("/other", [24, 30]), ("/task_requester", [12, 18])]


def test_an_ignore_comment_on_any_instance_line_silences_the_finding(write_tree) -> None:
    text = ["<launch>"] + ['  <node pkg="rmf_demos_tasks" exec="dispatch_patrol" '
                           'name="task_requester"/>' for _ in range(3)] + ["</launch>"]
    for ignored in (2, 3, 4):
        marked = list(text)
        marked[ignored - 1] += " <!-- haros-arch: ignore duplicate-node-names -->"
        root = write_tree({LAUNCH: "\n".join(marked) + "\n"})
        assert findings(node(2), node(3), node(4), roots=(str(root),)) == [], ignored
    root = write_tree({LAUNCH: "\n".join(text) + "\n"})
    assert len(findings(node(2), node(3), node(4), roots=(str(root),))) == 1


SETUP = """
    from setuptools import setup
    setup(name="tasks", packages=["tasks"],
          entry_points={"console_scripts": ["dispatch_patrol = tasks.patrol:main"]})
    """
PATROL = """
    import rclpy
    from std_msgs.msg import String
    def main():
        rclpy.init()
        node = rclpy.create_node("task_requester")
        node.create_publisher(String, "task_api_requests", 10)
    """
BATTLE_GO = """<launch>
  <node pkg="tasks" exec="dispatch_patrol" name="task_requester" args="-p a b"/>
  <node pkg="tasks" exec="dispatch_patrol" name="task_requester" args="-p c d"/>
  <node pkg="tasks" exec="dispatch_patrol" name="task_requester" args="-p e f"/>
  <node pkg="tasks" exec="dispatch_patrol" name="task_requester" args="-p g h"/>
</launch>
"""


def test_a_ros2_launch_of_four_namesakes_is_one_result_in_json_and_sarif(write_tree):
    root = write_tree({
        "src/tasks/package.xml": package_xml("tasks", "ament_python"),
        "src/tasks/setup.py": SETUP, "src/tasks/tasks/__init__.py": "",
        "src/tasks/tasks/patrol.py": PATROL,
        "src/tasks/launch/battle_go.launch.xml": BATTLE_GO,
        "project.yaml": "project: p\nconfigurations:\n  c: [tasks/launch/battle_go.launch.xml]\n",
    })
    out = root / "check.json"
    main(["check", str(root / "project.yaml"), "--format", "json", "-o", str(out),
          "--fail-on", "never"])
    (finding,) = [f for f in json.loads(out.read_text())["findings"]
                  if f["rule"].startswith("duplicate")]
    assert finding["severity"] == "error" and len(finding["entities"]) == 4
    assert finding["message"] == ("4 nodes are named /task_requester "
                                  "(tasks/launch/battle_go.launch.xml lines 2, 3, 4 and 5)")
    sarif = root / "check.sarif"
    main(["check", str(root / "project.yaml"), "--format", "sarif", "-o", str(sarif),
          "--fail-on", "never"])
    (result,) = [r for r in json.loads(sarif.read_text())["runs"][0]["results"]
                 if r["ruleId"].startswith("duplicate")]
    assert result["locations"][0]["physicalLocation"]["region"]["startLine"] == 2
    assert [r["physicalLocation"]["region"]["startLine"]
            for r in result["relatedLocations"]] == [3, 4, 5]


def test_group_by_groups_a_list_by_a_field_in_the_order_first_seen() -> None:
    model = from_data({"configurations": [{"name": "c", "nodes": [
        {"name": "/a/cam"}, {"name": "/b/lidar"}, {"name": "/b/cam"},
        {"name": "/a/cam", "id": "node:/a/cam#2"}]}]})
    config = model.configuration("c")

    def run(text: str) -> list:
        return query.compile(text).run(query.config_scope(config, model))

    assert run("for g in group_by(<nodes>, 'name') return len(g)") == [2, 1, 1]
    assert run("for g in group_by(<nodes>, 'rosname.own') return g[0].name") == [
        "/a/cam", "/b/lidar"]
    with pytest.raises(query.QueryError, match="no field 'nmae'"):
        run("for g in group_by(<nodes>, 'nmae') return g")
