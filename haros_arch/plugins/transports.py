"""The topics of image_transport's plugins: a publisher of an image topic also
publishes the topic of every transport plugin it loads, a subscriber subscribes the
topic of the one transport it is told to use (``hosts.TRANSPORTS``).

Which transports a publisher loads is decided per workspace: a transport whose package
is in the workspace or installed (``Workspace.find``) is loaded; one of the usual
installs (``Transport.common``) that is neither, under the condition that its package is
installed; any other not at all. The publisher's list parameter (ROS 1
``disable_pub_plugins``, ROS 2 ``enable_pub_plugins``) then removes transports; a value
we cannot read leaves each transport under a condition that says so. A subscriber's
transport comes from its code, or from the node's ``image_transport`` parameter (not set:
the default its TransportHints are made with, ``raw`` when none, the base topic; a value
not known: the topic ``<base>/?``); in ROS 2 only when the node declares that parameter
(TransportHints read it with get_parameter_or, which sees no launch value of an
undeclared parameter), else that default.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Protocol

from ..model.conditions import Condition
from ..model.runtime import NodeInstance, Parameter, Resource
from ..model.source import RECONFIGURE_SERVICE, RECONFIGURE_TOPICS, CallKind, PrimitiveCall
from ..model.values import UNKNOWN_MARK
from ..workspace import Workspace
from .hosts import (
    DISABLE_PUB_PLUGINS,
    ENABLE_PUB_PLUGINS,
    TRANSPORT_PARAM,
    TRANSPORTS,
    Transport,
    transport_named,
)

RAW = "raw"
# a ROS 1 dynamic_reconfigure server's service and topics, below its handle's namespace
_RECONFIGURE: tuple[tuple[CallKind, str, str], ...] = (
    ("server", *RECONFIGURE_SERVICE),
    *(("publish", topic, type_) for topic, type_ in RECONFIGURE_TOPICS))


class Params(Protocol):
    by_name: dict[tuple[type[Resource], str], Resource]


class Transports:
    """The transports of one configuration's workspace."""

    def __init__(self, workspace: Workspace, params: Params) -> None:
        self.workspace = workspace
        self.params = params
        self._found: dict[str, bool] = {}

    def installed(self, transport: Transport) -> bool | None:
        """Whether the transport's package is there: True (workspace or installed), None
        (not found, but part of the usual installs), False."""
        if transport.name == RAW:
            return True
        if transport.package not in self._found:
            self._found[transport.package] = self.workspace.find(transport.package) is not None
        if self._found[transport.package]:
            return True
        return None if transport.common else False

    def calls(self, call: PrimitiveCall, base: str, instance: NodeInstance,
              given: str | None = RAW) -> list[PrimitiveCall]:
        """The calls an image_transport call stands for: ``call`` itself for the base
        topic when it is made there, the transports' topics (absolute: ``base`` is
        resolved and remapped), and the reads of the parameters that choose them.
        ``given``: what gives a subscriber's ``?`` transport where the node's
        ``image_transport`` parameter does not (None: not known)."""
        if call.kind == "subscribe":
            return self._subscription(call, base, instance, given)
        if call.kind != "publish":
            return [call]
        version = 1 if instance.ros_version == 1 else 2
        key, listed = self._list(base, instance)
        out = [call, PrimitiveCall(
            "read", key, location=call.location, conditions=call.conditions,
            has_default=True, default=[], origin="plugin")]
        for transport in TRANSPORTS:
            msg_type = transport.types[version - 1]
            installed = self.installed(transport)
            if transport.name == RAW or msg_type is None or installed is False:
                continue
            conditions = list(call.conditions)
            if installed is None:
                conditions.append(Condition(f"{transport.package} is installed",
                                            statement="if"))
            chosen = _chosen(transport.name, listed, version)
            if chosen is False:
                continue
            if chosen is None:
                conditions.append(Condition(
                    f"image_transport/{transport.name} is "
                    f"{'not in' if version == 1 else 'in'} {key}", statement="if"))
            topic = f"{base.rstrip('/')}/{transport.name}"
            made = replace(call, name=topic, type=msg_type, conditions=tuple(conditions),
                           name_param=None, name_default=None, handle_namespace=None,
                           transport=None, origin="plugin")
            out.append(made)
            if transport.reconfigure and version == 1:
                out.extend(replace(made, kind=kind, name=f"{topic}/{name}", type=type_,
                                   queue_size=None, latch=False)
                           for kind, name, type_ in _RECONFIGURE)
            out.extend(self._parameters(made, transport, topic, base, instance))
        return out

    def _parameters(self, made: PrimitiveCall, transport: Transport, topic: str, base: str,
                    instance: NodeInstance) -> list[PrimitiveCall]:
        """The parameters a publisher plugin reads: ROS 1 under its topic (its
        dynamic_reconfigure server's), ROS 2 declared on the node under the base made a
        parameter name (not stripped of a leading ``.``, as the plugins write it)."""
        def param(kind: CallKind, name: str) -> PrimitiveCall:
            return replace(made, kind=kind, name=name, type=None, queue_size=None,
                           latch=False, has_default=True)

        if instance.ros_version == 1:
            return [param("read", f"{topic}/{name}") for name in transport.parameters[0]]
        key = _base_key(base, instance)
        out = [param("declare", f"{key}.{transport.name}.{name}")
               for name in transport.parameters[1]]
        if transport.unscoped:
            out += [param("declare", f"{key}.{name}") for name in transport.parameters[1]]
        return out

    def _list(self, base: str, instance: NodeInstance) -> tuple[str, object]:
        """The publisher's list parameter, as the call reads it, and its value (None:
        not set; ``?``: not known)."""
        if instance.ros_version == 1:
            key = f"{base.rstrip('/')}/{DISABLE_PUB_PLUGINS}"
            full = key
        else:
            relative = _base_key(base, instance).lstrip(".")
            key = f"{relative}.{ENABLE_PUB_PLUGINS}"
            full = f"{instance.name.rstrip('/')}/{key}"
        found = self.params.by_name.get((Parameter, full))
        if not isinstance(found, Parameter) or not found.set_by_launch:
            return key, None
        value = found.value
        if isinstance(value, str):
            value = [value]
        if not isinstance(value, list) or not all(
                isinstance(v, str) and UNKNOWN_MARK not in v for v in value):
            return key, UNKNOWN_MARK
        return key, value

    def _subscription(self, call: PrimitiveCall, base: str, instance: NodeInstance,
                      given: str | None) -> list[PrimitiveCall]:
        version = 1 if instance.ros_version == 1 else 2
        out: list[PrimitiveCall] = []
        name: str | None = (call.transport or "").rstrip("/=")
        if name == UNKNOWN_MARK and (call.transport_fixed or (
                version == 2 and not _declares(instance, TRANSPORT_PARAM))):
            # the transport the ROS 2 code passes itself; or ROS 2 TransportHints,
            # which get_parameter_or a parameter they never declare: without the node's
            # own declaration the launch value is not there, their default is used
            name = given
        elif name == UNKNOWN_MARK:  # TransportHints: the node's parameter
            key = ("~" if version == 1 else "") + TRANSPORT_PARAM
            out.append(PrimitiveCall("read", key, location=call.location,
                                     conditions=call.conditions, has_default=True,
                                     default=given, origin="plugin"))
            found = self.params.by_name.get(
                (Parameter, f"{instance.name.rstrip('/')}/{TRANSPORT_PARAM}"))
            name = given
            if isinstance(found, Parameter) and found.set_by_launch:
                value = found.value
                name = value if isinstance(value, str) and value and (
                    UNKNOWN_MARK not in value) else None
        if name == RAW:
            return [call, *out]
        row = transport_named(name)
        msg_type = row.types[version - 1] if row is not None else None
        topic = f"{base.rstrip('/')}/{name if name else UNKNOWN_MARK}"
        return [replace(call, name=topic, type=msg_type, name_param=None,
                        name_default=None, handle_namespace=None, transport=None,
                        origin="plugin"), *out]


