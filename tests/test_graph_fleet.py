"""fixtures/graph_fleet: namespaces, remaps at every level, hints, conditions, collisions."""

from __future__ import annotations

import os

import pytest
from conftest import FIXTURES

from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_rule


@pytest.fixture(scope="module")
def model():
    project = load(str(FIXTURES / "graph_fleet/project.yaml"))
    return analyse(project, {"PATH": os.environ.get("PATH", "")})


@pytest.fixture(scope="module")
def two(model):
    return model.configuration("two_robots")


def publishers(config, topic):
    found = config.topic(topic)
    assert found is not None, topic
    return sorted(link.node.name for link in found.publishers)


def test_namespaces_from_groups_and_includes(two):
    assert sorted(n.name for n in two.nodes) == [
        "/logger", "/robot_a/driver", "/robot_a/planner", "/robot_b/driver",
        "/robot_b/driver", "/robot_b/planner"]


def test_launch_level_remap_reaches_included_nodes(two):
    assert publishers(two, "/robot_a/wheels") == ["/robot_a/planner"]
    wheels = two.topic("/robot_a/wheels")
    assert [link.rosname.given for link in wheels.links] == ["cmd_vel", "wheels"]


def test_group_remap_and_command_line_remap(two):
    assert publishers(two, "/fleet_status") == ["/robot_b/driver"]
    spare = two.topic("/spare")
    assert spare is not None
    assert [link.node.name for link in spare.subscribers] == ["/robot_b/driver"]
    # the second /robot_b/driver is outside the group: its status is not remapped
    assert publishers(two, "/robot_b/status") == ["/robot_b/driver"]


def test_private_names(two):
    assert publishers(two, "/robot_a/planner/debug") == ["/robot_a/planner"]
    rate = two.parameter("/robot_a/driver/rate")
    assert rate is not None and rate.value == 20
    assert [link.node.name for link in rate.readers] == ["/robot_a/driver"]


def test_hints_complete_unknown_names_and_describe_missing_nodes(model, two):
    assert publishers(two, "/robot_a/plan") == ["/robot_a/planner"]
    assert two.topic("/robot_a/plan").publishers[0].origin == "hint"
    unresolved = [t.name for t in two.topics if t.is_unresolved]
    # read at run time, so it may be global: in no namespace
    assert unresolved == ["?"]
    logger = two.node("/logger")
    assert logger is not None and logger.node is not None
    assert [(link.kind, link.name) for link in logger.links] == [
        ("subscribe", "/robot_a/status")]
    unknown = model.configuration("unknown_switch")
    assert [t.name for t in unknown.topics if t.is_unresolved] == ["?", "?"]


def test_unknown_argument_makes_the_node_conditional(model):
    config = model.configuration("unknown_switch")
    logger = config.node("/logger")
    assert [(c.kind, c.statement, c.text) for c in logger.conditions] == [
        ("launch", "if", "$(arg with_logger)")]
    assert model.configuration("two_robots").node("/logger").conditions == ()


def test_collision_is_reported_once(model, two):
    found = [(d.code, d.location.file, d.location.line) for d in two.diagnostics
             if "DUPLICATE" in d.code]
    assert found == [("LAUNCH_NODE_DUPLICATE", "fleet/launch/fleet.launch", 15)]
    ids = [n.id for n in two.nodes if n.name == "/robot_b/driver"]
    assert len(set(ids)) == 2
    # roslaunch refuses it already: the catalogue query does not say it again
    (rule,) = [r for r in load_catalogue() if r.id == "duplicate-node-names"]
    assert run_rule(rule, model) == []


def test_candidates_for_the_unknown_plan_topic(model):
    config = model.configuration("unknown_switch")
    unknown_a = next(t for t in config.topics if t.name == "?"
                     and t.links[0].node.namespace == "/robot_a/")
    # same type (std_msgs/String), the publisher's namespace first; the name, read at
    # run time, may be any other robot's too
    names = [c.name for c in unknown_a.candidates]
    assert names[:1] == ["/robot_a/status"]
    assert "/robot_b/status" in names
    assert "/robot_a/wheels" not in names  # geometry_msgs/Twist
