"""Capture a running ROS 2 system from DDS discovery (Eclipse Cyclone DDS's Python binding).

The capture joins a DDS domain as one participant with readers and no writer: the
built-in topics ``DCPSPublication`` and ``DCPSSubscription`` (every reader and writer in
the domain: its DDS topic, type and QoS) and ROS 2's ``ros_discovery_info`` (which node
owns which reader and writer, by GID). DDS itself announces the participant; nothing else
is sent. It reads for a bounded time and leaves. DDS discovery interoperates across
vendors, so Fast DDS and Connext nodes are seen too; QoS that a vendor does not put in
discovery (history, for most) is left out of an endpoint's QoS, not guessed. Nodes on a
middleware that is not DDS (``rmw_zenoh``) are not seen.

``ros_discovery_info`` carries ``rmw_dds_common/msg/ParticipantEntitiesInfo``: its readers'
types are in ``dds_types`` (a ``Gid`` is ``char[16] data`` since Iron, ``char[24]`` before:
one reader each), its samples are read by ``entities`` (bounded: any participant may write
them).
"""

from __future__ import annotations

import time
from typing import Any

from .capture import CaptureError
from .entities import ParticipantEntities, read_entities
from .ros2 import Endpoint, Graph, node_name, ros_name, ros_type

DISCOVERY_TOPIC = "ros_discovery_info"
INFINITE = 0x7FFFFFFFFFFFFFFF  # DDS_INFINITY, in nanoseconds
NEEDS = ("'haros-arch capture --ros2' needs Eclipse Cyclone DDS's Python binding: "
         "pip install 'haros-arch[live]' (or: pip install cyclonedds)")


def discovery_types() -> dict[int, tuple[Any, Any, Any]]:
    """(``Gid``, ``NodeEntitiesInfo``, ``ParticipantEntitiesInfo``) per GID width; a clear
    error when the optional binding is not installed."""
    try:
        from .dds_types import BY_WIDTH
    except ImportError:
        raise CaptureError(NEEDS) from None
    return BY_WIDTH


def _gid(data: bytes) -> bytes:
    """The 16 bytes of a GID that are the endpoint's DDS GUID."""
    return data[:16]


def qos_data(qos: Any) -> dict[str, Any]:
    """A DDS QoS as ROS 2 names it (the policies ``ros2 topic info -v`` shows); a policy
    the endpoint did not announce is left out; durations in seconds, infinite as None."""
    from cyclonedds.core import Policy

    found: dict[str, Any] = {}
    for policy in qos:
        scope = getattr(policy, "__scope__", "")
        if scope == "Reliability":
            found["reliability"] = ("best_effort" if policy == Policy.Reliability.BestEffort
                                    else "reliable")
        elif scope == "Durability":
            found["durability"] = {
                Policy.Durability.Volatile: "volatile",
                Policy.Durability.TransientLocal: "transient_local",
                Policy.Durability.Transient: "transient",
                Policy.Durability.Persistent: "persistent"}.get(policy)
        elif scope == "History":
            if policy == Policy.History.KeepAll:
                found["history"] = "keep_all"
            else:
                found["history"], found["depth"] = "keep_last", policy.depth
        elif scope == "Deadline":
            found["deadline"] = _seconds(policy.deadline)
        elif scope == "Liveliness":
            found["liveliness"] = ("manual_by_topic"
                                   if isinstance(policy, Policy.Liveliness.ManualByTopic)
                                   else "manual_by_participant"
                                   if isinstance(policy, Policy.Liveliness.ManualByParticipant)
                                   else "automatic")
            found["lease_duration"] = _seconds(policy.lease_duration)
    return found


def _seconds(nanoseconds: int) -> float | None:
    return None if nanoseconds >= INFINITE else nanoseconds / 1e9


