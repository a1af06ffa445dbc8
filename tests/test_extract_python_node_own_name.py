"""A Python node's name built from its own name: rclpy's ``get_name()`` is the node's
name without its namespace (``talker``), so ``f"/{self.get_name()}/x"`` is the global
``/talker/x`` and ``f"{self.get_namespace()}/{self.get_name()}/x"`` the private ``~x``.
elevation_mapping_cupy publishes ``f"/{self.get_name()}/{pub_key}"``: its names stayed
``/?/?`` though the launch file names the node (now ``/elevation_mapping/?``). rospy's
``get_name()`` is the fully qualified name: at a name's start it is ``~``, elsewhere the
graph puts the instance's name in its place (``PrimitiveCall.name_full``,
tests/test_graph_rospy_full_name.py)."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl
from haros_arch.model import Configuration, Node
from haros_arch.workspace import Workspace, scan

RCLPY = """
import os
import rclpy
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import Trigger


class Talker(Node):
    def __init__(self):
        super().__init__('talker')
        self.create_publisher(String, f"/{self.get_name()}/status", 1)
        self.create_publisher(String, "/" + self.get_name() + "/plain", 1)
        self.create_publisher(String, f"{self.get_namespace()}/{self.get_name()}/own", 1)
        self.create_publisher(String, f"{self.get_name()}_debug", 1)
        self.create_publisher(String, f"/{self.get_fully_qualified_name()}/odd", 1)
        self.create_publisher(String, f"/{self.get_name()}/{os.environ['KEY']}", 1)
        self.create_service(Trigger, f"{self.get_name()}/reset", self.cb)

    def cb(self, request, response):
        return response


def main():
    rclpy.init()
    rclpy.spin(Talker())
"""

ROSPY = """
import rospy
from std_msgs.msg import String
rospy.init_node('talker')
rospy.Publisher("/" + rospy.get_name() + "/odd", String, queue_size=1)
rospy.Publisher(rospy.get_name() + "/own", String, queue_size=1)
"""


def test_rclpy_node_name_inside_a_name_is_the_instance_name(tmp_path) -> None:
    source = tmp_path / "talker.py"
    source.write_text(RCLPY)
    found = extract_python([str(source)], scan([str(tmp_path)]))
    calls = sorted((c.kind, c.name, c.name_self) for c in found.calls)
    assert calls == [
        ("publish", "/?/?", True),  # the node's name first, then a value not known
        ("publish", "/?/odd", False),  # the fully qualified name after a '/': unknown
        ("publish", "/?/plain", True),
        ("publish", "/?/status", True),
        ("publish", "?_debug", True),  # relative: talker_debug in the node's namespace
        ("publish", "~own", False),
        ("server", "~reset", False),
    ]
    node = Node("demo", "talker", calls=list(found.calls))
    config = build(Configuration("c"), LaunchModel(
        nodes=[NodeDecl("/robot/cam", "demo", "talker", namespace="/robot",
                        ros_version=2)]),
        Workspace(root="/nowhere"), {node.name: node})
    topics = sorted(link.rosname.full for link in config.links if link.kind == "publish")
    assert topics == ["/?/odd", "/cam/?", "/cam/plain", "/cam/status", "/robot/cam/own",
                      "/robot/cam_debug"]


def test_rospy_node_name_inside_a_name_is_its_full_name(tmp_path) -> None:
    source = tmp_path / "talker.py"
    source.write_text(ROSPY)
    found = extract_python([str(source)], scan([str(tmp_path)]))
    assert sorted((c.name, c.name_self, c.name_full) for c in found.calls
                  if c.kind == "publish") == [("/?/odd", False, True), ("~own", False, False)]
