"""Every shipped query has a fixture that triggers it and one that must not.

``fixtures/queries/catalogue/<id>.yaml`` holds ``trigger`` and ``clean`` (one
configuration each, in the JSON model's shape), ``expect`` (entity ids the findings
must name) and optionally ``message_has`` (text the message must contain).
"""

from __future__ import annotations

from types import SimpleNamespace

import pytest
import yaml
from conftest import FIXTURES, ROOT, only_case

from haros_arch import query
from haros_arch.model.load import from_data
from haros_arch.query.catalogue import (
    UNDECIDED,
    load_catalogue,
    project_rules,
    run_catalogue,
    run_rule,
)

CASES = FIXTURES / "queries" / "catalogue"
RULES = {rule.id: rule for rule in load_catalogue()}
IDS = sorted(i for i in RULES if only_case() in (None, i))


def configuration(doc: dict) -> object:
    """One configuration. A node that only links name runs code we know completely (a
    node type of its own); a fixture lists a node with ``node: null`` to say its
    interface is unknown."""
    doc = dict(doc or {})
    packages = doc.pop("packages", [])
    listed = {n["name"] for n in doc.get("nodes", ())}
    implied = dict.fromkeys(link["node"] for link in doc.get("links", ())
                            if link["node"] not in listed)
    doc["nodes"] = [*doc.get("nodes", ()),
                    *({"name": n, "node": f"known{n.replace('/', '_')}/node"} for n in implied)]
    return from_data({"project": "p", "packages": packages,
                      "configurations": [{"name": "c", **doc}]})


def test_every_rule_has_a_fixture_and_the_required_fields():
    assert sorted(p.stem for p in CASES.glob("*.yaml")) == sorted(RULES)
    for path in (ROOT / "queries").glob("*.yaml"):
        data = yaml.safe_load(path.read_text())
        assert data["id"] == path.stem
        assert data["severity"] in ("error", "warning", "info")
        assert {"title", "description", "query"} <= set(data)
        assert "Fix" in data["description"], f"{path.name}: say how to fix it"


@pytest.mark.parametrize("rule_id", IDS)
def test_rule_triggers_on_its_fixture(rule_id):
    case = yaml.safe_load((CASES / f"{rule_id}.yaml").read_text())
    findings = [f for f in run_rule(RULES[rule_id], configuration(case["trigger"]))
                if not f.rule.endswith(UNDECIDED)]
    assert findings, f"{rule_id} found nothing in its trigger fixture"
    assert all(f.rule == rule_id and f.configuration == "c" for f in findings)
    named = {e for f in findings for e in f.entities}
    assert set(case["expect"]) <= named
    for text in case.get("message_has", ()):
        assert any(text in f.message for f in findings), (text, findings)
    assert all("{" not in f.message for f in findings), "unfilled message template"


@pytest.mark.parametrize("rule_id", IDS)
def test_rule_is_silent_on_its_clean_fixture(rule_id):
    case = yaml.safe_load((CASES / f"{rule_id}.yaml").read_text())
    found = run_rule(RULES[rule_id], configuration(case["clean"]))
    assert [f for f in found if f.rule == rule_id] == []
    # an absence that a node of unknown interface could contradict is one info, at most
    assert [f.rule for f in found] in ([], [rule_id + UNDECIDED])


def test_findings_point_at_the_source_line():
    case = yaml.safe_load((CASES / "global-names.yaml").read_text())
    (finding,) = run_rule(RULES["global-names"], configuration(case["trigger"]))
    assert (finding.location.file, finding.location.line) == ("base/src/driver.cpp", 30)
    assert finding.severity == "info"


def test_a_global_name_from_the_configuration_is_no_global_name_in_code():
    """topic_tools' relay publishes on its output_topic parameter, which relay.launch
    sets to /relay_output: the code wrote no global name (the clean fixture). A global
    default the code writes for the parameter is one."""
    links = [{"kind": "subscribe", "node": "/driver", "name": "/scan", "given": "/scan",
              "type": "sensor_msgs/LaserScan",
              "location": {"file": "base/src/driver.cpp", "line": 31},
              "call": {"kind": "subscribe", "name": "?", "name_param": "topic",
                       "name_default": default}}
             for default in ("/scan", "scan")]
    found = [run_rule(RULES["global-names"], configuration({"links": [link]}))
             for link in links]
    assert [[f.entities for f in each] for each in found] == [
        [("node:/driver", "topic:/scan")], []]


def test_inline_suppressions_in_source_and_launch_files(write_tree):
    root = write_tree({
        "base/src/driver.cpp": "int x;\n// haros-arch: ignore global-names\n"
                               "pub = nh.advertise<nav_msgs::Odometry>(\"/odom\", 1);\n",
        "base/launch/robot.launch": "<launch>\n  <node name=\"a\"/> "
                                    "<!-- haros-arch: ignore duplicate-node-names -->\n"
                                    "  <node name=\"a\"/>\n</launch>\n",
    })
    model = from_data({"configurations": [{"name": "c", "nodes": [
        {"name": "/a", "location": {"file": "base/launch/robot.launch", "line": 2}},
        {"name": "/a", "id": "node:/a#2",
         "location": {"file": "base/launch/robot.launch", "line": 3}}],
        "links": [{"kind": "publish", "node": "/driver", "name": "/odom", "given": "/odom",
                   "queue_size": 1, "location": {"file": "base/src/driver.cpp", "line": 3}},
                  {"kind": "publish", "node": "/driver", "name": "/status", "given": "/status",
                   "location": {"file": "base/src/driver.cpp", "line": 1}}]}]})
    rules = [RULES["global-names"], RULES["duplicate-node-names"]]
    kept = run_catalogue(model, SimpleNamespace(workspace=[str(root)]), rules)
    assert [(f.rule, f.entities) for f in kept] == [
        ("global-names", ("node:/driver", "topic:/status"))]
    unsuppressed = run_catalogue(model, SimpleNamespace(workspace=["/nowhere"]), rules)
    assert len(unsuppressed) == 3


