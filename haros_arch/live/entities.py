"""Read a ``ros_discovery_info`` sample (``rmw_dds_common/msg/ParticipantEntitiesInfo``)
from its CDR bytes, bounded by their length.

Any participant in the domain may write this topic, so its bytes are hostile input: a
sequence length of 2**31 must not make us loop 2**31 times (the binding's own decoder
does). Each count here is checked against the bytes left before anything is read. The
layout is plain CDR (XCDR1, as rmw writes it) of::

    Gid gid                                  # char[W] data: W = 16, or 24 before Iron
    NodeEntitiesInfo[] node_entities_info_seq
        string node_namespace, string node_name, Gid[] reader_gid_seq, Gid[] writer_gid_seq

The GID width is the one for which the whole sample is read to its end.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass, field

WIDTHS = (16, 24)
MAX_STRING = 4096  # bytes of a node's name or namespace (rmw bounds them at 256)


@dataclass
class NodeEntities:
    namespace: str
    name: str
    readers: list[bytes] = field(default_factory=list)
    writers: list[bytes] = field(default_factory=list)


@dataclass
class ParticipantEntities:
    gid: bytes
    nodes: list[NodeEntities]


class _Short(Exception):
    """The bytes end (or a count exceeds them) before the sample does."""


class _Reader:
    def __init__(self, data: bytes, little: bool) -> None:
        self.data, self.at, self.order = data, 4, "<" if little else ">"

    def left(self) -> int:
        return len(self.data) - self.at

    def align(self, size: int) -> None:
        self.at += (-(self.at - 4)) % size  # alignment counts from after the header

    def take(self, size: int) -> bytes:
        if size < 0 or size > self.left():
            raise _Short
        part = self.data[self.at:self.at + size]
        self.at += size
        return part

    def count(self, each: int) -> int:
        """A sequence length, when that many elements of ``each`` bytes fit."""
        self.align(4)
        (found,) = struct.unpack(self.order + "I", self.take(4))
        if found * each > self.left():
            raise _Short
        return found

    def string(self) -> str:
        size = self.count(1)
        if not 1 <= size <= MAX_STRING:
            raise _Short
        return self.take(size).rstrip(b"\0").decode("utf-8", "replace")

    def gids(self, width: int) -> list[bytes]:
        return [self.take(width) for _ in range(self.count(width))]


def read_entities(data: bytes | memoryview) -> ParticipantEntities | None:
    """The sample, or None when it is not one (unknown encoding, cut short, garbage)."""
    data = bytes(data)
    if len(data) < 4 or data[0] != 0 or data[1] not in (0, 1):  # CDR_BE or CDR_LE
        return None
    for width in WIDTHS:
        reader = _Reader(data, data[1] == 1)
        try:
            gid = reader.take(width)
            nodes = []
            for _ in range(reader.count(8)):  # a node is at least two empty strings
                namespace, name = reader.string(), reader.string()
                nodes.append(NodeEntities(namespace, name, reader.gids(width),
                                          reader.gids(width)))
        except (_Short, struct.error):
            continue
        if reader.left() < 4 and not data[reader.at:].strip(b"\0"):  # only padding after
            return ParticipantEntities(gid, nodes)
    return None
