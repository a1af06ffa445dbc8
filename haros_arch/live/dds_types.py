# mypy: disable-error-code="type-arg,valid-type"
"""``rmw_dds_common/msg/ParticipantEntitiesInfo`` as Cyclone DDS IDL types, from its message
definitions:

- ParticipantEntitiesInfo: ``Gid gid``, ``NodeEntitiesInfo[] node_entities_info_seq``;
- NodeEntitiesInfo: ``string<=256 node_namespace``, ``string<=256 node_name``,
  ``Gid[] reader_gid_seq``, ``Gid[] writer_gid_seq``;
- Gid: ``char[16] data`` (``char[24]`` before Iron).

A message ``char`` is an IDL ``uint8``; the DDS type names are rosidl's
(``rmw_dds_common::msg::dds_::Gid_``). Both GID widths are here: a ROS 2 before Iron
writes 24 bytes. This module imports the optional binding: import it only when it is there
(no ``from __future__ import annotations``: the binding reads these annotations as
objects, which are no static types: mypy is told so above).
"""

from dataclasses import dataclass
from typing import Any

from cyclonedds.idl import IdlStruct, types

PREFIX = "rmw_dds_common::msg::dds_::"


def _types(width: int) -> tuple[Any, Any, Any]:
    """The three types with ``width``-byte GIDs (annotations evaluated here, as objects)."""

    @dataclass
    class Gid(IdlStruct, typename=PREFIX + "Gid_"):
        data: types.array[types.uint8, width]

    @dataclass
    class NodeEntitiesInfo(IdlStruct, typename=PREFIX + "NodeEntitiesInfo_"):
        node_namespace: types.bounded_str[256]
        node_name: types.bounded_str[256]
        reader_gid_seq: types.sequence[Gid]
        writer_gid_seq: types.sequence[Gid]

    @dataclass
    class ParticipantEntitiesInfo(IdlStruct, typename=PREFIX + "ParticipantEntitiesInfo_"):
        gid: Gid
        node_entities_info_seq: types.sequence[NodeEntitiesInfo]

    return Gid, NodeEntitiesInfo, ParticipantEntitiesInfo


BY_WIDTH: dict[int, tuple[Any, Any, Any]] = {width: _types(width) for width in (16, 24)}