def test_project_queries_haros_rules_and_plugin_user_data_run():
    project = SimpleNamespace(
        path="project.yaml",
        queries=[{"id": "no-cmd-vel", "severity": "error", "title": "No cmd_vel",
                  "query": "topics[self.name == '/cmd_vel']",
                  "message": "{self.name} is used"},
                 "configs/nodes[len(self.remaps) > 0]"],
        rules={"type_check_topics": {
            "name": "Message Types Must Match", "description": "d", "tags": ["x"],
            "scope": "configuration",
            "query": "for p in <nodes/publishers | nodes/subscribers>,\n"
                     "    s in <nodes/publishers | nodes/subscribers>\n"
                     "where p.topic_name == s.topic_name and p.type != s.type\n"
                     "return p, s"}, "not_a_query": {"name": "metric"}},
        configurations=[SimpleNamespace(name="c", user_data={"haros_plugin_pyflwor": [
            {"name": "Query 6 - One Publisher Per Topic",
             "details": "Found {n} topics with multiple publishers - {entities}",
             "query": "topics[len(self.publishers) > 1]"}]})])
    model = from_data({"configurations": [{"name": "c", "nodes": [
        {"name": "/teleop", "remaps": [["cmd", "/cmd_vel"]]}], "links": [
        {"kind": "publish", "node": "/teleop", "name": "/cmd_vel", "type": "a/B"},
        {"kind": "publish", "node": "/planner", "name": "/cmd_vel", "type": "a/B"},
        {"kind": "subscribe", "node": "/base", "name": "/cmd_vel", "type": "a/C"}]}]})
    rules = project_rules(project)
    assert [r.id for r in rules] == ["no-cmd-vel", "project-query-2", "type_check_topics",
                                     "c-query-1"]
    found = run_catalogue(model, project, catalogue=[])
    by_rule: dict[str, list] = {}
    for finding in found:
        by_rule.setdefault(finding.rule, []).append(finding)
    assert by_rule["no-cmd-vel"][0].message == "/cmd_vel is used"
    assert by_rule["no-cmd-vel"][0].severity == "error"
    assert [f.entities for f in by_rule["project-query-2"]] == [("node:/teleop",)]
    # HAROS's rule compares every pair both ways: 2 publishers x 1 subscriber, twice
    assert len(by_rule["type_check_topics"]) == 4
    assert len(by_rule["c-query-1"]) == 1


def test_a_broken_project_query_is_an_error_finding_not_a_crash():
    project = SimpleNamespace(path="p.yaml", queries=["topics[len(self.publishers) >]"],
                              rules={}, configurations=[])
    (finding,) = run_catalogue(from_data({"configurations": [{"name": "c"}]}), project,
                               catalogue=[])
    assert finding.rule == "query-error" and finding.severity == "error"
    assert "^" in finding.message


DOCKING = {"text": "has_dock", "kind": "source", "statement": "if"}


def test_an_action_is_one_finding_not_one_per_wire_topic():
    # a global, partly unknown action name: the action link is reported, not the five
    # topics actionlib puts on the wire for it (``direct_links`` leaves those out)
    wire = [("publish", "goal"), ("publish", "cancel"), ("subscribe", "status"),
            ("subscribe", "feedback"), ("subscribe", "result")]
    model = configuration({"links": [
        {"kind": "action-client", "node": "/ui", "name": "/?/dock", "given": "/?/dock",
         "type": "dock_msgs/Dock", "conditions": [DOCKING]},
        *({"kind": kind, "node": "/ui", "name": f"/?/dock/{suffix}",
           "given": f"/?/dock/{suffix}", "origin": "action", "conditions": [DOCKING]}
          for kind, suffix in wire)]})
    for rule_id in ("global-names", "unresolved-names", "conditional-communication"):
        found = run_rule(RULES[rule_id], model)
        assert [f.entities for f in found] == [("node:/ui", "action:/?/dock")], rule_id
    config = model.configurations[0]
    assert query.compile("direct_links").run(query.config_scope(config, model)) == [
        config.links[0]]
    assert len(query.compile("config/direct_links").run(query.config_scope(config))) == 1


def test_the_same_finding_at_the_same_place_is_said_once():
    # the listener subscribes to /chatter twice (two callbacks): one pair, one warning
    model = configuration({"links": [
        {"kind": "publish", "node": "/talker", "name": "/chatter1", "given": "chatter",
         "type": "std_msgs/String", "location": {"file": "demo/talker.py", "line": 4}},
        *({"kind": "subscribe", "node": "/listener", "name": "/chatter", "given": "chatter",
           "type": "std_msgs/String", "location": {"file": "demo/listener.py", "line": line}}
          for line in (7, 8))]})
    found = run_catalogue(model, None, [RULES["similar-disconnected-topics"]])
    assert [(f.location.file, f.location.line) for f in found] == [("demo/talker.py", 4)]


