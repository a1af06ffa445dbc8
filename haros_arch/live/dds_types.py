# mypy: disable-error-code="type-arg,valid-type"
"""``rmw_dds_common/msg/ParticipantEntitiesInfo`` as Cyclone DDS IDL types, from its message
definitions::

    # ParticipantEntitiesInfo          # NodeEntitiesInfo           # Gid
    Gid gid                            string<=256 node_namespace   char[16] data
    NodeEntitiesInfo[] node_entities_info_seq                       (char[24] before Iron)
                                       string<=256 node_name
                                       Gid[] reader_gid_seq
                                       Gid[] writer_gid_seq

A message ``char`` is an IDL ``uint8``; the DDS type names are rosidl's
(``rmw_dds_common::msg::dds_::Gid_``). Both GID widths are here: a ROS 2 before Iron
writes 24 bytes. This module imports the optional binding: import it only when it is there
(no ``from __future__ import annotations``: the binding reads these annotations as types,
which are no static types: mypy is told so above).
"""

from dataclasses import dataclass
from typing import Any

from cyclonedds.idl import IdlStruct, types

PREFIX = "rmw_dds_common::msg::dds_::"


@dataclass
class Gid(IdlStruct, typename=PREFIX + "Gid_"):
    data: types.array[types.uint8, 16]


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


@dataclass
class Gid24(IdlStruct, typename=PREFIX + "Gid_"):
    data: types.array[types.uint8, 24]


@dataclass
class NodeEntitiesInfo24(IdlStruct, typename=PREFIX + "NodeEntitiesInfo_"):
    node_namespace: types.bounded_str[256]
    node_name: types.bounded_str[256]
    reader_gid_seq: types.sequence[Gid24]
    writer_gid_seq: types.sequence[Gid24]


@dataclass
class ParticipantEntitiesInfo24(IdlStruct, typename=PREFIX + "ParticipantEntitiesInfo_"):
    gid: Gid24
    node_entities_info_seq: types.sequence[NodeEntitiesInfo24]


BY_WIDTH: dict[int, tuple[Any, Any, Any]] = {16: (Gid, NodeEntitiesInfo, ParticipantEntitiesInfo),
            24: (Gid24, NodeEntitiesInfo24, ParticipantEntitiesInfo24)}