def capture_ros2(domain: int = 0, seconds: float = 3.0) -> dict[str, Any]:
    """The ROS 2 graph of DDS domain ``domain`` as seen for ``seconds``, as live-graph
    data (``haros-arch capture --ros2``)."""
    kinds = discovery_types()
    from cyclonedds.builtin import (
        BuiltinDataReader,
        BuiltinTopicDcpsPublication,
        BuiltinTopicDcpsSubscription,
    )
    from cyclonedds.core import DDSException, Policy, Qos
    from cyclonedds.domain import DomainParticipant
    from cyclonedds.sub import DataReader
    from cyclonedds.topic import Topic

    if not 0 <= domain <= 232:
        raise CaptureError(f"domain id {domain} is outside 0..232")
    try:
        participant = DomainParticipant(domain)
    except DDSException as error:
        raise CaptureError(f"cannot join DDS domain {domain}: {error}") from None
    readers: list[Any] = []
    try:
        builtin = {name: BuiltinDataReader(participant, topic) for name, topic in (
            ("publications", BuiltinTopicDcpsPublication),
            ("subscriptions", BuiltinTopicDcpsSubscription))}
        readers.extend(builtin.values())
        # rmw writes ros_discovery_info reliable and transient-local: asking for the same
        # gets each participant's last sample even when it was written before we joined;
        # one reader per GID width, as a writer that announces its type matches only that
        qos = Qos(Policy.Reliability.Reliable(0), Policy.Durability.TransientLocal,
                  Policy.History.KeepAll)
        entities = [DataReader(participant, Topic(participant, DISCOVERY_TOPIC, kind[2]),
                               qos=qos) for kind in kinds.values()]
        readers.extend(entities)
        seen = _listen(builtin, entities, seconds)
        return _graph(participant.guid, seen[0], seen[1]).to_data(
            {"kind": "dds", "domain": domain, "seconds": seconds},
            ["nodes", "topics", "topic types", "publish links", "subscribe links",
             "services", "service types", "service links", "service client links",
             "actions", "qos"])
    except DDSException as error:
        raise CaptureError(f"DDS domain {domain}: {error}") from None
    finally:  # leave the domain now (the binding keeps every entity until deleted)
        for entity in (*readers, participant):
            entity.__del__()


Seen = dict[str, dict[Any, Any]]  # built-in topic -> endpoint key -> its sample
Owners = dict[bytes, ParticipantEntities]  # participant GUID -> its nodes and their GIDs


def _listen(builtin: dict[str, Any], entities: list[Any],
            seconds: float) -> tuple[Seen, Owners]:
    """Endpoints alive at the end of ``seconds`` (per built-in topic, by key) and each
    participant's last ``ParticipantEntitiesInfo`` (by its GUID)."""
    from cyclonedds.core import InstanceState

    seen: Seen = {name: {} for name in builtin}
    owners: Owners = {}
    deadline = time.monotonic() + max(0.0, seconds)
    while True:
        for name, reader in builtin.items():
            for sample in _drain(reader.take):
                info = getattr(sample, "sample_info", None)
                if info is not None and info.instance_state != InstanceState.Alive:
                    seen[name].pop(sample.key, None)  # the endpoint is gone
                elif info is None or info.valid_data:
                    seen[name][sample.key] = sample
        for reader in entities:
            for sample in _drain(lambda N, reader=reader: _take_entities(reader, N)):
                if sample is not None:
                    owners[_gid(sample.gid)] = sample
        if time.monotonic() >= deadline:
            return seen, owners
        time.sleep(0.05)


BATCH = 256
MOST_PER_PASS = 100_000  # samples of one reader in one pass; the next pass takes the rest


def _drain(take: Any) -> list[Any]:
    """What a reader holds now, in batches (bounded: a flood waits for the next pass)."""
    found: list[Any] = []
    while len(found) < MOST_PER_PASS:
        batch = take(N=BATCH)
        found.extend(batch)
        if len(batch) < BATCH:
            break
    return found


def _take_entities(reader: Any, count: int) -> list[Any]:
    """``ros_discovery_info`` samples: what ``DataReader.take`` does, with our bounded
    decoder of both GID widths in place of the binding's (None for a sample without data or
    that is not one)."""
    from cyclonedds._clayer import ddspy_take
    from cyclonedds.core import InstanceState, SampleState, ViewState

    taken = ddspy_take(reader._ref, SampleState.Any | ViewState.Any | InstanceState.Any, count)
    if isinstance(taken, int):  # a DDS return code
        return []
    return [read_entities(data) if info.valid_data else None for data, info in taken]


def _graph(own: Any, seen: Seen, owners: Owners) -> Graph:
    graph = Graph()
    owner_of: dict[bytes, str] = {}
    for info in owners.values():
        for node in info.nodes:
            name = node_name(node.namespace, node.name)
            graph.nodes.add(name)
            for gid in (*node.readers, *node.writers):
                owner_of[_gid(gid)] = name
    for kind in ("publications", "subscriptions"):
        for sample in seen[kind].values():
            if sample.participant_key == own:
                continue
            meaning = ros_name(sample.topic_name)
            if meaning is None:
                if sample.topic_name != DISCOVERY_TOPIC:
                    graph.other_topics.add(sample.topic_name)
                continue
            role, name = meaning
            graph.endpoints.append(Endpoint(
                role, name, ros_type(sample.type_name), kind == "publications",
                owner_of.get(sample.key.bytes), qos_data(sample.qos)))
    return graph
