"""A node class whose ``__init__`` picks its node's name from an argument, built by the
program with a literal: fruit_competition's serial_pkg (serial_controller.py:9-19)
``SerialServer(type='sender')`` names its node ``serial_sender`` and, given
``type='receiver'``, ``serial_receiver``; serial_sender.py builds the first only. The walk
inlines ``__init__`` at the call (the test decided, one name, the sender's subscription
alone) and also walks every method on its own with its arguments unknown; that walk's
calls are dropped for a function inlined at its callers, but the names it gave were kept:
each program made both nodes (a duplicate-node-names error per launch file that starts
the two programs). Now a walk whose calls are dropped names no node either."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

SERVER = """
from rclpy.node import Node
from std_msgs.msg import String


class SerialServer(Node):
    def __init__(self, port='/dev/ttyUSB0', type='sender'):
        if type == 'sender':
            node_name = 'serial_sender'
        elif type == 'receiver':
            node_name = 'serial_receiver'
        else:
            node_name = 'serial_sender'
        super().__init__(node_name=node_name)
        if type == 'sender':
            self.sub = self.create_subscription(String, 'control_data', self.send, 10)
        elif type == 'receiver':
            self.pub = self.create_publisher(String, 'feedback_data', 10)

    def send(self, msg):
        pass
"""

SENDER = """
import rclpy
from serial_pkg.serial_controller import SerialServer


def main(args=None):
    rclpy.init(args=args)
    node = SerialServer(port='/dev/serial_ch340', type='sender')
    rclpy.spin(node)
"""

RECEIVER = """
import rclpy
from serial_pkg.serial_controller import SerialServer


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(SerialServer('/dev/serial_ch340', 'receiver'))
"""

# a function walked on its own that nothing inlines still names its node (guard)
UNCALLED = """
import rclpy
from rclpy.node import Node


class Helper(Node):
    def __init__(self):
        super().__init__('helper_node')


def main(args=None):
    rclpy.init(args=args)
"""


def _package(tmp_path):
    pkg = tmp_path / "serial_pkg"
    (pkg / "serial_pkg").mkdir(parents=True)
    (pkg / "package.xml").write_text(
        '<package format="3"><name>serial_pkg</name><version>0.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>MIT</license><exec_depend>rclpy</exec_depend>'
        '<export><build_type>ament_python</build_type></export></package>')
    (pkg / "serial_pkg" / "__init__.py").write_text("")
    (pkg / "serial_pkg" / "serial_controller.py").write_text(SERVER)
    (pkg / "serial_pkg" / "serial_sender.py").write_text(SENDER)
    (pkg / "serial_pkg" / "serial_receiver.py").write_text(RECEIVER)
    (pkg / "serial_pkg" / "helper.py").write_text(UNCALLED)
    return pkg / "serial_pkg"


def test_a_literal_argument_names_the_one_node_the_program_builds(tmp_path) -> None:
    folder = _package(tmp_path)
    workspace = scan([str(tmp_path)])
    sender = extract_python([str(folder / "serial_sender.py")], workspace,
                            package="serial_pkg", entry="main")
    assert (sender.rosname, sender.names, sender.nodes) == ("serial_sender",
                                                            ["serial_sender"], [])
    assert [(c.kind, c.name) for c in sender.calls] == [("subscribe", "control_data")]
    receiver = extract_python([str(folder / "serial_receiver.py")], workspace,
                              package="serial_pkg", entry="main")
    assert (receiver.rosname, receiver.names, receiver.nodes) == (
        "serial_receiver", ["serial_receiver"], [])
    assert [(c.kind, c.name) for c in receiver.calls] == [("publish", "feedback_data")]
    assert not [d for d in sender.diagnostics + receiver.diagnostics
                if d.code == "PY_SEVERAL_NODES"]


def test_a_node_class_walked_on_its_own_still_names_its_node(tmp_path) -> None:
    folder = _package(tmp_path)
    found = extract_python([str(folder / "helper.py")], scan([str(tmp_path)]),
                           package="serial_pkg", entry="main")
    assert (found.rosname, found.names) == ("helper_node", ["helper_node"])
