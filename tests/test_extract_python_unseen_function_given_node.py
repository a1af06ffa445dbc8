"""A Python node that hands itself to a function whose code is not read
(``setup_publishers(node)`` of a module named after a workspace package that the loader
cannot find, or of an installed ROS package the node's package depends on) was
'complete', the function's publishers silently missing: only a class of such a module
built was said (PY_CLASS_UNSEEN). Now PY_FUNCTION_UNSEEN names the function and what it
was given, and the node is partial. Not when the argument is not the node (a message, a
number, a publisher an rclpy node made), nor for a function of the standard library, a
client library, a library known to make no ROS call, or a message module."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan


def _manifest(name: str, *depends: str) -> str:
    tags = "".join(f"<exec_depend>{d}</exec_depend>" for d in depends)
    return (
        '<?xml version="1.0"?><package format="2">'
        f"<name>{name}</name><version>0.0.1</version><description>d</description>"
        '<maintainer email="a@b.c">a</maintainer><license>MIT</license>'
        f"<buildtool_depend>ament_cmake</buildtool_depend>{tags}</package>\n")


def _run(tmp_path, body: str, client: str = "rclpy"):
    src = tmp_path / "src"
    node = src / "p"
    (node / "scripts").mkdir(parents=True)
    (node / "package.xml").write_text(_manifest("p", client, "q", "nav_helpers", "numpy"))
    (node / "CMakeLists.txt").write_text("project(p)\n")
    other = src / "q"
    (other / "odd_layout" / "q").mkdir(parents=True)  # a layout no reader looks in
    (other / "package.xml").write_text(_manifest("q", client))
    (other / "odd_layout" / "q" / "__init__.py").write_text("")
    (other / "odd_layout" / "q" / "setup.py").write_text(
        "def setup_publishers(node):\n"
        "    node.create_publisher(object, 'hidden', 1)\n")
    source = node / "scripts" / "n.py"
    source.write_text(body)
    return extract_python([str(source)], scan([str(src)]), package="p")


def _said(result) -> list[str]:
    return [d.message for d in result.diagnostics if d.code == "PY_FUNCTION_UNSEEN"]


ROS2 = """
import rclpy
from rclpy.node import Node
import numpy
import os.path
import q.setup
from q.setup import setup_publishers
from q.msg import Thing
import nav_helpers

class Talker(Node):
    def __init__(self):
        super().__init__('talker')
        self.pub = self.create_publisher(Thing, 'out', 10)
        setup_publishers(self)
        q.setup.configure(10, Thing(), self.pub)
        numpy.asarray(self)
        os.path.join('a', 'b')

rclpy.init()
node = rclpy.create_node('other')
nav_helpers.wait_for(timeout=5.0, node=node)
rclpy.spin(Talker())
"""


def test_a_function_given_the_node_is_unseen_code(tmp_path) -> None:
    result = _run(tmp_path, ROS2)
    said = _said(result)
    assert len(said) == 2, said
    own, installed = sorted(said, key=lambda m: m.startswith("nav_helpers"))
    assert "q.setup.setup_publishers" in own and "package q" in own and "(self)" in own
    assert "nav_helpers.wait_for" in installed and "package nav_helpers" in installed
    assert "(node)" in installed
    # the publisher the node made, a number and a message given: no node, not said;
    # numpy (a library) and os.path (the standard library) neither
    assert not any("configure" in m or "numpy" in m or "os.path" in m for m in said)


ROS1 = """
import rospy
from std_msgs.msg import String
from q import setup
rospy.init_node('n')
pub = rospy.Publisher('out', String, queue_size=1)
setup.attach(pub)
setup.log_level(3)
rospy.spin()
"""


def test_rospy_s_objects_given_are_the_node_in_ros1(tmp_path) -> None:
    said = _said(_run(tmp_path, ROS1, client="rospy"))
    assert len(said) == 1 and "q.setup.attach" in said[0] and "(pub)" in said[0], said
