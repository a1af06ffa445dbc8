"""A helper module that imports neither rospy nor rclpy is read with the ROS version of
the node that uses it: stretch_ros2's stretch_diagnostics.py (``diagnostic_updater.
Updater(node)``, imported by the rclpy driver) published ROS 1's
``diagnostic_msgs/DiagnosticArray``, and a ``message_filters.Subscriber(node, type,
topic)`` there was read with rospy's (topic, type) arguments."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan
from tests.conftest import package_xml

HELPER = """
import diagnostic_updater
import message_filters
from sensor_msgs.msg import Image


class Helper:
    def __init__(self, node):
        self.updater = diagnostic_updater.Updater(node)
        self.sub = message_filters.Subscriber(node, Image, '/camera/image_raw')
"""

RCLPY_NODE = """
import rclpy
from rclpy.node import Node
from .helper import Helper


class Driver(Node):
    def __init__(self):
        super().__init__('driver')
        self.helper = Helper(self)


def main():
    rclpy.init()
    rclpy.spin(Driver())
"""

ROSPY_HELPER = """
import diagnostic_updater


def start():
    return diagnostic_updater.Updater()
"""

ROSPY_NODE = """
import rospy
from helper1 import start

rospy.init_node('monitor')
updater = start()
"""


def test_helper_module_takes_the_nodes_ros_version(write_tree) -> None:
    root = write_tree({
        "drv/package.xml": package_xml("drv", "ament_python"),
        "drv/drv/__init__.py": "",
        "drv/drv/helper.py": HELPER,
        "drv/drv/driver.py": RCLPY_NODE,
        "mon/package.xml": package_xml("mon"),
        "mon/scripts/helper1.py": ROSPY_HELPER,
        "mon/scripts/monitor.py": ROSPY_NODE,
    })
    ws = scan([str(root)])
    ros2 = extract_python([str(root / "drv" / "drv" / "driver.py")], ws, package="drv")
    assert sorted((c.kind, c.name, c.type) for c in ros2.calls) == [
        ("publish", "/diagnostics", "diagnostic_msgs/msg/DiagnosticArray"),
        ("subscribe", "/camera/image_raw", "sensor_msgs/msg/Image")]
    ros1 = extract_python([str(root / "mon" / "scripts" / "monitor.py")], ws, package="mon")
    assert [(c.kind, c.name, c.type) for c in ros1.calls] == [
        ("publish", "/diagnostics", "diagnostic_msgs/DiagnosticArray")]
