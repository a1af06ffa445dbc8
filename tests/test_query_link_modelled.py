"""``is_modelled`` of a link: the rules about code (queue sizes, global and unresolved
names, conditional communication) leave out the calls known only from an interface model,
and only those. A modelled host (gazebo_ros' gzserver, a ROS 1 /gazebo) also loads the
workspace's plugin classes and a robot description's Gazebo plugins: their calls are the
workspace's, reported as they were when the host was not modelled."""

from __future__ import annotations

from haros_arch.graph.build import Resources
from haros_arch.model.rosname import RosName
from haros_arch.model.runtime import LINK_CLASSES, Configuration, Link, NodeInstance, Topic
from haros_arch.model.source import Node, PrimitiveCall
from haros_arch.plugins.transports import Transports
from haros_arch.query.access import VIEWS
from haros_arch.workspace import Workspace


def _modelled(origin: str, model: str | None) -> bool:
    node = NodeInstance("/gazebo", Node("gazebo_ros", "gzserver", model=model))
    link = LINK_CLASSES["publish"](node=node, resource=Topic("/t"),
                                   rosname=RosName("t", "/t", "/"), origin=origin)
    return VIEWS[Link]["is_modelled"](link)


def test_a_modelled_hosts_own_calls_are_modelled_its_workspace_plugins_not() -> None:
    model = "noetic/gazebo_ros 2.9.2"
    assert [_modelled(o, model) for o in ("model", "action", "hint")] == [True] * 3
    assert [_modelled(o, model) for o in ("plugin", "description")] == [False] * 2
    # a host whose code is read: a plugin of its known from a model is still modelled
    assert [_modelled(o, None) for o in ("model", "source", "plugin")] == [
        True, False, False]


def test_the_transports_of_a_modelled_image_publisher_are_modelled(tmp_path) -> None:
    config = Configuration("c")
    transports = Transports(Workspace(str(tmp_path)), Resources(config))
    instance = NodeInstance("/camera", Node("usb_cam", "usb_cam_node", model="m"))
    for origin, made in (("model", "model"), ("source", "plugin")):
        call = PrimitiveCall("publish", "image_raw", "sensor_msgs/Image", origin=origin,
                             transport="*")
        out = transports.calls(call, "/camera/image_raw", instance)
        assert len(out) > 2 and {c.origin for c in out[1:]} == {made}