def _base_key(base: str, instance: NodeInstance) -> str:
    """The base topic as a ROS 2 publisher names its parameters after it: cut by the
    length of the node's namespace, ``/`` as ``.`` (image_transport's and its plugins'
    ``substr``). A base whose start is not known statically (``?``, ``?/image_raw``:
    OrbbecSDK_ROS2's image topics, named from a map filled at run time) does not show
    where the namespace ends: its key is not known up to the text after its last unknown
    part, never the empty name the cut would leave of ``?``."""
    namespace = instance.namespace.rstrip("/") or "/"
    if base.startswith(namespace) or UNKNOWN_MARK not in base:
        return base[len(namespace):].replace("/", ".")
    return UNKNOWN_MARK + base[base.rindex(UNKNOWN_MARK) + 1:].replace("/", ".")


def _declares(instance: NodeInstance, parameter: str) -> bool:
    """Whether the instance's node declares the ROS 2 parameter ``parameter``."""
    node = instance.node
    return node is not None and any(
        c.kind == "declare" and c.name.removeprefix("~").lstrip("/.") == parameter
        for c in node.calls)


def _chosen(name: str, listed: object, version: int) -> bool | None:
    """Whether the list parameter lets the publisher load transport ``name``."""
    if listed is None:
        return True
    if listed == UNKNOWN_MARK or not isinstance(listed, list):
        return None
    entry = f"image_transport/{name}"
    return (entry not in listed) if version == 1 else (entry in listed)