def test_a_type_mismatch_at_two_client_calls_is_one_finding_naming_both():
    model = configuration({"links": [
        {"kind": "server", "node": "/server", "name": "/add", "type": "a/Add",
         "location": {"file": "a/server.cpp", "line": 10}},
        *({"kind": "client", "node": "/client", "name": "/add", "type": "b/Bad",
           "location": {"file": "b/client.py", "line": line}} for line in (20, 30)),
        {"kind": "action-server", "node": "/server", "name": "/dock", "type": "a/Dock",
         "location": {"file": "a/server.cpp", "line": 12}},
        {"kind": "action-client", "node": "/client", "name": "/dock", "type": "b/Dock",
         "location": {"file": "b/client.py", "line": 40}}]})
    found = run_catalogue(model, None, [RULES["service-type-mismatch"],
                                        RULES["action-type-mismatch"]])
    # one problem, one finding: the client's second call site is a place of the same one
    assert sorted((f.rule, f.location.file, f.location.line, tuple(map(str, f.also)))
                  for f in found) == [
        ("action-type-mismatch", "b/client.py", 40, ()),
        ("service-type-mismatch", "b/client.py", 20, ("b/client.py:30",))]


def test_a_long_value_is_shortened_in_the_message():
    # a binfile's base64 text read as a string: the message names it, not the megabyte
    blob = "QUJD" * 50_000
    model = configuration({
        "parameters": [{"name": "/cam/calib", "type": "binary", "value": blob,
                        "writers": ["<launch>"]}],
        "links": [{"kind": "read", "node": "/cam", "name": "/cam/calib", "type": "str"}]})
    (finding,) = run_rule(RULES["parameter-type-mismatch"], model)
    assert "set as binary (QUJDQUJD" in finding.message and len(finding.message) < 300


def test_a_long_place_keeps_its_line_in_the_message():
    # Autoware's sensor kit: a launch file's path of 118 characters, whose line was cut
    # off as a long value ("gnss.launch.xml:… and gnss.launch.xml:…")
    path = ("autowarefoundation+autoware_launch/sensor_kit/sample_sensor_kit_launch/"
            "sample_sensor_kit_launch/launch/gnss.launch.xml")
    model = configuration({"nodes": [
        {"name": "/sensing/gnss/ublox", "location": {"file": path, "line": 15}},
        {"name": "/sensing/gnss/ublox", "id": "node:/sensing/gnss/ublox#2",
         "location": {"file": path, "line": 37}}]})
    (finding,) = run_rule(RULES["duplicate-node-names"], model)
    assert f"({path} lines 15 and 37)" in finding.message


def test_a_diagnostic_s_message_is_filled_in_whole():
    # Autoware's "node type autoware_lidar_centerpoint/autoware::lidar_centerpoint::
    # LidarCenterPointNode is not in the workspace; its int…": the sentence is the finding
    text = ("node type autoware_lidar_centerpoint/autoware::lidar_centerpoint::"
            "LidarCenterPointNode is not in the workspace; its interface is unknown")
    model = configuration({"diagnostics": [
        {"code": "NODE_NOT_FOUND", "severity": "warning", "message": text,
         "location": {"file": "perception/launch/detection.launch.xml", "line": 7}}]})
    (finding,) = run_rule(RULES["launch-missing-reference"], model)
    assert finding.message == text


def test_a_long_list_is_cut_between_its_items_and_a_long_name_is_whole():
    # Autoware's /service_log, published by 22 nodes: "... /localization/util/default_a…"
    publishers = [f"/localization/util/node_number_{i:02d}" for i in range(22)]
    model = configuration({"links": [
        {"kind": "publish", "node": node, "name": "/service_log", "type": "a/Log"}
        for node in publishers]})
    (finding,) = run_rule(RULES["multiple-publishers"], model)
    assert "…" not in finding.message
    shown = [p for p in publishers if p in finding.message]
    assert 3 <= len(shown) < 22 and f"and {22 - len(shown)} more" in finding.message


def test_a_double_read_as_an_int_is_a_mismatch_only_in_ros_2():
    # roscpp's getParam(int) rounds a double; rospy hands the float on, and its integer
    # default is no type (spencer_people_tracking's visualize_plane.py reads
    # get_param("~z", 0) where the launch file sets -0.02); rclcpp and rclpy throw
    def reader(node: str, file: str) -> dict:
        return {"kind": "read", "node": node, "name": f"{node}/width", "type": "int",
                "location": {"file": file, "line": 3}}

    names = ("/cpp1", "/py1", "/cpp2", "/py2")
    doc = {"parameters": [{"name": f"{n}/width", "type": "double", "value": 6.0,
                           "writers": ["<launch>"]} for n in names],
           "nodes": [{"name": "/cpp1", "node": "a/cpp1"}, {"name": "/py1", "node": "a/py1"},
                     {"name": "/cpp2", "node": "a/cpp2", "ros_version": 2},
                     {"name": "/py2", "node": "a/py2", "ros_version": 2}],
           "links": [reader("/cpp1", "a/src/n.cpp"), reader("/py1", "a/scripts/n.py"),
                     reader("/cpp2", "a/src/n.cpp"), reader("/py2", "a/a/n.py")]}
    found = run_rule(RULES["parameter-type-mismatch"], configuration(doc))
    assert sorted(f.entities[0] for f in found) == ["parameter:/cpp2/width",
                                                    "parameter:/py2/width"]


