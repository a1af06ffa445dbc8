"""A running ROS 2 system without ROS 2: DDS participants, readers and writers named and
typed as rmw names them, with the ``ros_discovery_info`` writer rmw keeps, on one domain.

Run as ``python ros2_system.py DOMAIN SPEC.json``; prints ``ready`` once every entity exists,
then lives until its standard input closes. SPEC is a list of participants::

    [{"nodes": [{"namespace": "/", "name": "talker",
                 "endpoints": [{"topic": "rt/chatter", "type": "std_msgs::msg::dds_::String_",
                                "writes": true, "qos": {"reliability": "best_effort"}}]}],
      "discovery_info": true}]

A participant with ``"discovery_info": false`` announces no node (its endpoints are
nobody's, as for a DDS application that is not ROS 2).
"""

import json
import sys
from dataclasses import dataclass

from cyclonedds.core import Policy, Qos
from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import IdlMeta, IdlStruct
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from haros_arch.live.dds import DISCOVERY_TOPIC, discovery_types


def message_type(dds_name: str) -> type:
    """A one-string struct under ``dds_name``: discovery compares type names, not layouts."""

    namespace = {"__annotations__": {"data": str}, "__idl_typename__": dds_name}
    return dataclass(IdlMeta("Message", (IdlStruct,), namespace))


def qos_of(spec: dict) -> Qos:
    policies = [
        Policy.Reliability.BestEffort if spec.get("reliability") == "best_effort"
        else Policy.Reliability.Reliable(duration(milliseconds=100)),
        Policy.Durability.TransientLocal if spec.get("durability") == "transient_local"
        else Policy.Durability.Volatile,
        Policy.History.KeepLast(spec.get("depth", 10)),
    ]
    if "deadline" in spec:
        policies.append(Policy.Deadline(duration(seconds=spec["deadline"])))
    return Qos(*policies)


def main() -> None:
    domain = int(sys.argv[1])
    with open(sys.argv[2]) as handle:
        spec = json.load(handle)
    width = int(sys.argv[3]) if len(sys.argv) > 3 else 16
    gid_type, node_type, info_type = discovery_types()[width]
    keep = []
    for participant_spec in spec:
        participant = DomainParticipant(domain, qos=Qos(Policy.Userdata(b"enclave=/;")))
        keep.append(participant)
        nodes = []
        topics: dict[str, Topic] = {}  # one Topic per name in a participant, as rmw does
        for node in participant_spec["nodes"]:
            readers, writers = [], []
            for end in node.get("endpoints", []):
                if end["topic"] not in topics:
                    topics[end["topic"]] = Topic(participant, end["topic"],
                                                 message_type(end["type"]))
                topic = topics[end["topic"]]
                made = (DataWriter if end["writes"] else DataReader)(
                    participant, topic, qos=qos_of(end.get("qos", {})))
                keep.append(made)
                gid = made.guid.bytes + bytes(width - 16)
                (writers if end["writes"] else readers).append(gid)
            nodes.append((node["namespace"], node["name"], readers, writers))
        if not participant_spec.get("discovery_info", True):
            continue
        topic = Topic(participant, DISCOVERY_TOPIC, info_type)
        writer = DataWriter(participant, topic, qos=Qos(
            Policy.Reliability.Reliable(duration(milliseconds=100)),
            Policy.Durability.TransientLocal, Policy.History.KeepLast(1)))
        keep.append(writer)
        writer.write(info_type(
            gid=_gid(gid_type, participant.guid.bytes + bytes(width - 16)),
            node_entities_info_seq=[
                node_type(
                    node_namespace=namespace, node_name=name,
                    reader_gid_seq=[_gid(gid_type, g) for g in readers],
                    writer_gid_seq=[_gid(gid_type, g) for g in writers])
                for namespace, name, readers, writers in nodes]))
    print("ready", flush=True)
    sys.stdin.read()


def _gid(kind: type, data: bytes):
    return kind(data=list(data))


if __name__ == "__main__":
    main()
