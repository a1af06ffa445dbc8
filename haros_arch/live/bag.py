"""Capture the graph a recorded bag shows, with the pure-Python ``rosbags`` library.

A bag records topics, not the whole graph: its topics and their types, and where the
format keeps them, the publishing node (a ROS 1 connection header's ``callerid``) and the
QoS each publisher offered (a ROS 2 bag's ``offered_qos_profiles``, not tied to a node).
Subscribers, services and parameters are not in a bag; the capture's ``observed`` says
which kinds ``compare`` may score. Only the bag's index is read, no message.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from .capture import SCHEMA, CaptureError
from .ros2 import Endpoint, Graph

NEEDS = ("'haros-arch capture --bag' needs the rosbags library: "
         "pip install 'haros-arch[live]' (or: pip install rosbags)")

# rosbags' QoS enums as ROS 2 names them
_POLICY_WORDS = {"MANUAL_BY_NODE": "manual_by_participant"}
# a ROS 2 bag stores an unset duration as this (rmw's "infinite")
_INFINITE_SECONDS = 0x7FFFFFFF


def capture_bag(path: str) -> dict[str, Any]:
    """The topics of the bag at ``path``: a ROS 1 ``.bag`` file, or a ROS 2 bag (its folder,
    or a ``.db3`` / ``.mcap`` file beside its ``metadata.yaml``)."""
    try:
        import rosbags  # noqa: F401
    except ImportError:
        raise CaptureError(NEEDS) from None
    where = Path(path)
    if not where.exists():
        raise CaptureError("no such file or folder")
    if where.is_file() and where.suffix == ".bag":
        return _rosbag1(where)
    folder = where if where.is_dir() else where.parent
    if (folder / "metadata.yaml").is_file():
        return _rosbag2(folder)
    if where.is_file() and where.suffix in STORAGES:  # a data file on its own
        return _rosbag2(where)
    raise CaptureError(f"neither a ROS 1 .bag nor a ROS 2 bag (no metadata.yaml in {folder})")


def _rosbag1(path: Path) -> dict[str, Any]:
    from rosbags.rosbag1 import Reader

    graph = Graph()
    try:
        with Reader(path) as reader:
            connections = list(reader.connections)
    except Exception as error:  # rosbags raises several kinds on a damaged file
        raise CaptureError(str(error) or type(error).__name__) from None
    callerids = False
    for connection in connections:
        callerid = getattr(connection.ext, "callerid", None) or None
        callerids = callerids or callerid is not None
        graph.endpoints.append(Endpoint(
            "topic", connection.topic, _ros1_type(connection.msgtype), True, callerid))
    observed = ["topics", "topic types"] + (["publish links"] if callerids else [])
    data = graph.to_data({"kind": "bag", "format": "rosbag1", "file": str(path)}, observed)
    return _as_ros1(data)


def _ros1_type(msgtype: str) -> str:
    """rosbags names every type ``pkg/msg/Name``; ROS 1 names it ``pkg/Name``."""
    parts = msgtype.split("/")
    return f"{parts[0]}/{parts[-1]}" if len(parts) == 3 and parts[1] == "msg" else msgtype


def _as_ros1(data: dict[str, Any]) -> dict[str, Any]:
    """A ROS 1 bag's capture is a ROS 1 graph: no ROS 2 QoS, actions or node ownership."""
    for topic in data["topics"]:
        topic.pop("endpoints", None)
    return {"schema": SCHEMA, "ros": 1, "source": data["source"],
            "observed": data["observed"], "nodes": data["nodes"], "topics": data["topics"],
            "services": [], "parameters": None}


def _rosbag2(where: Path) -> dict[str, Any]:
    """A bag folder (its metadata.yaml), or one .db3 / .mcap file on its own: both keep
    every connection's topic, type and offered QoS (in the file since Foxy's db3 schema
    3 and in every mcap's channel metadata)."""
    graph = Graph()
    try:
        if where.is_dir():
            from rosbags.rosbag2 import Reader

            with Reader(where) as reader:
                connections = list(reader.connections)
        else:
            reader = _storage_reader(where)
            reader.open()
            try:
                connections = list(reader.connections)
            finally:
                reader.close()
    except Exception as error:  # rosbags raises several kinds on a damaged bag
        raise CaptureError(str(error) or type(error).__name__) from None
    for connection in connections:
        profiles = getattr(connection.ext, "offered_qos_profiles", None) or [None]
        for profile in profiles:
            graph.endpoints.append(Endpoint(
                "topic", connection.topic, connection.msgtype, True, None,
                _qos(profile) if profile is not None else None))
    files = where.iterdir() if where.is_dir() else [where]
    storage = sorted({STORAGES[f.suffix] for f in files if f.suffix in STORAGES})
    # a ROS 2 bag names no publishing node: its endpoints are all "unowned", and compare
    # holds their QoS against every publisher of the topic in the model
    data = graph.to_data({"kind": "bag", "format": "rosbag2", "file": str(where),
                          "storage": storage}, ["topics", "topic types", "qos"])
    if data["services"]:  # recorded service events (`ros2 bag record --all-services`)
        data["observed"] += ["services", "service types"]
    return data


STORAGES = {".db3": "sqlite3", ".mcap": "mcap"}


def _storage_reader(path: Path) -> Any:
    if path.suffix == ".mcap":
        from rosbags.rosbag2.storage_mcap import McapReader

        return McapReader(path)
    from rosbags.rosbag2.storage_sqlite3 import Sqlite3Reader

    return Sqlite3Reader(path)


def _qos(profile: Any) -> dict[str, Any]:
    """A rosbags QoS profile as the policies a DDS capture names."""
    found: dict[str, Any] = {}
    for policy in ("reliability", "durability", "history", "liveliness"):
        word = getattr(getattr(profile, policy, None), "name", None)
        if word and word not in ("SYSTEM_DEFAULT", "UNKNOWN", "BEST_AVAILABLE"):
            found[policy] = _POLICY_WORDS.get(word, word.lower())
    if found.get("history") == "keep_last":
        found["depth"] = profile.depth
    for policy, field in (("deadline", "deadline"),
                          ("lease_duration", "liveliness_lease_duration")):
        value = getattr(profile, field, None)
        if value is not None:  # zero is rmw's default: none, as infinite is
            found[policy] = (None if value.sec >= _INFINITE_SECONDS
                             or not (value.sec or value.nsec)
                             else value.sec + value.nsec / 1e9)
    return found