def test_zero_or_one_read_as_a_bool_is_a_mismatch_but_by_rospy():
    # omniveyor's multi-robot teleop: <param name="use_odom_only" value="0"/>, read by
    # rospy.get_param('~use_odom_only', False) and tested with ``if``; roscpp's
    # getParam(bool) refuses an integer (the node keeps its default), rclpy throws; 2
    # is no boolean's value in any client
    def reader(node: str) -> dict:
        return {"kind": "read", "node": node, "name": f"{node}/flag", "type": "bool",
                "location": {"file": "a/n", "line": 3}}

    names = ("/py1", "/py2", "/cpp1", "/py1two", "/pyros2")
    values = {"/py1two": 2}
    types = {"/py1": ("python", 1), "/py2": ("python", 1), "/cpp1": ("cpp", 1),
             "/py1two": ("python", 1), "/pyros2": ("python", 2)}
    doc = {"packages": [{"name": "a", "nodes": [
               {"name": f"a{n.replace('/', '_')}", "language": language}
               for n, (language, _) in types.items()]}],
           "parameters": [{"name": f"{n}/flag", "type": "int", "value": values.get(n, 0),
                           "writers": ["<launch>"]} for n in names],
           "nodes": [{"name": n, "node": f"a/a{n.replace('/', '_')}", "ros_version": version}
                     for n, (_, version) in types.items()],
           "links": [reader(n) for n in names]}
    found = run_rule(RULES["parameter-type-mismatch"], configuration(doc))
    assert sorted(f.entities[0] for f in found) == [
        "parameter:/cpp1/flag", "parameter:/py1two/flag", "parameter:/pyros2/flag"]


def test_a_list_value_keeps_every_element_in_the_message():
    # navigation_tutorials' y_vels: [-0.3, -0.1, 0.1, -0.3], read as a string
    model = configuration({
        "parameters": [{"name": "/mb/y_vels", "type": "list", "value": [-0.3, -0.1, 0.1, -0.3],
                        "writers": ["<launch>"]}],
        "links": [{"kind": "read", "node": "/mb", "name": "/mb/y_vels", "type": "str"}]})
    (finding,) = run_rule(RULES["parameter-type-mismatch"], model)
    assert "-0.3, -0.1, 0.1, -0.3" in finding.message


def test_a_node_that_also_reads_the_value_as_it_is_set_is_no_mismatch():
    # costmap_2d reads its footprint list as an XmlRpcValue; its dynamic_reconfigure
    # server's string "footprint" keeps its default, which costmap_2d ignores
    def doc(untyped: str | None) -> dict:
        return {"parameters": [{"name": "/mb/costmap/footprint", "type": "list",
                                "value": [[-0.5, -0.3], [0.5, 0.3]], "writers": ["<launch>"]}],
                "links": [{"kind": "read", "node": "/mb", "name": "/mb/costmap/footprint",
                           "type": "str", "location": {"file": "c/src/ros.cpp", "line": 3}},
                          {"kind": "read", "node": "/mb", "name": "/mb/costmap/footprint",
                           "type": untyped, "location": {"file": "c/src/fp.cpp", "line": 9}}]}

    assert run_rule(RULES["parameter-type-mismatch"], configuration(doc(None))) == []
    assert run_rule(RULES["parameter-type-mismatch"], configuration(doc("list"))) == []
    # no read takes the list: both are reported
    found = run_rule(RULES["parameter-type-mismatch"], configuration(doc("int")))
    assert sorted(f.message.rsplit(" ", 1)[-1] for f in found) == ["int", "str"]


UNDECIDED_IDS = [i for i in IDS if "undecided" in yaml.safe_load(
    (CASES / f"{i}.yaml").read_text())]


def test_every_rule_that_claims_an_absence_has_an_undecided_fixture():
    absences = {"parameter-set-not-read", "parameter-read-not-set",
                "subscriber-without-publisher", "publisher-without-subscriber",
                "similar-disconnected-topics", "client-without-server"}
    assert absences <= set(UNDECIDED_IDS) | (absences - set(IDS))
    assert all(RULES[i].undecided_by for i in UNDECIDED_IDS)


@pytest.mark.parametrize("rule_id", UNDECIDED_IDS)
def test_an_absence_an_unknown_node_could_fill_is_no_finding_but_one_info(rule_id):
    case = yaml.safe_load((CASES / f"{rule_id}.yaml").read_text())
    found = run_rule(RULES[rule_id], configuration(case["undecided"]))
    assert [f.rule for f in found] == [rule_id + UNDECIDED]
    (info,) = found
    assert info.severity == "info"
    assert set(case["unseen"]) <= set(info.entities)
    if "conditions" in case:  # undecided by conditions: the message names them
        assert all(c in info.message for c in case["conditions"]), info.message
    else:
        assert all(n.removeprefix("node:") in info.message for n in case["unseen"])
    if "decided" in case:  # an unknown node that cannot be the missing side: still found
        found = run_rule(RULES[rule_id], configuration(case["decided"]))
        assert [f.rule for f in found] == [rule_id], found


