"""A saved JSON model reads back with the call-level facts that queries use."""

from __future__ import annotations

import json
import os

from conftest import ROOT

from haros_arch.model.load import from_data
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import analyse
from haros_arch.project import load


def test_round_trip_keeps_links_calls_and_instances():
    model = analyse(load(str(ROOT / "examples/project.yaml")), {"PATH": os.environ["PATH"]})
    data = json.loads(json.dumps(model_to_data(model)))
    again = from_data(data)
    for before, after in zip(model.configurations, again.configurations, strict=True):
        assert [(n.name, n.ros_version, n.origin) for n in before.nodes] == [
            (n.name, n.ros_version, n.origin) for n in after.nodes]
        assert [(link.kind, link.name, link.origin) for link in before.links] == [
            (link.kind, link.name, link.origin) for link in after.links]
        with_call = [link for link in after.links if link.origin == "source"]
        assert all(link.call is not None for link in with_call if link.node.node is not None)
    robot = again.configuration("robot")
    threshold = robot.parameter("/robot1/battery/threshold")
    assert threshold.readers[0].call.has_default and threshold.readers[0].call.default == 0.2
    assert json.loads(json.dumps(model_to_data(again)))["configurations"] == data[
        "configurations"]
