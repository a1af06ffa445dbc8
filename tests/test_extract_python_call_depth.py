"""The Python walk follows calls into the package's own code a bounded number of calls
deep (``MAX_CALL_DEPTH``). carla's ros-bridge builds its actors five calls down from
the bridge (``initialize_bridge`` -> ``actor_factory.start`` -> ``update`` -> ...), and
each actor makes its publishers on the node it is handed: past the bound the actor's
``__init__`` ran only as an entry, on a node not known, and the publishers were lost
without a word. The bound now reaches them; a call deeper still is said where it is cut
(``PY_CALL_DEPTH``, file:line) and the node is partial, unless the function cut cannot
reach a ROS call (a pure helper is cut silently)."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.extract.python.calls import MAX_CALL_DEPTH as DEPTH
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import Workspace

BRIDGE = """import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Actor:
    def __init__(self, node, name):
        self.pub = node.create_publisher(String, name + '/status', 10)


class Factory:
    def __init__(self, node):
        self.node = node
        self.actors = []

    def start(self):
        self.update()

    def update(self):
        self.create_from('ego')

    def create_from(self, name):
        self.create(name)

    def create(self, name):
        self.actors.append(Actor(self.node, name))


class Bridge(Node):
    def __init__(self):
        super().__init__('bridge')

    def initialize(self):
        self.factory = Factory(self)
        self.factory.start()


def main():
    rclpy.init()
    bridge = Bridge()
    bridge.initialize()
    rclpy.spin(bridge)


if __name__ == '__main__':
    main()
"""


def _chain(levels: int, last: str) -> str:
    """``main`` -> ``f1(node)`` -> ... -> ``f<levels>(node)``, whose body is ``last``."""
    lines = ["import rclpy", "from std_msgs.msg import String", "", ""]
    for level in range(1, levels):
        lines += [f"def f{level}(node, total):",
                  f"    return f{level + 1}(node, total + 1)", "", ""]
    lines += [f"def f{levels}(node, total):", f"    {last}", "", "",
              "def main():", "    rclpy.init()", "    node = rclpy.create_node('deep')",
              "    f1(node, 0)", "    rclpy.spin(node)", "", "",
              "if __name__ == '__main__':", "    main()", ""]
    return "\n".join(lines)


def test_an_object_built_five_calls_down_makes_its_publisher(tmp_path) -> None:
    source = tmp_path / "bridge.py"
    source.write_text(BRIDGE)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    made = sorted((c.kind, c.name, c.type) for c in result.calls)
    assert made == [("publish", "ego/status", "std_msgs/msg/String")]
    assert not [d for d in result.diagnostics if d.code == "PY_CALL_DEPTH"]


def test_a_cut_that_may_lose_a_ros_call_is_said(tmp_path) -> None:
    source = tmp_path / "deep.py"
    source.write_text(_chain(14, "return node.create_publisher(String, 'out', 10)"))
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    said = [(d.location.file, d.location.line, d.message) for d in result.diagnostics
            if d.code == "PY_CALL_DEPTH"]
    # main, called from the module, is walked at depth 1: the call of f<DEPTH> is the
    # one DEPTH calls deep (each f<k> four lines below the one before)
    assert said == [("deep.py", 4 * DEPTH - 2, f"the call of f{DEPTH} is not followed, "
                     f"{DEPTH} calls deep; ROS calls it may make are not read here")]


def test_a_cut_of_a_helper_without_ros_calls_is_silent(tmp_path) -> None:
    source = tmp_path / "deep.py"
    source.write_text(_chain(14, "return str(total) + 'x'"))
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    assert not [d for d in result.diagnostics if d.code == "PY_CALL_DEPTH"]


def test_the_node_with_a_cut_is_partial(write_tree) -> None:
    root = write_tree({
        "src/deep/package.xml": package_xml("deep"),
        "src/deep/CMakeLists.txt": "project(deep)\n",
        "src/deep/scripts/deep.py": _chain(
            14, "return rospy.Subscriber('in', String, None)").replace(
            "import rclpy", "import rospy").replace(
            "    rclpy.init()\n    node = rclpy.create_node('deep')",
            "    rospy.init_node('deep')\n    node = None").replace(
            "    rclpy.spin(node)", "    rospy.spin()"),
        "src/deep/launch/deep.launch": (
            '<launch>\n  <node name="deep" pkg="deep" type="deep.py"/>\n</launch>\n'),
        "project.yaml": "project: p\nconfigurations:\n  c: [deep/launch/deep.launch]\n",
    })
    os.chmod(root / "src/deep/scripts/deep.py", 0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    (node,) = model.configuration("c").nodes
    assert node.completeness == "partial"
    assert any(f"deep.py:{4 * DEPTH - 2}" in reason and f"f{DEPTH}" in reason
               for reason in node.completeness_reasons)
