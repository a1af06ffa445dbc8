"""rclpy's tf2_ros.Buffer(cache_time=None, node=None) serves ``tf2_frames`` on the node it
is given, and on none when it is given none (tf2_tools' view_frames gives it the node;
the tf2 Python examples do not)."""

from __future__ import annotations

from typing import Any

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

SCRIPT = """
import rclpy
import tf2_ros
from rclpy.node import Node

rclpy.init()
node = Node('viewer')
with_node = tf2_ros.Buffer(node=node)
positional = tf2_ros.Buffer(None, node)
without = tf2_ros.Buffer()
none_given = tf2_ros.Buffer(node=None)
listener = tf2_ros.TransformListener(without, node)
"""


def test_a_buffer_given_a_node_serves_its_frames(write_tree: Any) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_python"),
                       "pkg/pkg/viewer.py": SCRIPT})
    found = extract_python([str(root / "pkg" / "pkg" / "viewer.py")], scan([str(root)]),
                           package="pkg")
    assert [(c.kind, c.name, c.type, c.location.line) for c in found.calls
            if c.kind == "server"] == [
        ("server", "tf2_frames", "tf2_msgs/srv/FrameGraph", 7),
        ("server", "tf2_frames", "tf2_msgs/srv/FrameGraph", 8)]
    assert {c.name for c in found.calls if c.kind == "subscribe"} == {"/tf", "/tf_static"}
