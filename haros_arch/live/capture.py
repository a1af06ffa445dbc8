"""Read a ROS 1 master's state over XML-RPC (the Master and Parameter Server APIs)."""

from __future__ import annotations

import socket
import xmlrpc.client
from typing import Any

CALLER = "/haros_arch_capture"
SCHEMA = "haros-arch-live/1"


class CaptureError(Exception):
    """The master could not be reached or answered with an error."""


def _call(master: Any, method: str, *args: Any) -> Any:
    try:
        code, message, value = getattr(master, method)(CALLER, *args)
    except (TimeoutError, OSError, xmlrpc.client.Error) as err:
        raise CaptureError(f"{method}: {err}") from None
    if code != 1:
        raise CaptureError(f"{method}: {message}")
    return value


def _plain(value: Any) -> Any:
    """XML-RPC values as JSON-ready data (binary and dates become text)."""
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_plain(v) for v in value]
    if isinstance(value, xmlrpc.client.Binary):
        return value.data.hex()
    if isinstance(value, xmlrpc.client.DateTime):
        return str(value)
    return value


def _leaves(prefix: str, value: Any) -> list[tuple[str, Any]]:
    """A parameter tree as leaf names and values, as ``rosparam list`` shows them."""
    if isinstance(value, dict) and value:
        found = []
        for key, item in value.items():
            found.extend(_leaves(f"{prefix.rstrip('/')}/{str(key).strip('/')}", item))
        return found
    return [(prefix, value)]


def capture(uri: str, timeout: float = 10.0) -> dict[str, Any]:
    """The live graph of the master at ``uri`` as JSON-ready data."""
    previous = socket.getdefaulttimeout()
    socket.setdefaulttimeout(timeout)
    try:
        master = xmlrpc.client.ServerProxy(uri, allow_none=True)
        publishers, subscribers, services = _call(master, "getSystemState")
        types = dict(_call(master, "getTopicTypes"))
        # the whole tree in one call: some names that getParamNames lists (keys that
        # start with "/" or "~" inside a YAML dictionary) cannot be read one by one
        params = {leaf: _plain(value)
                  for leaf, value in _leaves("/", _call(master, "getParam", "/"))}
    finally:
        socket.setdefaulttimeout(previous)
    topics: dict[str, dict[str, Any]] = {}
    for key, entries in (("publishers", publishers), ("subscribers", subscribers)):
        for topic, nodes in entries:
            record = topics.setdefault(topic, {"name": topic, "types": [],
                                               "publishers": [], "subscribers": []})
            record[key] = sorted(nodes)
    for topic, record in topics.items():
        record["types"] = [types[topic]] if topic in types and types[topic] != "*" else []
    nodes = sorted({n for _t, ns in (*publishers, *subscribers, *services) for n in ns})
    return {
        "schema": SCHEMA,
        "master": uri,
        "nodes": nodes,
        "topics": [topics[name] for name in sorted(topics)],
        "services": [{"name": name, "servers": sorted(servers)}
                     for name, servers in sorted(services)],
        "parameters": [{"name": name, "value": params[name]} for name in sorted(params)],
    }
