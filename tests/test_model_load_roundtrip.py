"""A saved JSON model reads back with the call-level facts that queries use, and a
reloaded model answers queries exactly like the one in memory."""

from __future__ import annotations

import json
import os

import pytest
from conftest import FIXTURES, ROOT

from haros_arch import query
from haros_arch.model.load import from_data
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

# the example (actions, parameters, ROS 1 and 2); the fleet (a duplicate node name,
# configuration hints that add links no node type lists); nodes from interface models, a
# plugin host and a spawner (node types no package lists, calls no node type lists, two
# calls of one kind at one place)
PROJECTS = [ROOT / "examples/project.yaml", FIXTURES / "graph_fleet/project.yaml",
            FIXTURES / "cache_readback/project.yaml"]


def saved_and_reloaded(path):
    model = analyse(load(str(path)), {"PATH": os.environ["PATH"]})
    data = json.loads(json.dumps(model_to_data(model)))
    return model, data, from_data(data)


@pytest.fixture(scope="module", params=PROJECTS, ids=lambda p: p.parent.name)
def models(request):
    return saved_and_reloaded(request.param)


def test_round_trip_keeps_links_calls_and_instances(models):
    model, data, again = models
    for before, after in zip(model.configurations, again.configurations, strict=True):
        assert [(n.id, n.ros_version, n.origin) for n in before.nodes] == [
            (n.id, n.ros_version, n.origin) for n in after.nodes]
        assert [(link.kind, link.name, link.origin, link.node.id) for link in before.links] \
            == [(link.kind, link.name, link.origin, link.node.id) for link in after.links]
        # every link has its call, as the graph made it: source calls, a configuration
        # hint's calls, and the topics and services an action stands for on the wire
        assert all(link.call is not None for link in after.links)
        assert [link.call for link in before.links] == [link.call for link in after.links]
    assert json.loads(json.dumps(model_to_data(again)))["configurations"] == data[
        "configurations"]


def test_a_reloaded_model_answers_queries_like_the_one_in_memory(models):
    model, _data, again = models
    assert run_catalogue(again) == run_catalogue(model)
    text = "links[self.origin == 'action' or self.origin == 'hint']/call/location"
    for before, after in zip(model.configurations, again.configurations, strict=True):
        expected = query.compile(text).run(query.config_scope(before, model))
        assert query.compile(text).run(query.config_scope(after, again)) == expected


def test_reads_keep_their_defaults():
    _model, _data, again = saved_and_reloaded(ROOT / "examples/project.yaml")
    robot = again.configuration("robot")
    threshold = robot.parameter("/robot1/battery/threshold")
    assert threshold.readers[0].call.has_default and threshold.readers[0].call.default == 0.2


def test_a_packages_plugin_exports_read_back():
    from haros_arch.model.source import Package, Plugin

    package = Package("p", "src/p", plugins=[Plugin("nav2_core", "p/plugins.xml"),
                                             Plugin("nodelet", "p/nodelets.xml")])
    data = json.loads(json.dumps({"packages": [model_to_data_of(package)]}))
    assert from_data(data).packages[0].plugins == package.plugins


def model_to_data_of(package):
    from haros_arch.model.model import Model

    return model_to_data(Model("m", packages=[package]))["packages"][0]


def test_node_types_no_package_lists_read_back_whole():
    """An instance's node type that no package lists (a command's arguments make the
    spawner's) reads back with its model, language and calls (they were rebuilt from the
    links: language "cpp", no model, calls without their defaults)."""
    model, data, again = saved_and_reloaded(FIXTURES / "cache_readback/project.yaml")
    listed = {id(n) for n in model.nodes}
    modelled = [i for c in model.configurations for i in c.nodes if id(i.node) not in listed]
    # amcl's and move_base's are their packages' (move_base's plugins, noetic NavfnROS
    # and DWAPlannerROS, are modelled whole: DWAPlannerROS's model reads the classes of
    # base_local_planner it builds), the spawner's its arguments'
    assert [i.name for i in modelled] == ["/spawner"]
    assert len(data["configurations"][0]["node_types"]) == 1
    host = next(i.node for i in model.configurations[0].nodes if i.name == "/move_base")
    assert host.completeness == "model" and not host.completeness_reasons
    for before, after in zip(model.configurations, again.configurations, strict=True):
        for one, other in zip(before.nodes, after.nodes, strict=True):
            assert (one.node.name, one.node.language, one.node.model, one.node.calls,
                    one.node.completeness, one.node.completeness_reasons) == (
                other.node.name, other.node.language, other.node.model, other.node.calls,
                other.node.completeness, other.node.completeness_reasons)
    spawner = again.configurations[0].nodes[2].node
    assert spawner.language == "python" and spawner.model is not None