def test_a_read_of_a_name_known_only_at_run_time_could_be_the_missing_reader():
    # the HAROS paper's talker: getParam(name read from stdin) may read /frequency
    doc = {"parameters": [{"name": "/frequency", "type": "double", "value": 1.0,
                           "writers": ["<launch>"]}],
           "links": [{"kind": "read", "node": "/talker", "name": "/?", "given": "?"}]}
    model = configuration(doc)
    from haros_arch.graph.candidates import find_candidates

    find_candidates(model.configurations[0])
    found = run_rule(RULES["parameter-set-not-read"], model)
    assert [(f.rule, f.entities) for f in found] == [
        ("parameter-set-not-read" + UNDECIDED, ("node:/talker",))]
    doc["links"][0].update(name="/rate", given="rate")  # a known name: decided
    found = run_rule(RULES["parameter-set-not-read"], configuration(doc))
    assert [f.rule for f in found] == ["parameter-set-not-read"]


def test_a_write_of_a_name_known_only_at_run_time_is_no_missing_reader():
    # duckietown's DTROS writes <node>/? (its DTParam values back to the server): that
    # node reads nothing through it, so a launch setting no node reads is still found;
    # a read of such a name keeps it undecided, and the missing setter of a parameter
    # read and never set may be a write of it
    from haros_arch.graph.candidates import find_candidates

    doc = {"nodes": [{"name": "/lane", "node": "dt/lane"}],
           "parameters": [{"name": "/lane/verbos", "type": "bool", "value": True,
                           "writers": ["<launch>"]},
                          {"name": "/lane/gain", "type": "double"}],
           "links": [{"kind": "write", "node": "/lane", "name": "/lane/?", "given": "~?"},
                     {"kind": "read", "node": "/lane", "name": "/lane/gain",
                      "given": "~gain", "type": "double"}]}
    model = configuration(doc)
    find_candidates(model.configurations[0])
    found = run_rule(RULES["parameter-set-not-read"], model)
    assert [(f.rule, f.entities) for f in found] == [
        ("parameter-set-not-read", ("parameter:/lane/verbos",))]
    found = run_rule(RULES["parameter-read-not-set"], model)
    assert [(f.rule, f.entities) for f in found] == [
        ("parameter-read-not-set" + UNDECIDED, ("node:/lane",))]
    doc["links"][0]["kind"] = "read"
    model = configuration(doc)
    find_candidates(model.configurations[0])
    found = run_rule(RULES["parameter-set-not-read"], model)
    assert [(f.rule, f.entities) for f in found] == [
        ("parameter-set-not-read" + UNDECIDED, ("node:/lane",))]


def test_compressed_image_topics_are_alike_by_the_name_before_the_transport():
    # duckietown's line_detector publishes ~debug/segments/compressed and
    # anti_instagram subscribes camera_node/image/compressed (both CompressedImage,
    # neither with a partner): alike only by image_transport's suffix, no pair; a
    # subscriber of .../image/compressed beside a publisher of .../imag/compressed is
    def doc(published: str) -> dict:
        return {"links": [{"kind": "publish", "node": "/det", "name": published,
                           "given": published, "type": "sensor_msgs/CompressedImage"},
                          {"kind": "subscribe", "node": "/ai",
                           "name": "/cam/image/compressed", "given": "image/compressed",
                           "type": "sensor_msgs/CompressedImage"}]}

    rule = RULES["similar-disconnected-topics"]
    assert run_rule(rule, configuration(doc("/det/debug/segments/compressed"))) == []
    assert [f.rule for f in run_rule(rule, configuration(doc("/det/imag/compressed")))] == [
        "similar-disconnected-topics"]
    assert [f.rule for f in run_rule(rule, configuration(doc("/det/image/compressed")))] == [
        "similar-disconnected-topics"]


def test_a_read_with_a_whole_unknown_segment_could_read_the_name_without_it():
    # autorally's serial ports read nodeName + (handle.empty() ? "" : "/" + handle) +
    # "/serialBaud": ~?/serialBaud, resolved /port/?/serialBaud; with the handle empty
    # roscpp cleans "//" and reads /port/serialBaud, which the launch file sets
    from haros_arch.graph.candidates import find_candidates

    doc = {"parameters": [{"name": "/port/serialBaud", "type": "int", "value": 9600,
                           "writers": ["<launch>"]},
                          {"name": "/port/other/rate", "type": "int", "value": 1,
                           "writers": ["<launch>"]}],
           "links": [{"kind": "read", "node": "/port", "name": "/port/?/serialBaud",
                      "given": "~?/serialBaud"}]}
    model = configuration(doc)
    find_candidates(model.configurations[0])
    found = run_rule(RULES["parameter-set-not-read"], model)
    assert sorted((f.rule, f.entities) for f in found) == [
        ("parameter-set-not-read", ("parameter:/port/other/rate",)),
        ("parameter-set-not-read" + UNDECIDED, ("node:/port",))]


def test_a_rule_that_hits_the_step_budget_is_a_query_limit_warning(monkeypatch):
    from haros_arch.query import catalogue
    from haros_arch.query.command import _exit_code

    monkeypatch.setattr(catalogue, "STEPS", 50)
    model = configuration({"links": [
        {"kind": "publish", "node": f"/n{i}", "name": f"/t{i}", "type": "a/B"}
        for i in range(40)]})
    rule = catalogue.Rule("pairs", "error", "Pairs",
                          "for a in <links>, b in <links> where a.name != b.name return a")
    (finding,) = run_rule(rule, model)
    assert (finding.rule, finding.severity) == ("query-limit", "warning")
    assert "steps" in finding.message and "Query pairs" in finding.title
    assert _exit_code([finding], [], "error") == 0


