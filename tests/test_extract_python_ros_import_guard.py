"""A module-level ``try`` that imports the ROS client library and messages and catches a
failed import: kyubic_ros' dashboard sets ``ROS_AVAILABLE = True`` after ``import
rclpy`` and its message modules and ``False`` in ``except ImportError`` (a UI-only
demo mode), then makes its node only when ``ROS_AVAILABLE``. Run as a ROS node those
imports succeed: the flag is True, and the node's topics are no longer conditional on
a test not known (11 conditional-communication infos, its absences undecided). A
``try`` that imports another library (which may be missing) decides nothing."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = '''import threading
IMPORTS
    ROS_AVAILABLE = True
except ImportError:
    ROS_AVAILABLE = False

    class Node:
        def __init__(self, name):
            pass


class Monitor(Node):
    def __init__(self):
        super().__init__('dashboard_node')
        self.sub = self.create_subscription(String, 'status', self.on_status, 10)

    def on_status(self, msg):
        pass


def ros_thread():
    if not ROS_AVAILABLE:
        return
    rclpy.init()
    rclpy.spin(Monitor())


def main():
    threading.Thread(target=ros_thread, daemon=True).start()
'''

ROS = '''try:
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String'''


def run(folder: Path):
    return extract_python([str(folder / "pkg" / "scripts" / "dashboard.py")],
                          scan([str(folder)]), package="pkg")


def test_a_ros_import_guard_holds_in_a_ros_node(write_tree) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg", "ament_python"),
                         "pkg/scripts/dashboard.py": NODE.replace("IMPORTS", ROS)})
    calls = [c for c in run(folder).calls if c.kind == "subscribe"]
    assert [(c.name, tuple(c.conditions)) for c in calls] == [("status", ())]


def test_a_guard_that_imports_another_library_decides_nothing(write_tree) -> None:
    imports = ROS + "\n    import nicegui"
    folder = write_tree({"pkg/package.xml": package_xml("pkg", "ament_python"),
                         "pkg/scripts/dashboard.py": NODE.replace("IMPORTS", imports)})
    calls = [c for c in run(folder).calls if c.kind == "subscribe"]
    assert [c.name for c in calls] == ["status"] and calls[0].conditions
