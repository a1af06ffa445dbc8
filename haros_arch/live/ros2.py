"""A ROS 2 graph from endpoints: DDS names and types back to ROS names, services and actions.

ROS 2 puts its topics and services on DDS topics whose names and types it mangles
(rmw_dds_common's conventions, the same in every DDS middleware):

- a topic ``/chatter`` is the DDS topic ``rt/chatter``; a service ``/add`` is two DDS
  topics, ``rq/addRequest`` (clients write, the server reads) and ``rr/addReply``
  (the server writes, clients read);
- a type ``std_msgs/msg/String`` is ``std_msgs::msg::dds_::String_``, a service's request
  type ``example_interfaces::srv::dds_::AddTwoInts_Request_``.

An action ``/fib`` is its three services and two topics under ``/fib/_action/``; its
servers are the nodes that serve ``/fib/_action/send_goal``. Both the capture of a running
system (``dds``) and of a ROS 2 bag (``bag``) turn their endpoints into the live-graph data
that ``compare`` reads, here.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from .capture import SCHEMA

TOPIC_PREFIX = "rt/"
REQUEST_PREFIX, REQUEST_SUFFIX = "rq/", "Request"
REPLY_PREFIX, REPLY_SUFFIX = "rr/", "Reply"
ACTION_INFIX = "/_action/"
ACTION_SEND_GOAL = "send_goal"
# service introspection (Jazzy and later): a topic beside each service whose node turned
# it on, `/add/_service_event` of type `pkg/srv/Add_Event`; it says the service exists
SERVICE_EVENT = "/_service_event"

_DDS_TYPE = re.compile(r"^(?P<pkg>\w+)::(?P<kind>\w+)::dds_::(?P<name>\w+)_$")
_SERVICE_PART = re.compile(r"_(Request|Response)$")
_ACTION_PART = re.compile(r"_(SendGoal|GetResult|FeedbackMessage|Feedback|Goal|Result)$")


def ros_type(dds_type: str) -> str | None:
    """``std_msgs::msg::dds_::String_`` -> ``std_msgs/msg/String``; None when the type is
    not one that ROS 2 generated."""
    found = _DDS_TYPE.match(dds_type)
    if not found:
        return None
    return f"{found['pkg']}/{found['kind']}/{found['name']}"


def service_type(request_type: str) -> str:
    """``pkg/srv/AddTwoInts_Request`` -> ``pkg/srv/AddTwoInts`` (the type a node names)."""
    return _SERVICE_PART.sub("", request_type)


def action_type(send_goal_type: str) -> str | None:
    """``pkg/action/Fibonacci_SendGoal`` -> ``pkg/action/Fibonacci``."""
    if "/action/" not in send_goal_type:
        return None
    return _ACTION_PART.sub("", service_type(send_goal_type))


def ros_name(dds_topic: str) -> tuple[str, str] | None:
    """A DDS topic's ROS 2 meaning: ``("topic", "/chatter")``, ``("request", "/add")`` or
    ``("reply", "/add")``; None for a DDS topic that is not ROS 2's (``ros_discovery_info``,
    another application's)."""
    if dds_topic.startswith(TOPIC_PREFIX):
        return "topic", "/" + dds_topic[len(TOPIC_PREFIX):]
    if dds_topic.startswith(REQUEST_PREFIX) and dds_topic.endswith(REQUEST_SUFFIX):
        return "request", "/" + dds_topic[len(REQUEST_PREFIX):-len(REQUEST_SUFFIX)]
    if dds_topic.startswith(REPLY_PREFIX) and dds_topic.endswith(REPLY_SUFFIX):
        return "reply", "/" + dds_topic[len(REPLY_PREFIX):-len(REPLY_SUFFIX)]
    return None


def node_name(namespace: str, name: str) -> str:
    """The full name of a node from its namespace and base name."""
    return f"{namespace.rstrip('/')}/{name}" if namespace else f"/{name}"


@dataclass
class Endpoint:
    """One reader or writer: on a ROS topic (``topic``, publish / subscribe) or one half
    of a service (``request`` / ``reply``, write / read). ``node`` is None when no node
    claims it (no ``ros_discovery_info`` seen for its participant)."""

    role: str  # "topic", "request" or "reply"
    name: str
    type: str | None
    writes: bool
    node: str | None
    qos: dict[str, Any] | None = None


