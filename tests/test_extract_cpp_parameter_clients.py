"""rclcpp parameter clients, modelled as rows of the rclcpp table: an
``AsyncParametersClient`` / ``SyncParametersClient`` for a remote node is a client of its
six parameter services (of the node itself when no remote is named), and
``on_parameter_event`` / ``ParameterEventHandler`` subscribe to ``/parameter_events``."""

from __future__ import annotations

import os

import pytest

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "parameter_clients")
SERVICES = [("get_parameters", "GetParameters"), ("get_parameter_types", "GetParameterTypes"),
            ("set_parameters", "SetParameters"),
            ("set_parameters_atomically", "SetParametersAtomically"),
            ("describe_parameters", "DescribeParameters"),
            ("list_parameters", "ListParameters")]


@pytest.fixture(scope="module")
def tuner() -> CppResult:
    return extract_cpp([os.path.join(ROOT, "src", "tuner", "src", "tuner.cpp")],
                       scan([ROOT]), cache_dir=None)


def clients(remote: str, line: int) -> list[tuple[str, str, str, int]]:
    return [("client", f"{remote}{name}", f"rcl_interfaces/srv/{kind}", line)
            for name, kind in SERVICES]


def test_parameter_clients_and_events(tuner: CppResult) -> None:
    rows = [(c.kind, c.name, c.type, c.location.line) for c in tuner.calls]
    assert rows == [
        *clients("camera_driver/", 13),  # make_shared<AsyncParametersClient>(this, "...")
        *clients("~", 14),               # SyncParametersClient(this): the node's own
        ("subscribe", "/parameter_events", "rcl_interfaces/msg/ParameterEvent", 15),
        *clients("/lidar/", 37),         # SyncParametersClient(executor, node, "/lidar")
    ]
    assert [d.code for d in tuner.diagnostics] == []


def test_parameter_event_handler() -> None:
    found = extract_cpp([os.path.join(ROOT, "src", "tuner", "src", "watcher.cpp")],
                        scan([ROOT]), cache_dir=None)
    assert [(c.kind, c.name, c.type, c.location.line) for c in found.calls] == [
        ("subscribe", "/parameter_events", "rcl_interfaces/msg/ParameterEvent", 9)]
    assert found.rosname == "watcher"
