"""capture --ros2 and compare against a real DDS domain on loopback.

A child process (tests/ros2_system.py) plays a running ROS 2 system with Cyclone DDS alone:
participants, readers and writers named and typed as rmw names them, and the
``ros_discovery_info`` writer that says which node owns which. The capture joins the same
random domain, restricted to the loopback interface, from this process.
"""

from __future__ import annotations

import json
import os
import random
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from conftest import FIXTURES

from haros_arch.cli import main
from haros_arch.live import CaptureError, capture_ros2, compare
from haros_arch.live.ros2 import action_type, ros_name, ros_type, service_type
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import analyse
from haros_arch.project import load

pytest.importorskip("cyclonedds", reason="the 'live' extra is not installed")

HERE = Path(__file__).parent
LOOPBACK = (
    "<CycloneDDS><Domain id='any'><General><Interfaces><NetworkInterface address='127.0.0.1'/>"
    "</Interfaces><AllowMulticast>false</AllowMulticast></General><Discovery>"
    "<ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>20"
    "</MaxAutoParticipantIndex><Peers><Peer address='127.0.0.1'/></Peers></Discovery>"
    "</Domain></CycloneDDS>")
STRING, INT32, INT64 = (f"std_msgs::msg::dds_::{t}_" for t in ("String", "Int32", "Int64"))
TRIGGER = "std_srvs::srv::dds_::Trigger_"
FIB = "example_interfaces::action::dds_::Fibonacci_"
CANCEL = "action_msgs::srv::dds_::CancelGoal_"
STATUS = "action_msgs::msg::dds_::GoalStatusArray_"


def topic(name: str, type_: str, writes: bool, **qos) -> dict:
    return {"topic": name, "type": type_, "writes": writes, "qos": qos}


def service(name: str, type_: str, serves: bool) -> list[dict]:
    """The request and reply topics of a service's server (or client)."""
    return [topic(f"rq/{name}Request", f"{type_}Request_", not serves),
            topic(f"rr/{name}Reply", f"{type_}Response_", serves)]


def action(name: str, serves: bool) -> list[dict]:
    return [*service(f"{name}/_action/send_goal", FIB[:-1] + "_SendGoal_", serves),
            *service(f"{name}/_action/get_result", FIB[:-1] + "_GetResult_", serves),
            *service(f"{name}/_action/cancel_goal", CANCEL, serves),
            topic(f"rt/{name}/_action/feedback", FIB[:-1] + "_FeedbackMessage_", serves),
            topic(f"rt/{name}/_action/status", STATUS, serves)]


# the fixture live_ros2 as it runs, with one difference of each kind: /monitor is not
# running and /rogue is (serving /ping), /status is not published, /count is published as
# Int64 (the model: Int32), /reset is served as a Trigger (the model: Empty) and
# /listener does not call it, /chatter is offered best effort (the model: reliable), and
# a DDS participant that is no ROS node publishes rt/debug
SYSTEM = [
    {"nodes": [
        {"namespace": "/", "name": "talker", "endpoints": [
            topic("rt/chatter", STRING, True, reliability="best_effort", deadline=2),
            topic("rt/count", INT64, True),
            topic("rt/rosout", "rcl_interfaces::msg::dds_::Log_", True,
                  durability="transient_local"),
            *service("talker/get_parameters", "rcl_interfaces::srv::dds_::GetParameters_", True),
            *service("reset", TRIGGER, True),
            *action("fib", True)]},
        {"namespace": "/", "name": "launch_ros_4242"},  # made by `ros2 launch`: ignored
        {"namespace": "/", "name": "listener", "endpoints": [
            topic("rt/chatter", STRING, False),
            topic("rt/count", INT64, False),
            *action("fib", False)]}]},
    {"nodes": [{"namespace": "/", "name": "rogue", "endpoints": service("ping", TRIGGER, True)}]},
    {"nodes": [{"namespace": "/", "name": "-", "endpoints": [topic("rt/debug", STRING, True)]}],
     "discovery_info": False},
]


@pytest.fixture
def domain(monkeypatch):
    monkeypatch.setenv("CYCLONEDDS_URI", LOOPBACK)
    return random.randint(1, 232)


