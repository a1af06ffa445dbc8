"""rosserial_arduino's serial_node.py: ``from rosserial_arduino import SerialClient`` is the
class the package's ``__init__`` binds (``from .SerialClient import *``), not the submodule
of the same name; that class derives from rosserial_python's SerialClient, a Python package
of another workspace package, whose methods (run() sets up the device's topics, names
known only at run time) the node runs too."""

from __future__ import annotations

from types import SimpleNamespace
from typing import Any

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.graph.candidates import compatible
from haros_arch.workspace import scan

BRIDGE = {
    "src/bridge_base/package.xml": package_xml("bridge_base"),
    "src/bridge_base/src/bridge_base/__init__.py": "from .Client import *\n",
    "src/bridge_base/src/bridge_base/Client.py": (
        "import rospy\n"
        "from std_msgs.msg import String\n"
        "class Client(object):\n"
        "    def __init__(self, port=None):\n"
        "        self.pub = rospy.Publisher('/diagnostics', String, queue_size=1)\n"
        "    def run(self):\n"
        "        self.setup(self.read())\n"
        "    def setup(self, info):\n"
        "        self.out = rospy.Publisher(info.topic_name, String, queue_size=1)\n"),
    "src/board/package.xml": package_xml("board"),
    "src/board/src/board/__init__.py": "from .Client import *\n",
    "src/board/src/board/Client.py": (
        "import rospy\n"
        "from std_srvs.srv import Empty\n"
        "from bridge_base import Client as _Client\n"
        "class Client(_Client):\n"
        "    def __init__(self, *args, **kwargs):\n"
        "        rospy.Service('~reset', Empty, self.reset)\n"
        "        super(Client, self).__init__(*args, **kwargs)\n"
        "    def reset(self, req):\n"
        "        return None\n"),
    "src/board/nodes/serial_node.py": (
        "import rospy\n"
        "from board import Client\n"
        "rospy.init_node('serial_node')\n"
        "port = rospy.get_param('~port', '/dev/ttyUSB0')\n"
        "client = Client(port)\n"
        "client.run()\n"),
}


def test_a_class_the_package_binds_and_its_base_in_another_package(write_tree) -> None:
    root = write_tree(BRIDGE)
    ws = scan([str(root / "src")], {})
    node = root / "src" / "board" / "nodes" / "serial_node.py"
    result = extract_python([str(node)], ws, package="board")
    got = sorted((c.kind, c.name, c.location.file) for c in result.calls)
    assert got == [
        ("publish", "/diagnostics", "bridge_base/src/bridge_base/Client.py"),
        ("publish", "?", "bridge_base/src/bridge_base/Client.py"),
        ("read", "~port", "board/nodes/serial_node.py"),
        ("server", "~reset", "board/src/board/Client.py"),
    ]


def test_a_submodule_the_init_does_not_bind_is_still_the_module(write_tree) -> None:
    files = dict(BRIDGE)
    files["src/board/src/board/__init__.py"] = ""
    files["src/board/nodes/serial_node.py"] = (
        "import rospy\n"
        "from board import Client\n"
        "rospy.init_node('serial_node')\n"
        "client = Client.Client('/dev/ttyUSB0')\n")
    root = write_tree(files)
    ws = scan([str(root / "src")], {})
    node = root / "src" / "board" / "nodes" / "serial_node.py"
    result = extract_python([str(node)], ws, package="board")
    assert ("server", "~reset") in [(c.kind, c.name) for c in result.calls]


def _topic(name: str, types: list[str]) -> Any:
    return SimpleNamespace(name=name, types=types)  # what compatible() reads of a topic


def test_a_topic_of_unknown_type_may_be_any_topic() -> None:
    """A '?' publisher of type '?' (the bridge's) may be /joy of sensor_msgs/Joy."""
    joy = _topic("/joy", ["sensor_msgs/Joy"])
    assert compatible(_topic("/?", ["?"]), joy)
    assert compatible(_topic("/?", ["sensor_msgs/?"]), joy)
    assert not compatible(_topic("/?", ["std_msgs/String"]), joy)
    assert not compatible(_topic("/?", ["std_msgs/?"]), joy)
