"""``diagnostic_updater.Updater`` in Python publishes /diagnostics, as its C++ twin does:
turtlebot4_diagnostics' updater node had no publisher at all."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan
from tests.conftest import package_xml

RCLPY = """
import rclpy
from rclpy.node import Node
from diagnostic_updater import Updater
from sensor_msgs.msg import Imu


class Updates(Node):
    def __init__(self):
        super().__init__('turtlebot4_diagnostics')
        self.updater = Updater(self)
        self.create_subscription(Imu, '/imu', self.imu, 10)

    def imu(self, msg):
        pass
"""

ROSPY = """
import rospy
import diagnostic_updater

rospy.init_node('monitor')
updater = diagnostic_updater.Updater()
"""


def test_python_diagnostic_updaters_publish_diagnostics(write_tree) -> None:
    root = write_tree({
        "diag2/package.xml": package_xml("diag2", "ament_python"),
        "diag2/diag2/updater.py": RCLPY,
        "diag1/package.xml": package_xml("diag1"),
        "diag1/scripts/monitor.py": ROSPY,
    })
    ws = scan([str(root)])
    ros2 = extract_python([str(root / "diag2" / "diag2" / "updater.py")], ws, package="diag2")
    assert [(c.kind, c.name, c.type) for c in ros2.calls] == [
        ("publish", "/diagnostics", "diagnostic_msgs/msg/DiagnosticArray"),
        ("subscribe", "/imu", "sensor_msgs/msg/Imu")]
    ros1 = extract_python([str(root / "diag1" / "scripts" / "monitor.py")], ws, package="diag1")
    assert [(c.kind, c.name, c.type) for c in ros1.calls] == [
        ("publish", "/diagnostics", "diagnostic_msgs/DiagnosticArray")]