@dataclass
class Graph:
    """The endpoints of a capture, and what else it saw."""

    endpoints: list[Endpoint] = field(default_factory=list)
    nodes: set[str] = field(default_factory=set)
    other_topics: set[str] = field(default_factory=set)  # DDS topics not ROS 2's

    def to_data(self, source: dict[str, Any], observed: list[str]) -> dict[str, Any]:
        """The live-graph data of ``haros-arch capture`` (``observed``: which element
        kinds the source can see at all; ``compare`` scores only those)."""
        topics: dict[str, dict[str, Any]] = {}
        services: dict[str, dict[str, Any]] = {}
        unowned = 0
        for end in self.endpoints:
            unowned += end.node is None
            if end.role == "topic" and end.name.endswith(SERVICE_EVENT):
                service = services.setdefault(end.name[:-len(SERVICE_EVENT)], {
                    "name": end.name[:-len(SERVICE_EVENT)], "types": [], "servers": [],
                    "clients": []})
                if end.type and end.type.endswith("_Event"):
                    _add(service["types"], end.type[:-len("_Event")])
                continue
            if end.role == "topic":
                topic = topics.setdefault(end.name, {
                    "name": end.name, "types": [], "publishers": [], "subscribers": [],
                    "endpoints": []})
                _add(topic["types"], end.type)
                _add(topic["publishers" if end.writes else "subscribers"], end.node)
                topic["endpoints"].append({
                    "kind": "publish" if end.writes else "subscribe", "node": end.node,
                    "qos": end.qos})
                continue
            service = services.setdefault(end.name, {"name": end.name, "types": [],
                                                     "servers": [], "clients": []})
            if end.role == "request":
                _add(service["types"], service_type(end.type) if end.type else None)
            serves = end.writes == (end.role == "reply")
            _add(service["servers" if serves else "clients"], end.node)
        nodes = set(self.nodes)
        for end in self.endpoints:
            if end.node:
                nodes.add(end.node)
        for record in (*topics.values(), *services.values()):
            for key in ("types", "publishers", "subscribers", "servers", "clients"):
                if key in record:
                    record[key].sort()
            if "endpoints" in record:
                record["endpoints"].sort(key=lambda e: (e["kind"], e["node"] or ""))
        return {
            "schema": SCHEMA,
            "ros": 2,
            "source": source,
            "observed": observed,
            "nodes": sorted(nodes),
            "topics": [topics[name] for name in sorted(topics)],
            "services": [services[name] for name in sorted(services)],
            "actions": _actions(services, topics),
            "parameters": None,  # ROS 2 has no parameter server to read
            "unowned_endpoints": unowned,
            "other_topics": sorted(self.other_topics),
        }


def _add(values: list[Any], value: Any) -> None:
    if value is not None and value not in values:
        values.append(value)


def _actions(services: dict[str, dict[str, Any]],
             topics: dict[str, dict[str, Any]]) -> list[dict[str, Any]]:
    """Actions from their ``_action/send_goal`` services (and, for an action whose
    services were not seen, its ``_action/feedback`` topic)."""
    actions: dict[str, dict[str, Any]] = {}
    for name, service in services.items():
        if name.endswith(ACTION_INFIX + ACTION_SEND_GOAL):
            action = actions.setdefault(name[:-len(ACTION_INFIX + ACTION_SEND_GOAL)], {
                "types": [], "servers": [], "clients": []})
            for item in service["types"]:
                _add(action["types"], action_type(item))
            for key in ("servers", "clients"):
                for node in service[key]:
                    _add(action[key], node)
    for name, topic in topics.items():
        if name.endswith(ACTION_INFIX + "feedback"):
            action = actions.setdefault(name[:-len(ACTION_INFIX + "feedback")], {
                "types": [], "servers": [], "clients": []})
            if not action["types"]:
                for item in topic["types"]:
                    _add(action["types"], action_type(item))
    return [{"name": name, **{k: sorted(v) for k, v in actions[name].items()}}
            for name in sorted(actions)]
