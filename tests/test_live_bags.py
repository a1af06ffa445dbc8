"""capture --bag on small ROS 1 and ROS 2 bags (sqlite3 and mcap) written here with rosbags."""

from __future__ import annotations

import json
import sys

import pytest
from conftest import FIXTURES

from haros_arch.cli import main
from haros_arch.live import CaptureError, capture_bag, compare
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import analyse
from haros_arch.project import load

pytest.importorskip("rosbags", reason="the 'live' extra is not installed")

from rosbags.interfaces import (
    Qos,
    QosDurability,
    QosHistory,
    QosLiveliness,
    QosReliability,
    QosTime,
)
from rosbags.rosbag1 import Writer as Writer1
from rosbags.rosbag2 import StoragePlugin
from rosbags.rosbag2 import Writer as Writer2
from rosbags.typesys import Stores, get_typestore


def model_of(fixture: str) -> dict:
    project = load(str(FIXTURES / fixture / "project.yaml"))
    return json.loads(json.dumps(model_to_data(analyse(project, {"PATH": ""}))))


def write_ros1(path, topics):
    """``topics``: (topic, type, callerid) rows, one message each."""
    store = get_typestore(Stores.ROS1_NOETIC)
    with Writer1(path) as writer:
        for stamp, (topic, msgtype, callerid) in enumerate(topics):
            connection = writer.add_connection(topic, msgtype, typestore=store,
                                               callerid=callerid)
            message = store.types[msgtype](data="hi" if "String" in msgtype else 1)
            writer.write(connection, stamp, store.serialize_ros1(message, msgtype))


def profile(reliability, durability=QosDurability.VOLATILE, depth=10):
    never = QosTime(0, 0)
    return Qos(QosHistory.KEEP_LAST, depth, reliability, durability, never, never,
               QosLiveliness.AUTOMATIC, never, False)


def write_ros2(path, storage, topics):
    """``topics``: (topic, type, QoS profiles) rows, one message each."""
    store = get_typestore(Stores.ROS2_HUMBLE)
    with Writer2(path, version=9, storage_plugin=storage) as writer:
        for stamp, (topic, msgtype, profiles) in enumerate(topics):
            connection = writer.add_connection(topic, msgtype, typestore=store,
                                               offered_qos_profiles=profiles)
            message = store.types[msgtype](data="hi" if "String" in msgtype else 1)
            writer.write(connection, stamp, store.serialize_cdr(message, msgtype))


def test_ros1_bag_gives_topics_types_and_publishers(tmp_path):
    bag = tmp_path / "run.bag"
    write_ros1(bag, [("/chatter", "std_msgs/msg/String", "/talker"),
                     ("/chatter", "std_msgs/msg/String", "/talker2"),
                     ("/count", "std_msgs/msg/Int32", "/talker")])
    live = capture_bag(str(bag))
    assert live["ros"] == 1 and live["observed"] == ["topics", "topic types", "publish links"]
    assert live["nodes"] == ["/talker", "/talker2"]
    assert live["topics"] == [
        {"name": "/chatter", "types": ["std_msgs/String"], "publishers": ["/talker", "/talker2"],
         "subscribers": []},
        {"name": "/count", "types": ["std_msgs/Int32"], "publishers": ["/talker"],
         "subscribers": []}]


def test_ros1_bag_compares_only_what_a_bag_can_show(tmp_path):
    bag = tmp_path / "run.bag"
    write_ros1(bag, [("/chatter", "std_msgs/msg/String", "/talker")])
    live_path = tmp_path / "live.json"
    assert main(["capture", "--bag", str(bag), "-o", str(live_path)]) == 0
    model = model_of("paper_minimal")
    result = compare(model, json.loads(live_path.read_text()))
    scores = {s.kind: s for s in result.scores}
    # no subscribers, services or parameters in a bag: not scored, not "missing"
    assert list(scores) == ["topics", "topic types", "publish links"]
    assert scores["publish links"].matched == {("/talker", "/chatter")}
    assert scores["topic types"].matched == {("/chatter", "std_msgs/String")}


@pytest.mark.parametrize("storage", [StoragePlugin.SQLITE3, StoragePlugin.MCAP],
                         ids=["db3", "mcap"])