def test_a_dynamic_reconfigure_server_reads_its_private_parameters_unseen():
    # velodyne's LaserScanNodelet: dynamic_reconfigure reads "ring" from its .cfg
    doc = {"parameters": [
        {"name": "/laserscan/ring", "type": "int", "value": -1, "writers": ["<launch>"]},
        {"name": "/driver/rpm", "type": "double", "value": 600.0, "writers": ["<launch>"]}],
        "links": [{"kind": "publish", "node": "/laserscan",
                   "name": "/laserscan/parameter_updates", "given": "~parameter_updates"},
                  {"kind": "publish", "node": "/driver", "name": "/packets"}]}
    found = run_rule(RULES["parameter-set-not-read"], configuration(doc))
    assert sorted((f.rule, f.entities) for f in found) == [
        ("parameter-set-not-read", ("parameter:/driver/rpm",)),
        ("parameter-set-not-read" + UNDECIDED, ("node:/laserscan",))]


def test_a_dynamic_reconfigure_server_leaves_undecided_only_its_own_namespace():
    # move_base's local planner serves on NodeHandle("~/DWAPlannerROS"); a controller on
    # the gazebo node serves on its own handle, a shared namespace; a costmap layer's
    # handle is "~/" + a name unknown statically
    doc = {"parameters": [
        {"name": name, "type": "double", "value": 1.0, "writers": ["<launch>"]}
        for name in ("/move_base/DWAPlannerROS/max_vel_x", "/move_base/controller_frequency",
                     "/wheels/wheel_radius", "/joints/publish_rate",
                     "/planner/costmap/inflation/radius", "/planner/rate")],
        "links": [{"kind": "publish", "node": "/move_base",
                   "name": "/move_base/DWAPlannerROS/parameter_updates",
                   "given": "~DWAPlannerROS/parameter_updates"},
                  {"kind": "server", "node": "/gazebo", "name": "/wheels/set_parameters",
                   "type": "dynamic_reconfigure/Reconfigure"},
                  {"kind": "publish", "node": "/planner",
                   "name": "/planner/costmap/?/parameter_updates",
                   "given": "~costmap/?/parameter_updates"}]}
    found = run_rule(RULES["parameter-set-not-read"], configuration(doc))
    assert sorted((f.rule, f.entities) for f in found) == [
        ("parameter-set-not-read", ("parameter:/joints/publish_rate",)),
        ("parameter-set-not-read", ("parameter:/move_base/controller_frequency",)),
        ("parameter-set-not-read", ("parameter:/planner/rate",)),
        ("parameter-set-not-read" + UNDECIDED, ("node:/gazebo", "node:/move_base",
                                               "node:/planner"))]


def test_a_catalogue_folder_is_read_again_when_a_file_changes(tmp_path) -> None:
    from haros_arch.query.catalogue import load_catalogue

    rule = tmp_path / "r.yaml"
    rule.write_text("id: r\nseverity: info\ntitle: One\nquery: nodes\n")
    assert [r.title for r in load_catalogue(tmp_path)] == ["One"]
    assert load_catalogue(tmp_path) == load_catalogue(tmp_path)  # kept while unchanged
    rule.write_text("id: r\nseverity: info\ntitle: Second\nquery: nodes\n")
    assert [r.title for r in load_catalogue(tmp_path)] == ["Second"]


@pytest.mark.parametrize("kinds", [("publish", "subscribe", "topic-type-mismatch"),
                                   ("server", "client", "service-type-mismatch"),
                                   ("action-server", "action-client",
                                    "action-type-mismatch")])
def test_a_type_not_known_statically_is_no_mismatch(kinds):
    """A call the parse could not resolve is typed '?': its type is not known, and the
    type checks do not compare it as a type (they reported 'publishes /t as ?')."""
    one, other, rule = kinds
    for unknown in ("?", "pkg/msg/?"):
        model = configuration({"links": [
            {"kind": one, "node": "/a", "name": "/t", "type": unknown,
             "location": {"file": "a/a.cpp", "line": 1}},
            {"kind": other, "node": "/b", "name": "/t", "type": "std_msgs/msg/String",
             "location": {"file": "b/b.cpp", "line": 2}}]})
        assert run_catalogue(model, None, [RULES[rule]]) == []
    # a known type that differs is still one
    model = configuration({"links": [
        {"kind": one, "node": "/a", "name": "/t", "type": "std_msgs/msg/Int32",
         "location": {"file": "a/a.cpp", "line": 1}},
        {"kind": other, "node": "/b", "name": "/t", "type": "std_msgs/msg/String",
         "location": {"file": "b/b.cpp", "line": 2}}]})
    assert [f.rule for f in run_catalogue(model, None, [RULES[rule]])] == [rule]


