"""Several ROS 2 nodes in one Python process (``fixtures/python/several_nodes``): each is
a node instance of its own with its own calls, named as ROS 2 names them."""

from __future__ import annotations

import json
import os

import pytest
from conftest import FIXTURES

from haros_arch.model.load import from_data
from haros_arch.model.model import Model
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_rule

CASE = FIXTURES / "python" / "several_nodes"


@pytest.fixture(scope="module")
def model() -> Model:
    return analyse(load(str(CASE / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def links(model: Model, node: str) -> list[tuple[str, str]]:
    config = model.configuration("pair")
    return sorted((link.kind, link.name) for link in config.links if link.node.name == node)


def test_the_executable_knows_its_nodes_and_each_call_its_node(model: Model) -> None:
    pair = {n.executable: n for p in model.packages for n in p.nodes}["pair"]
    assert pair.rosnames == ["sensor", "monitor"]
    assert {(c.kind, c.name, c.node_name) for c in pair.calls} >= {
        ("declare", "rate", "sensor"), ("publish", "reading", "sensor"),
        ("subscribe", "reading", "monitor"), ("publish", "~alarm", "monitor"),
        ("action-server", "calibrate", "monitor")}


def test_unnamed_launch_node_gives_one_instance_per_ros_node(model: Model) -> None:
    config = model.configuration("pair")
    names = [n.name for n in config.nodes]
    assert names[:2] == ["/plant/sensor", "/plant/monitor"]
    # the namespace and the remap apply to both nodes of the process
    assert links(model, "/plant/sensor") == [
        ("publish", "/plant/temperature"), ("read", "/plant/sensor/rate")]
    assert ("subscribe", "/plant/temperature") in links(model, "/plant/monitor")
    assert ("publish", "/plant/monitor/alarm") in links(model, "/plant/monitor")
    assert ("action-server", "/plant/calibrate") in links(model, "/plant/monitor")
    topic = next(t for t in config.topics if t.name == "/plant/temperature")
    assert [p.node.name for p in topic.publishers] == ["/plant/sensor"]
    assert [s.node.name for s in topic.subscribers] == ["/plant/monitor"]


def test_launch_parameters_of_the_process_reach_each_node(model: Model) -> None:
    config = model.configuration("pair")
    rate = config.parameter("/plant/sensor/rate")
    assert rate is not None and rate.set_by_launch and rate.value == 5.0
    assert config.parameter("/plant/monitor/rate").set_by_launch
    assert config.parameter("/plant/?/rate") is None


def test_enable_logger_service_serves_the_logger_levels(model: Model) -> None:
    served = [(link.name, link.type) for link in model.configuration("pair").links
              if link.kind == "server" and link.node.name == "/plant/monitor"
              and "/_action/" not in link.name]
    assert served == [
        ("/plant/monitor/get_logger_levels", "rcl_interfaces/srv/GetLoggerLevels"),
        ("/plant/monitor/set_logger_levels", "rcl_interfaces/srv/SetLoggerLevels")]
    assert not [link for link in model.configuration("pair").links
                if link.kind == "server" and link.node.name == "/plant/sensor"]


def test_launch_name_renames_every_node_of_the_process(model: Model) -> None:
    config = model.configuration("pair")
    wheels = [n for n in config.nodes if n.name == "/wheels"]
    assert len(wheels) == 2  # rcl gives both nodes the name: a real clash, reported
    assert [len(n.links) for n in wheels] == [1, 2]  # left: status; right: status, command
    # said once, by the duplicate-node-names query (ROS 2 launch does not refuse it)
    (rule,) = [r for r in load_catalogue() if r.id == "duplicate-node-names"]
    found = [f for f in run_rule(rule, model) if f.configuration == "pair"]
    assert [f.entities for f in found] == [("node:/wheels", "node:/wheels#2")]
    # one launch action, not two: the message says the name renamed both nodes
    assert [n.code_name for n in wheels] == ["left_wheel", "right_wheel"]
    assert found[0].message.endswith(
        "; one process: the launch file's name renames every node its code makes, "
        "left_wheel and right_wheel")
    # kept in the saved model
    again = from_data(json.loads(json.dumps(model_to_data(model))))
    assert [n.code_name for n in again.configuration("pair").nodes
            if n.name == "/wheels"] == ["left_wheel", "right_wheel"]


def test_the_model_round_trips_and_single_node_json_is_unchanged(model: Model) -> None:
    data = json.loads(json.dumps(model_to_data(model)))
    nodes = {f'{n["package"]}/{n["executable"]}': n for p in data["packages"]
             for n in p["nodes"]}
    assert nodes["pair_nodes/pair"]["rosnames"] == ["sensor", "monitor"]
    assert all("node_name" in c for c in nodes["pair_nodes/pair"]["calls"])
    again = from_data(data)
    pair = {n.name: n for p in again.packages for n in p.nodes}["pair_nodes/pair"]
    assert pair.rosnames == ["sensor", "monitor"]
    assert [c.node_name for c in pair.calls] == [
        c.node_name for p in model.packages for n in p.nodes if n.name == "pair_nodes/pair"
        for c in n.calls]
    # an old document (no rosnames, no node_name) loads, and one node keeps them out
    for node in (n for p in data["packages"] for n in p["nodes"]):
        node.pop("rosnames", None)
        for call in node["calls"]:
            call.pop("node_name", None)
    old = from_data(data)
    assert all(not n.rosnames for p in old.packages for n in p.nodes)
    single = json.loads(json.dumps(model_to_data(old)))
    assert all("rosnames" not in n and all("node_name" not in c for c in n["calls"])
               for p in single["packages"] for n in p["nodes"])


def test_launch_name_that_is_one_nodes_own_name_still_says_one_process(tmp_path) -> None:
    """doosan-robot2's dsr_control_node2: the launch names the process after the node its
    code names so (``name='dsr_control_node2'``), and the code makes a second node,
    ``stop_subscriber_node``, which the launch name renames too. Only the second
    instance has a code name of its own; the message still says why the two clash."""
    import shutil

    shutil.copytree(CASE, tmp_path / "case")
    launch = tmp_path / "case" / "src" / "pair_bringup" / "launch" / "pair.launch.py"
    launch.write_text(launch.read_text().replace("name='wheels'", "name='left_wheel'"))
    model = analyse(load(str(tmp_path / "case" / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    config = model.configuration("pair")
    wheels = [n for n in config.nodes if n.name == "/left_wheel"]
    assert [n.code_name for n in wheels] == [None, "right_wheel"]
    (rule,) = [r for r in load_catalogue() if r.id == "duplicate-node-names"]
    (found,) = [f for f in run_rule(rule, model) if f.configuration == "pair"]
    assert found.message.endswith(
        "; one process: the launch file's name renames every node its code makes, "
        "left_wheel and right_wheel")