class System:
    """The system in its child process, and an observer here that waits until this
    process's domain has discovered all of it: the capture then runs in a domain that
    already knows the system, so a loaded machine does not make it miss a slow announcer."""

    def __init__(self, domain: int, tmp_path: Path, spec: list, width: int = 16) -> None:
        from cyclonedds.builtin import (
            BuiltinDataReader,
            BuiltinTopicDcpsPublication,
            BuiltinTopicDcpsSubscription,
        )
        from cyclonedds.domain import DomainParticipant

        spec_path = tmp_path / "system.json"
        spec_path.write_text(json.dumps(spec))
        env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(HERE.parent), str(HERE)])}
        self.child = subprocess.Popen(
            [sys.executable, str(HERE / "ros2_system.py"), str(domain), str(spec_path),
             str(width)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, env=env, text=True)
        assert self.child.stdout is not None
        assert self.child.stdout.readline().strip() == "ready"
        self.observer = DomainParticipant(domain)
        self.readers = [BuiltinDataReader(self.observer, topic) for topic in (
            BuiltinTopicDcpsPublication, BuiltinTopicDcpsSubscription)]
        ends = [e for p in spec for n in p["nodes"] for e in n.get("endpoints", [])]
        want = [sum(e["writes"] for e in ends) + sum(p.get("discovery_info", True)
                                                     for p in spec),
                sum(not e["writes"] for e in ends)]
        seen: list[set] = [set(), set()]
        limit = time.monotonic() + 20
        while any(len(s) < w for s, w in zip(seen, want, strict=True)) and time.monotonic() < limit:
            for found, reader in zip(seen, self.readers, strict=True):
                found.update(s.key for s in reader.take(N=256)
                             if s.participant_key != self.observer.guid)
            time.sleep(0.05)

    def stop(self) -> None:
        for entity in (*self.readers, self.observer):
            entity.__del__()
        assert self.child.stdin is not None
        self.child.stdin.close()
        self.child.wait(timeout=10)


@pytest.fixture(scope="module")
def demo_model():
    project = load(str(FIXTURES / "live_ros2/project.yaml"))
    return json.loads(json.dumps(model_to_data(analyse(project, {"PATH": ""}))))


def test_ros2_names_undone_as_rmw_made_them():
    assert ros_name("rt/robot/scan") == ("topic", "/robot/scan")
    assert ros_name("rq/add_two_intsRequest") == ("request", "/add_two_ints")
    assert ros_name("rr/fib/_action/get_resultReply") == ("reply", "/fib/_action/get_result")
    assert ros_name("ros_discovery_info") is None
    assert ros_type(STRING) == "std_msgs/msg/String"
    assert ros_type("MyDdsType") is None
    assert service_type("std_srvs/srv/Trigger_Request") == "std_srvs/srv/Trigger"
    assert action_type("example_interfaces/action/Fibonacci_SendGoal") \
        == "example_interfaces/action/Fibonacci"


@pytest.mark.parametrize("store", ["ROS2_HUMBLE", "ROS2_JAZZY"])
def test_discovery_info_reads_what_the_real_message_definitions_encode(store):
    """Our IDL types against rosbags' CDR encoder fed with rmw_dds_common's own message
    definitions (Humble: a Gid is 24 bytes, Jazzy: 16)."""
    rosbags = pytest.importorskip("rosbags.typesys", reason="the 'live' extra is not installed")
    import numpy

    from haros_arch.live.entities import read_entities

    types = rosbags.get_typestore(getattr(rosbags.Stores, store))
    gid_type = types.types["rmw_dds_common/msg/Gid"]
    node_type = types.types["rmw_dds_common/msg/NodeEntitiesInfo"]
    info_type = types.types["rmw_dds_common/msg/ParticipantEntitiesInfo"]
    width = 24 if store == "ROS2_HUMBLE" else 16

    def gid(first: int):
        return gid_type(data=numpy.array([first] * 16 + [0] * (width - 16), dtype=numpy.uint8))

    message = info_type(gid=gid(1), node_entities_info_seq=[
        node_type(node_namespace="/robot", node_name="driver", reader_gid_seq=[gid(2)],
                  writer_gid_seq=[gid(3), gid(4)])])
    for big_endian in (False, True):
        sample = read_entities(types.serialize_cdr(message, info_type.__msgtype__,
                                                   little_endian=not big_endian))
        assert sample is not None and sample.gid == bytes([1] * 16 + [0] * (width - 16))
        (node,) = sample.nodes
        assert (node.namespace, node.name) == ("/robot", "driver")
        assert [g[:16] for g in node.writers] == [bytes([3] * 16), bytes([4] * 16)]
        assert [g[:16] for g in node.readers] == [bytes([2] * 16)]


@pytest.mark.parametrize("width", [16, 24], ids=["iron-and-later", "humble"])
def test_capture_reads_nodes_endpoints_and_qos(domain, tmp_path, width):
    system = System(domain, tmp_path, SYSTEM, width)
    try:
        live = capture_ros2(domain, 0.7)
    finally:
        system.stop()
    assert live["ros"] == 2 and live["parameters"] is None
    assert live["nodes"] == ["/launch_ros_4242", "/listener", "/rogue", "/talker"]
    topics = {t["name"]: t for t in live["topics"]}
    assert set(topics) == {"/chatter", "/count", "/rosout", "/debug",
                           "/fib/_action/feedback", "/fib/_action/status"}
    chatter = topics["/chatter"]
    assert (chatter["types"], chatter["publishers"], chatter["subscribers"]) \
        == (["std_msgs/msg/String"], ["/talker"], ["/listener"])
    offered = next(e["qos"] for e in chatter["endpoints"] if e["kind"] == "publish")
    assert offered == {"reliability": "best_effort", "durability": "volatile",
                       "history": "keep_last", "depth": 10, "deadline": 2.0,
                       "liveliness": "automatic", "lease_duration": None}
    # a participant that announces no node: its writer is nobody's, and said to be
    assert topics["/debug"]["publishers"] == [] and live["unowned_endpoints"] == 1
    services = {s["name"]: s for s in live["services"]}
    assert services["/reset"] == {"name": "/reset", "types": ["std_srvs/srv/Trigger"],
                                  "servers": ["/talker"], "clients": []}
    assert services["/ping"]["servers"] == ["/rogue"]
    assert live["actions"] == [{"name": "/fib", "types": ["example_interfaces/action/Fibonacci"],
                                "servers": ["/talker"], "clients": ["/listener"]}]


def test_compare_shows_every_kind_of_difference_once(domain, tmp_path, demo_model, capsys):
    system = System(domain, tmp_path, SYSTEM)
    live_path, model_path = tmp_path / "live.json", tmp_path / "model.json"
    try:
        assert main(["capture", "--ros2", "--domain", str(domain), "--seconds", "0.7",
                     "-o", str(live_path)]) == 0
    finally:
        system.stop()
    result = compare(demo_model, json.loads(live_path.read_text()))
    found = {s.kind: (s.missing, s.extra, s.differs) for s in result.scores}
    assert found == {
        "nodes": (["/rogue"], ["/monitor"], None),
        "topics": (["/debug"], ["/status"], None),
        # (a topic only on one side brings its type along)
        "topic types": ([("/count", "std_msgs/msg/Int64"), ("/debug", "std_msgs/msg/String")],
                        [("/count", "std_msgs/msg/Int32"), ("/status", "std_msgs/msg/String")],
                        None),
        "publish links": ([], [("/talker", "/status")], None),
        "subscribe links": ([], [("/monitor", "/status")], None),
        "services": (["/ping"], [], None),
        "service types": ([("/ping", "std_srvs/srv/Trigger"), ("/reset", "std_srvs/srv/Trigger")],
                          [("/reset", "std_srvs/srv/Empty")], None),
        "service links": ([("/rogue", "/ping")], [], None),
        "service client links": ([], [("/listener", "/reset")], None),
        "actions": ([], [], None),
        "action types": ([], [], None),
        "action server links": ([], [], None),
        "action client links": ([], [], None),
        "qos": (found["qos"][0], found["qos"][1],
                ["/talker /chatter publish reliability: model reliable, live best_effort"]),
    }
    model_path.write_text(json.dumps(demo_model))
    capsys.readouterr()
    assert main(["compare", str(model_path), str(live_path), "--both"]) == 0
    out = capsys.readouterr().out
    assert "differs: /talker /chatter publish reliability: model reliable, live best_effort" \
        in out
    assert "missing: /rogue" in out and "extra:   /monitor" in out
    assert "both:    /listener /fib" in out  # an action client link seen live and modelled


def test_capture_writes_nothing(domain):
    """The capture's participant has readers only: an observer in the domain sees no writer
    of it (DDS announces the participant itself; that is all)."""
    from cyclonedds.builtin import BuiltinDataReader, BuiltinTopicDcpsPublication
    from cyclonedds.domain import DomainParticipant

    observer = DomainParticipant(domain)
    publications = BuiltinDataReader(observer, BuiltinTopicDcpsPublication)
    found = []
    worker = threading.Thread(target=lambda: found.append(capture_ros2(domain, 0.5)))
    worker.start()
    seen = []
    while worker.is_alive():
        seen.extend(s for s in publications.take(N=64) if s.participant_key != observer.guid)
        time.sleep(0.05)
    worker.join()
    seen.extend(s for s in publications.take(N=64) if s.participant_key != observer.guid)
    for entity in (publications, observer):
        entity.__del__()
    assert found and found[0]["topics"] == [] and seen == []


def test_capture_without_the_binding_says_what_to_install(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "cyclonedds", None)
    monkeypatch.setitem(sys.modules, "haros_arch.live.dds_types", None)
    with pytest.raises(CaptureError, match="pip install"):
        capture_ros2(0, 0.1)
    assert main(["capture", "--ros2", "--seconds", "0.1"]) == 2
    assert "haros-arch[live]" in capsys.readouterr().err


def test_capture_refuses_a_domain_dds_cannot_have(capsys):
    assert main(["capture", "--ros2", "--domain", "999", "--seconds", "0.1"]) == 2
    assert "outside 0..232" in capsys.readouterr().err
    for seconds in ("0", "nan", "601"):  # bounded in time
        assert main(["capture", "--ros2", "--seconds", seconds]) == 2
        assert "--seconds must be" in capsys.readouterr().err


def test_a_domain_that_cannot_be_joined_is_a_clean_error(monkeypatch, capsys):
    monkeypatch.setenv("CYCLONEDDS_URI", "<CycloneDDS><Domain><General><Interfaces>"
                       "<NetworkInterface name='haros-no-such-if'/></Interfaces></General>"
                       "</Domain></CycloneDDS>")
    domain = str(random.randint(1, 232))
    assert main(["capture", "--ros2", "--domain", domain, "--seconds", "0.1"]) == 2
    assert f"cannot join DDS domain {domain}" in capsys.readouterr().err
