"""A method called through its class with the instance passed first
(``Base.method(self, ...)``) runs as a method of that instance: stretch_ros2's demos
call ``hm.HelloNode.main(self, 'funmap', 'funmap')``, whose ``super().__init__(node_name,
...)`` names the node. The arguments were bound one place off (``node_name`` taking
``self``) and ``super()`` had no instance: every such node was named ``?``."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import Workspace

SOURCE = (
    "import rclpy\nfrom rclpy.node import Node\nfrom std_msgs.msg import String\n"
    "class HelloNode(Node):\n"
    "    def __init__(self):\n"
    "        self.ready = False\n"
    "    def main(self, node_name, topic_namespace):\n"
    "        rclpy.init()\n"
    "        super().__init__(node_name)\n"
    "        self.create_publisher(String, '/' + topic_namespace + '/status', 1)\n"
    "class Funmap(HelloNode):\n"
    "    def __init__(self):\n"
    "        HelloNode.__init__(self)\n"
    "    def main(self):\n"
    "        HelloNode.main(self, 'funmap', 'mapping')\n"
    "        self.create_subscription(String, 'goal', self.on_goal, 1)\n"
    "    def on_goal(self, msg):\n"
    "        pass\n"
    "def main():\n"
    "    node = Funmap()\n"
    "    node.main()\n")


def test_a_method_called_through_its_class_runs_on_the_instance(tmp_path) -> None:
    source = tmp_path / "funmap.py"
    source.write_text(SOURCE)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    assert result.rosname == "funmap"
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "/mapping/status"), ("subscribe", "goal")]