def test_ros2_bag_gives_offered_qos_and_compare_holds_it_to_the_model(tmp_path, storage):
    bag = tmp_path / "run"
    write_ros2(bag, storage, [
        ("/chatter", "std_msgs/msg/String", [profile(QosReliability.BEST_EFFORT)]),
        ("/count", "std_msgs/msg/Int32", [profile(QosReliability.RELIABLE)]),
        ("/status", "std_msgs/msg/String",
         [profile(QosReliability.RELIABLE, QosDurability.TRANSIENT_LOCAL, 1)])])
    data_file = next(p for p in bag.iterdir() if p.suffix in (".db3", ".mcap"))
    for where in (bag, data_file):  # the bag's folder or its data file
        live = capture_bag(str(where))
        assert live["ros"] == 2 and live["observed"] == ["topics", "topic types", "qos"]
        chatter = live["topics"][0]
        assert (chatter["name"], chatter["types"]) == ("/chatter", ["std_msgs/msg/String"])
        assert chatter["endpoints"] == [{"kind": "publish", "node": None, "qos": {
            "reliability": "best_effort", "durability": "volatile", "history": "keep_last",
            "depth": 10, "liveliness": "automatic", "deadline": None,
            "lease_duration": None}}]
    result = compare(model_of("live_ros2"), live)
    scores = {s.kind: s for s in result.scores}
    assert list(scores) == ["topics", "topic types", "qos"]
    # a bag's publishers are nobody's: their QoS is held against the model's publisher
    assert scores["qos"].differs == [
        "/talker /chatter publish reliability: model reliable, live best_effort"]
    assert ("/talker", "/status", "publish", "durability=transient_local") \
        in scores["qos"].matched


@pytest.mark.parametrize("storage", [StoragePlugin.SQLITE3, StoragePlugin.MCAP],
                         ids=["db3", "mcap"])
def test_a_data_file_without_its_metadata_and_service_events(tmp_path, storage):
    """A .db3 / .mcap shared alone keeps its topics and QoS; a recorded service-event topic
    (service introspection) is the service, not a topic."""
    bag = tmp_path / "run"
    with Writer2(bag, version=9, storage_plugin=storage) as writer:
        for topic, msgtype in (("/chatter", "std_msgs/msg/String"),
                               ("/reset/_service_event", "std_srvs/srv/Empty_Event")):
            # (the definition is never read: only the connection's names and QoS)
            writer.add_connection(topic, msgtype, msgdef="uint8 structure_needs_at_least_one",
                                  rihs01="RIHS01_" + "0" * 64,
                                  offered_qos_profiles=[profile(QosReliability.RELIABLE)])
    (bag / "metadata.yaml").unlink()
    alone = next(p for p in bag.iterdir() if p.suffix in (".db3", ".mcap"))
    live = capture_bag(str(alone))
    assert [t["name"] for t in live["topics"]] == ["/chatter"]
    assert live["services"] == [{"name": "/reset", "types": ["std_srvs/srv/Empty"],
                                 "servers": [], "clients": []}]
    assert live["observed"] == ["topics", "topic types", "qos", "services", "service types"]
    assert live["topics"][0]["endpoints"][0]["qos"]["reliability"] == "reliable"


def test_a_file_that_is_no_bag_is_a_clean_error(tmp_path, capsys):
    junk = tmp_path / "junk.bag"
    junk.write_bytes(b"#ROSBAG V2.0\n" + b"\xff" * 64)
    with pytest.raises(CaptureError):
        capture_bag(str(junk))
    assert main(["capture", "--bag", str(junk)]) == 2
    assert "cannot capture from" in capsys.readouterr().err
    (tmp_path / "lone.txt").write_bytes(b"")
    assert main(["capture", "--bag", str(tmp_path / "lone.txt")]) == 2
    assert "neither a ROS 1 .bag nor a ROS 2 bag" in capsys.readouterr().err
    (tmp_path / "lone.mcap").write_bytes(b"\x89MCAP0\r\n" + b"\0" * 40)
    assert main(["capture", "--bag", str(tmp_path / "lone.mcap")]) == 2
    assert "cannot capture from" in capsys.readouterr().err
    assert main(["capture", "--bag", str(tmp_path / "missing.bag")]) == 2
    assert "no such file" in capsys.readouterr().err


def test_capture_without_rosbags_says_what_to_install(monkeypatch, tmp_path, capsys):
    monkeypatch.setitem(sys.modules, "rosbags", None)
    (tmp_path / "run.bag").write_bytes(b"#ROSBAG V2.0\n")
    assert main(["capture", "--bag", str(tmp_path / "run.bag")]) == 2
    assert "haros-arch[live]" in capsys.readouterr().err
