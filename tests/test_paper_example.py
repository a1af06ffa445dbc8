"""The running example of the HAROS paper must come out exactly as the paper has it."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest
from conftest import FIXTURES

from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import analyse
from haros_arch.project import load

ENV = {"PATH": os.environ.get("PATH", "")}


@pytest.fixture(scope="module")
def config() -> dict:
    model = model_to_data(analyse(load(str(FIXTURES / "paper_minimal/project.yaml")), ENV))
    assert model["schema"] == "haros-arch/1"
    # the only remark: the parameter name read from std::cin is unknown
    assert [(d["code"], d["location"]["line"]) for d in model["diagnostics"]] == [
        ("CPP_DYNAMIC_NAME", 18)]
    (minimal,) = model["configurations"]
    assert minimal["diagnostics"] == []
    return minimal


def by_name(items):
    return {item["name"]: item for item in items}


def test_node_instances(config):
    nodes = by_name(config["nodes"])
    assert sorted(nodes) == ["/listener", "/talker"]
    assert nodes["/listener"]["node"] == "example/reactive"
    assert nodes["/talker"]["node"] == "example/active"
    assert nodes["/talker"]["remaps"] == [["monologue", "chatter"]]


def test_topic_chatter(config):
    (topic,) = config["topics"]
    assert topic["name"] == "/chatter"
    assert topic["types"] == ["std_msgs/String"]
    assert topic["publishers"] == ["/talker"]
    assert topic["subscribers"] == ["/listener"]
    links = [link for link in config["links"] if link["name"] == "/chatter"]
    publish = next(link for link in links if link["kind"] == "publish")
    subscribe = next(link for link in links if link["kind"] == "subscribe")
    assert (publish["node"], publish["given"], publish["queue_size"]) == (
        "/talker", "monologue", 10)
    assert (subscribe["node"], subscribe["given"], subscribe["queue_size"]) == (
        "/listener", "chatter", 10)
    assert publish["location"]["file"] == "example/src/active.cpp"
    assert publish["location"]["line"] == 20
    assert subscribe["location"]["file"] == "example/src/reactive.cpp"
    assert subscribe["location"]["line"] == 23


def test_service_counter(config):
    (service,) = config["services"]
    assert service["name"] == "/counter"
    assert service["types"] == ["example/GetCounter"]
    assert service["servers"] == ["/listener"]
    assert service["clients"] == ["/talker"]


def test_parameters(config):
    params = config["parameters"]
    frequency = next(p for p in params if p["name"] == "/frequency")
    assert (frequency["type"], frequency["value"], frequency["writers"]) == (
        "double", 1.0, ["<launch>"])
    assert frequency["readers"] == []
    unknown = next(p for p in params if p["name"] == "?")
    assert unknown["readers"] == ["/talker"]
    assert len(params) == 2
    read = next(link for link in config["links"] if link["kind"] == "read")
    assert (read["node"], read["given"], read["location"]["line"]) == ("/talker", "?", 18)


def test_exactly_these_links(config):
    kinds = sorted((link["kind"], link["node"], link["name"]) for link in config["links"])
    assert kinds == [
        ("client", "/talker", "/counter"),
        ("publish", "/talker", "/chatter"),
        ("read", "/talker", "?"),
        ("server", "/listener", "/counter"),
        ("subscribe", "/listener", "/chatter"),
    ]
    assert all(link["conditions"] == [] for link in config["links"])


@pytest.mark.skipif(not os.path.exists("/usr/include/ros/ros.h"),
                    reason="Debian's libroscpp-dev is not installed (scripts/test installs it)")
def test_same_graph_when_ros_headers_are_installed(config, tmp_path):
    """Debian's real ROS headers are on the default include path; nothing changes."""
    assert Path("/usr/include/std_msgs/String.h").exists()
    copy = tmp_path / "paper"
    shutil.copytree(FIXTURES / "paper_minimal", copy)
    model = model_to_data(analyse(load(str(copy / "project.yaml")), ENV))
    assert model["configurations"][0] == config
