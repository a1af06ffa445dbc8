"""Nodes whose interface is their command line: ``rostopic pub`` / ``ros2 topic pub``.

A launch file that starts ``<node pkg="rostopic" type="rostopic" args="pub /initialpose
geometry_msgs/PoseWithCovarianceStamped '{...}'"/>`` runs a publisher of that topic and
type; its instance gets a node made from its arguments. The options are read as the
tools read them (rostopic's optparse and ros2topic's argparse): options may come
anywhere, and those that take a value take the next word.

Facts from the tools' sources: rostopic pub creates ``rospy.Publisher(topic, type,
latch=latch, queue_size=100)`` with ``latch = rate is None or --latch``
(ros_comm ``tools/rostopic/src/rostopic/__init__.py``, ``_rostopic_cmd_pub`` and
``create_publisher``). For ros2 topic pub the QoS is what its ``--qos-*`` options say
(unknown, ``None``, when they say nothing: its defaults changed between releases).
"""

from __future__ import annotations

import shlex
from typing import Any

from ..launch.model import NodeDecl
from ..model.source import Node, PrimitiveCall

ROS1_VALUE_OPTIONS = {"-r", "--rate", "-f", "--file"}
ROS2_VALUE_OPTIONS = {"-r", "--rate", "-p", "--print", "-t", "--times", "-w",
                      "--wait-matching-subscriptions", "-n", "--node-name",
                      "--qos-profile", "--qos-depth", "--qos-history",
                      "--qos-reliability", "--qos-durability", "--max-wait-time-secs",
                      "--keep-alive", "--yaml-file"}
ROS2_QOS = {"--qos-depth": "depth", "--qos-history": "history",
            "--qos-reliability": "reliability", "--qos-durability": "durability"}


def command_node(decl: NodeDecl) -> Node | None:
    """The node a ``rostopic pub`` / ``ros2 topic pub`` declaration runs, from its
    arguments; None for any other declaration (or one whose arguments name no topic)."""
    words = _words(decl.args)
    if (decl.package, decl.executable) == ("rostopic", "rostopic"):
        return _rostopic(decl, words)
    if decl.executable == "ros2" and words[:2] == ["topic", "pub"]:
        return _ros2_topic(decl, words[1:])
    return None


def _words(args: str) -> list[str]:
    try:
        words = shlex.split(args)
    except ValueError:
        words = args.split()
    return [w for w in words if ":=" not in w and w != "--ros-args"]


def _positional(words: list[str], value_options: set[str]) -> tuple[list[str], dict[str, str],
                                                                      set[str]]:
    """Positional words, options with values and flags, as optparse / argparse split them."""
    positional: list[str] = []
    values: dict[str, str] = {}
    flags: set[str] = set()
    index = 0
    while index < len(words):
        word = words[index]
        if word.startswith("--") and "=" in word:
            key, _, value = word.partition("=")
            values[key] = value
        elif word in value_options and index + 1 < len(words):
            values[word] = words[index + 1]
            index += 1
        elif word.startswith("-") and len(word) > 1:
            flags.add(word)
        else:
            positional.append(word)
        index += 1
    return positional, values, flags


def _rostopic(decl: NodeDecl, words: list[str]) -> Node | None:
    if not words or words[0] != "pub":
        return None
    positional, values, flags = _positional(words[1:], ROS1_VALUE_OPTIONS)
    if not positional:
        return None
    rate = values.get("-r", values.get("--rate"))
    latch = rate is None or bool(flags & {"-l", "--latch"})
    type_ = positional[1] if len(positional) > 1 else None
    call = PrimitiveCall("publish", positional[0], type_, queue_size=100, latch=latch,
                         location=decl.location, origin="arguments")
    return _node(decl, "rostopic", call, "python")


def _ros2_topic(decl: NodeDecl, words: list[str]) -> Node | None:
    positional, values, _flags = _positional(words[1:], ROS2_VALUE_OPTIONS)
    if not positional:
        return None
    qos: dict[str, Any] = {}
    for option, key in ROS2_QOS.items():
        if option in values:
            value = values[option]
            qos[key] = int(value) if value.isdigit() else value.replace("-", "_")
    type_ = positional[1] if len(positional) > 1 else None
    call = PrimitiveCall("publish", positional[0], type_, qos=qos or None,
                         location=decl.location,
                         origin="arguments")
    return _node(decl, decl.package or "ros2topic", call, "python")


def _node(decl: NodeDecl, package: str, call: PrimitiveCall, language: Any) -> Node:
    node = Node(package, decl.executable, "executable", language, calls=[call],
                location=decl.location)
    node.model = f"the arguments of {decl.package or 'ros2'} {decl.executable}"
    node.completeness = "model"
    return node
