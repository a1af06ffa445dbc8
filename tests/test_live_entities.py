"""ros_discovery_info samples read by our bounded CDR reader (no DDS needed)."""

from __future__ import annotations

import struct
import time

from haros_arch.live.entities import read_entities


def sample(width: int, nodes: list[tuple[str, str, int, int]], little: bool = True) -> bytes:
    """CDR of a ParticipantEntitiesInfo as rmw writes it (tests/test_live_ros2.py checks the
    reader against rosbags' encoder too)."""
    order = "<" if little else ">"
    out = bytearray(b"\0\1\0\0" if little else b"\0\0\0\0")

    def align(size: int) -> None:
        out.extend(b"\0" * ((-(len(out) - 4)) % size))

    def u32(value: int) -> None:
        align(4)
        out.extend(struct.pack(order + "I", value))

    out.extend(bytes([9] * width))
    u32(len(nodes))
    for namespace, name, readers, writers in nodes:
        for text in (namespace, name):
            u32(len(text) + 1)
            out.extend(text.encode() + b"\0")
        for count in (readers, writers):
            u32(count)
            for i in range(count):
                out.extend(bytes([i + 1] * width))
    return bytes(out)


def test_both_widths_and_byte_orders_read():
    for width in (16, 24):
        for little in (True, False):
            found = read_entities(sample(width, [("/", "a", 1, 2), ("/ns", "b", 0, 0)], little))
            assert found is not None and found.gid == bytes([9] * width)
            assert [(n.namespace, n.name, len(n.readers), len(n.writers))
                    for n in found.nodes] == [("/", "a", 1, 2), ("/ns", "b", 0, 0)]


def test_hostile_counts_and_short_samples_are_no_sample_and_quick():
    good = sample(16, [("/", "a", 1, 1)])
    count_at = 4 + 16  # the node count follows the GID
    hostile = good[:count_at] + struct.pack("<I", 0x7FFFFFFF) + good[count_at + 4:]
    began = time.monotonic()
    assert read_entities(hostile) is None
    assert read_entities(good[:-3]) is None
    assert read_entities(b"\0\7\0\0" + good[4:]) is None  # an encoding rmw does not write
    assert read_entities(b"") is None
    assert time.monotonic() - began < 0.1
