"""A constant of a message class the workspace defines, used as a topic name in a
Python node (smarc2's ``SamTopics.DVL_TOPIC``, ``from sam_msgs.msg import Topics as
SamTopics``): the value of its definition's ``string DVL_TOPIC = 'core/dvl'``
(rosidl's, without the quotes), not an unknown name; a number constant (``RATE``) is
that number."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

TOPICS = """\
# topics of the vehicle
string DVL_TOPIC = 'core/dvl'
string DEPTH_TOPIC="core/depth"
string PLAIN_TOPIC = core/plain
int32 RATE = 10
"""

PY = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String
from vehicle_msgs.msg import Topics as VehicleTopics
import vehicle_msgs.msg


class Listener(Node):
    def __init__(self):
        super().__init__('listener')
        self.create_subscription(String, VehicleTopics.DVL_TOPIC, self.cb, 10)
        self.create_publisher(String, vehicle_msgs.msg.Topics.DEPTH_TOPIC, 1)
        self.create_publisher(String, VehicleTopics.PLAIN_TOPIC, VehicleTopics.RATE)

    def cb(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Listener())
"""


def _workspace(tmp_path):
    msgs = tmp_path / "vehicle_msgs"
    (msgs / "msg").mkdir(parents=True)
    (msgs / "package.xml").write_text(package_xml("vehicle_msgs", "ament_cmake"))
    (msgs / "msg" / "Topics.msg").write_text(TOPICS)
    node = tmp_path / "listener"
    node.mkdir()
    (node / "package.xml").write_text(package_xml("listener", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>rclpy</depend>"
        "<depend>std_msgs</depend><depend>vehicle_msgs</depend></package>"))
    return node


def test_python_reads_a_message_constant_of_the_workspace(tmp_path) -> None:
    node = _workspace(tmp_path)
    source = node / "listener.py"
    source.write_text(PY)
    result = extract_python([str(source)], scan([str(tmp_path)]))
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "core/depth"), ("publish", "core/plain"), ("subscribe", "core/dvl")]
    plain = next(c for c in result.calls if c.name == "core/plain")
    assert plain.queue_size == 10