def test_a_name_not_known_statically_is_no_qos_incompatibility():
    """Two names with '?' print alike (``/?``) whatever topics they stand for: a
    publisher and a subscriber whose names both come from values not known statically
    are no pair (create3_sim: every node's parameter-named topics met /ros_gz_sim's on
    /?, 25 errors). The other pairwise checks already skip them."""
    def links(name: str) -> list[dict]:
        return [{"kind": "publish", "node": "/a", "name": name, "type": "std_msgs/msg/String",
                 "qos": {"reliability": "best_effort"}, "location": {"file": "a.cpp", "line": 1}},
                {"kind": "subscribe", "node": "/b", "name": name, "type": "std_msgs/msg/String",
                 "qos": {"reliability": "reliable"}, "location": {"file": "b.cpp", "line": 2}}]
    rule = RULES["qos-incompatible"]
    for name in ("/?", "/robot/?/scan"):
        assert run_catalogue(configuration({"links": links(name)}), None, [rule]) == []
    assert [f.rule for f in run_catalogue(configuration({"links": links("/scan")}), None,
                                          [rule])] == ["qos-incompatible"]


def test_a_finding_about_a_topic_points_at_a_publisher():
    """multiple-publishers reports a topic: its place is a publisher's, not that of the
    topic's first link when that is a subscriber (create3_sim: /dock_status, published
    twice, was shown at docking_behavior.cpp:27, a subscription)."""
    model = configuration({"links": [
        {"kind": "subscribe", "node": "/user", "name": "/dock", "type": "std_msgs/msg/String",
         "location": {"file": "user.cpp", "line": 27}},
        {"kind": "publish", "node": "/a", "name": "/dock", "type": "std_msgs/msg/String",
         "location": {"file": "a.cpp", "line": 5}},
        {"kind": "publish", "node": "/b", "name": "/dock", "type": "std_msgs/msg/String",
         "location": {"file": "b.cpp", "line": 9}}]})
    [found] = run_catalogue(model, None, [RULES["multiple-publishers"]])
    assert (found.location.file, found.location.line) == ("a.cpp", 5)


def test_two_instances_of_one_name_are_counted_in_a_message():
    """create3_sim includes one launch file twice: two /sensors_node publish
    /dock_status, and multiple-publishers said "/dock_status is published by
    /sensors_node", one name, as if one node published it. (A ROS 2 launch: two ROS 1
    nodes of one name never run together, test_query_ros1_one_name_runs_once.)"""
    model = configuration({
        "nodes": [{"name": "/sensors", "node": "k/sensors", "id": "node:/sensors",
                   "ros_version": 2},
                  {"name": "/sensors", "node": "k/sensors", "id": "node:/sensors#2",
                   "ros_version": 2}],
        "links": [
            {"kind": "publish", "node": "/sensors", "node_id": "node:/sensors",
             "name": "/dock", "type": "std_msgs/msg/String",
             "location": {"file": "a.cpp", "line": 5}},
            {"kind": "publish", "node": "/sensors", "node_id": "node:/sensors#2",
             "name": "/dock", "type": "std_msgs/msg/String",
             "location": {"file": "a.cpp", "line": 5}}]})
    [found] = run_catalogue(model, None, [RULES["multiple-publishers"]])
    assert found.message == "/dock is published by /sensors (2 instances)"


def test_similar_disconnected_topics_leaves_names_not_known_out():
    """OrbbecSDK_ROS2: once its driver was read whole, 64 warnings paired topics whose
    names hold '?' (``/camera_01/?`` with ``/start_benchmark/?``, a publisher of
    ``/?/depth_to_color/image_raw`` with a subscriber of ``/?/color/image_raw``): a name
    not known may be the other's, or have a partner; every other absence rule leaves
    such names out (unresolved-names lists them)."""
    def pair(published: str, subscribed: str) -> object:
        return configuration({"links": [
            {"kind": "publish", "node": "/cam", "name": published, "given": published,
             "type": "sensor_msgs/Image"},
            {"kind": "subscribe", "node": "/bench", "name": subscribed,
             "given": subscribed, "type": "sensor_msgs/Image"}]})
    rule = RULES["similar-disconnected-topics"]
    assert len(run_rule(rule, pair("/cam/image", "/bench/image"))) == 1
    assert run_rule(rule, pair("/cam/?", "/bench/?")) == []
    assert run_rule(rule, pair("/?/depth/image_raw", "/?/color/image_raw")) == []


def test_similar_disconnected_topics_a_name_not_known_may_be_the_subscribers_partner():
    """OrbbecSDK_ROS2's multi_camera: each camera publishes its images on names made
    from a map filled at run time (``stream_name_[i] + "/image_raw"``: ``/camera_02/?``)
    and its D2C viewer subscribes ``color/image_raw``: camera_01's
    ``depth_to_color/image_raw`` with camera_02's ``color/image_raw`` were said to have
    no partner, while camera_02's own ``?`` publisher may well be the subscriber's (as
    subscriber-without-publisher says: not decided). A subscriber of ``?`` beside the
    publisher's topic makes the pair undecided already; the publisher's side now too."""
    from haros_arch.graph.candidates import find_candidates

    def run(unknown_kind: str | None) -> list[str]:
        links = [{"kind": "publish", "node": "/cam1", "name": "/cam1/depth_to_color/image",
                  "given": "depth_to_color/image", "type": "sensor_msgs/msg/Image"},
                 {"kind": "subscribe", "node": "/cam2", "name": "/cam2/color/image",
                  "given": "color/image", "type": "sensor_msgs/msg/Image"}]
        if unknown_kind is not None:
            links.append({"kind": unknown_kind, "node": "/cam2", "name": "/cam2/?",
                          "given": "?", "type": "sensor_msgs/msg/Image"})
        model = configuration({"links": links})
        find_candidates(model.configurations[0])
        return [f.rule for f in run_rule(RULES["similar-disconnected-topics"], model)]

    assert run(None) == ["similar-disconnected-topics"]
    # a publisher of a name not known may publish /cam2/color/image
    assert run("publish") == ["similar-disconnected-topics" + UNDECIDED]
    # a subscriber of one is no publisher: the pair stands
    assert run("subscribe") == ["similar-disconnected-topics"]


