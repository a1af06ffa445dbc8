"""``is_modelled`` of a link: the rules about code (queue sizes, global and unresolved
names, conditional communication) leave out the calls known only from an interface model.
A modelled gazebo instance (gazebo_ros' gzserver, a ROS 1 /gazebo) also loads a robot
description's Gazebo plugins: their calls are the description's, reported as they were
when the gazebo instance was not modelled (their cameras' image transports are
image_transport's, left out as a modelled camera driver's are)."""

from __future__ import annotations

from haros_arch.model.rosname import RosName
from haros_arch.model.runtime import LINK_CLASSES, Link, NodeInstance, Topic
from haros_arch.model.source import Node
from haros_arch.query.access import VIEWS


def _modelled(origin: str, model: str | None) -> bool:
    node = NodeInstance("/gazebo", Node("gazebo_ros", "gzserver", model=model))
    link = LINK_CLASSES["publish"](node=node, resource=Topic("/t"),
                                   rosname=RosName("t", "/t", "/"), origin=origin)
    return VIEWS[Link]["is_modelled"](link)


def test_a_modelled_hosts_own_calls_are_modelled_its_descriptions_not() -> None:
    model = "noetic/gazebo_ros 2.9.2"
    assert [_modelled(o, model) for o in ("model", "action", "plugin")] == [True] * 3
    assert _modelled("description", model) is False
    # a host whose code is read: a plugin of its known from a model is still modelled
    assert [_modelled(o, None) for o in ("model", "source", "plugin")] == [
        True, False, False]
