"""A ROS 2 process whose code makes its second node only under a condition
(``fixtures/cpp/conditional_node``: ublox_gps' ``raw_data_pa``, made only when
``raw_data_stream.enable`` is set, in another file than the node's own code): that node
and everything it does exist only under the condition, so the launch name that renames
both nodes is no certain duplicate."""

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
from haros_arch.query import run_catalogue

CASE = FIXTURES / "cpp" / "conditional_node"
CONDITION = 'get_parameter("raw_stream.enable").as_bool()'


@pytest.fixture(scope="module")
def model() -> Model:
    return analyse(load(str(CASE / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def test_the_second_node_s_calls_hold_the_condition_of_its_construction(model: Model) -> None:
    (node,) = [n for p in model.packages for n in p.nodes]
    assert node.rosnames == ["gps_driver", "raw_logger"]
    assert [(c.name, [k.text for k in c.conditions]) for c in node.calls_of("raw_logger")
            ] == [("raw_stream", [CONDITION])]
    assert all(not c.conditions for c in node.calls_of("gps_driver"))


def test_the_instance_exists_under_it_and_the_clash_is_undecided(model: Model) -> None:
    (config,) = model.configurations
    assert [(n.id, n.code_name, [k.text for k in n.conditions]) for n in config.nodes] == [
        ("node:/gps", "gps_driver", []), ("node:/gps#2", "raw_logger", [CONDITION])]
    found = [(f.rule, f.severity) for f in run_catalogue(model) if "duplicate" in f.rule]
    assert found == [("duplicate-node-names-undecided", "info")]
    again = from_data(json.loads(json.dumps(model_to_data(model))))
    assert [k.text for k in again.configurations[0].nodes[1].conditions] == [CONDITION]