def test_similar_disconnected_topics_pairs_a_topic_with_its_closest_partners():
    """cybership_software_suite's drillship simulator publishes six thrusters'
    ``/cybership/thruster/<name>/issued`` and its rviz file shows
    ``/drillship/thruster/<name>/issued``: every publisher was paired with every
    display (36 warnings), though each has one of its own name, which shares more of its
    last segments (``thruster/bow_port/issued``) than the others (``issued``). A pair is
    said only when neither topic has a partner closer by that measure; the same
    name in another namespace is said, and a pair with no closer one stays."""
    def run(published: list[str], subscribed: list[str]) -> list[str]:
        links = [{"kind": "publish", "node": "/sim", "name": n, "given": n,
                  "type": "geometry_msgs/msg/WrenchStamped"} for n in published]
        links += [{"kind": "subscribe", "node": "/rviz", "name": n, "given": n,
                   "type": "geometry_msgs/msg/WrenchStamped"} for n in subscribed]
        found = run_rule(RULES["similar-disconnected-topics"], configuration({"links": links}))
        return sorted(f.message.split(" and ")[0].split()[-1] + " "
                      + f.message.split("subscribes to ")[1].split()[0] for f in found)

    names = ["bow_port", "bow_center", "stern_port"]
    assert run([f"/cybership/thruster/{n}/issued" for n in names],
               [f"/drillship/thruster/{n}/issued" for n in names]) == sorted(
        f"/cybership/thruster/{n}/issued /drillship/thruster/{n}/issued" for n in names)
    # no closer partner on either side: the pair stays
    assert run(["/a/cmd_vel"], ["/b/cmd_vel"]) == ["/a/cmd_vel /b/cmd_vel"]
    # the subscriber's only partner has a closer one: that one is said
    assert run(["/a/base/cmd_vel"], ["/b/base/cmd_vel", "/c/cmd_vel"]) == [
        "/a/base/cmd_vel /b/base/cmd_vel"]


def test_an_int_read_as_a_double_is_a_mismatch_only_in_ros_2():
    # ROS 1 takes an integer where a double is read; ROS 2's statically typed
    # parameters refuse it (leo_robot-ros2 8014e18c^ gave rosbridge_websocket
    # unregister_timeout 86400, which it declares as 10.0: the node does not start)
    def reader(node: str) -> dict:
        return {"kind": "declare", "node": node, "name": f"{node}/timeout", "type": "double",
                "location": {"file": "a/n.py", "line": 3}}

    doc = {"parameters": [{"name": f"{n}/timeout", "type": "int", "value": 86400,
                           "writers": ["<launch>"]} for n in ("/one", "/two")],
           "nodes": [{"name": "/one", "node": "a/one"},
                     {"name": "/two", "node": "a/two", "ros_version": 2}],
           "links": [reader("/one"), reader("/two")]}
    (found,) = run_rule(RULES["parameter-type-mismatch"], configuration(doc))
    assert found.entities[0] == "parameter:/two/timeout"
    assert found.message == "/two/timeout is set as int (86400) but /two reads it as double"


def test_a_shape_shifter_carries_any_type():
    """topic_tools' ShapeShifter is roscpp's any-message (md5sum ``*``): a subscriber of
    it connects to a publisher of any type, and a publisher of it (topic_tools' relay,
    ``ShapeShifter::advertise``) publishes the type it received. imu_transformer's
    nodelet subscribes to ``imu_in/mag`` as a ShapeShifter and instantiates a
    MagneticField or a Vector3Stamped: a MagneticField publisher there was an error
    'publishes /imu_in/mag as sensor_msgs/MagneticField but ... subscribes to it as
    topic_tools/ShapeShifter'. Two known types that differ are still one."""
    rule = RULES["topic-type-mismatch"]
    for shifter in ("subscribe", "publish"):
        other = "publish" if shifter == "subscribe" else "subscribe"
        model = configuration({"links": [
            {"kind": shifter, "node": "/a", "name": "/t", "type": "topic_tools/ShapeShifter",
             "location": {"file": "a/a.cpp", "line": 1}},
            {"kind": other, "node": "/b", "name": "/t", "type": "sensor_msgs/MagneticField",
             "location": {"file": "b/b.py", "line": 2}}]})
        assert run_catalogue(model, None, [rule]) == []
    model = configuration({"links": [
        {"kind": "publish", "node": "/a", "name": "/t", "type": "geometry_msgs/Vector3Stamped",
         "location": {"file": "a/a.cpp", "line": 1}},
        {"kind": "subscribe", "node": "/b", "name": "/t", "type": "sensor_msgs/MagneticField",
         "location": {"file": "b/b.py", "line": 2}}]})
    assert [f.rule for f in run_catalogue(model, None, [rule])] == ["topic-type-mismatch"]
