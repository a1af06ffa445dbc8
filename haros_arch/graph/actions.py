"""An action is also its topics (ROS 1 actionlib) or its services and topics (ROS 2).

A node that serves or calls action ``/fib`` of type ``pkg/Fibonacci`` also, on the wire:

- ROS 1: subscribes (server) or publishes (client) ``/fib/goal`` and ``/fib/cancel``,
  and publishes (server) or subscribes (client) ``/fib/status``, ``/fib/feedback`` and
  ``/fib/result``;
- ROS 2: serves (server) or calls (client) ``/fib/_action/send_goal``,
  ``/fib/_action/cancel_goal`` and ``/fib/_action/get_result``, and publishes (server)
  or subscribes (client) ``/fib/_action/feedback`` and ``/fib/_action/status``.

These links are added with ``origin="action"`` and the action call's location, so a
live system's topics and services match the model and reports can fold them away.
"""

from __future__ import annotations

from ..model.rosname import RosName, namespace_of
from ..model.runtime import Configuration, Link
from ..model.source import CallKind, PrimitiveCall, wire_call

# (suffix, kind for the server, kind for the client, type template) per ROS version;
# in a type template {pkg} and {name} come from the action type pkg/Name
ROS1 = (
    ("goal", "subscribe", "publish", "{pkg}/{name}ActionGoal"),
    ("cancel", "subscribe", "publish", "actionlib_msgs/GoalID"),
    ("status", "publish", "subscribe", "actionlib_msgs/GoalStatusArray"),
    ("feedback", "publish", "subscribe", "{pkg}/{name}ActionFeedback"),
    ("result", "publish", "subscribe", "{pkg}/{name}ActionResult"),
)
ROS2 = (
    ("_action/send_goal", "server", "client", "{pkg}/action/{name}_SendGoal"),
    ("_action/cancel_goal", "server", "client", "action_msgs/srv/CancelGoal"),
    ("_action/get_result", "server", "client", "{pkg}/action/{name}_GetResult"),
    ("_action/feedback", "publish", "subscribe", "{pkg}/action/{name}_FeedbackMessage"),
    ("_action/status", "publish", "subscribe", "action_msgs/msg/GoalStatusArray"),
)


def _type(template: str, action_type: str | None) -> str | None:
    if "{" not in template:
        return template
    if not action_type or action_type.count("/") not in (1, 2):
        return None
    parts = action_type.split("/")
    return template.format(pkg=parts[0], name=parts[-1])


def wire_calls(link: Link) -> list[tuple[PrimitiveCall, RosName]]:
    """The topic and service calls that an action link stands for, each with its name:
    the action's name (as written and as resolved) with the wire suffix."""
    serving = link.kind == "action-server"
    rows = ROS2 if link.node.ros_version == 2 else ROS1
    made = []
    for suffix, server_kind, client_kind, template in rows:
        kind: CallKind = server_kind if serving else client_kind  # type: ignore[assignment]
        full = f"{link.rosname.full.rstrip('/')}/{suffix}"
        call = wire_call(link.call or PrimitiveCall(kind, full), kind, full,
                         _type(template, link.type),
                         tuple(c for c in link.conditions if c not in link.node.conditions))
        given = f"{link.rosname.given.rstrip('/')}/{suffix}"
        made.append((call, RosName(given, full, namespace_of(full))))
    return made


def action_links(config: Configuration) -> list[tuple[Link, PrimitiveCall, RosName]]:
    """Every action link of the configuration with each call it stands for and its name."""
    return [(link, call, name) for link in list(config.links)
            if link.kind in ("action-server", "action-client")
            for call, name in wire_calls(link)]
