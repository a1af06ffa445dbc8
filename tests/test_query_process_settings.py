"""A ROS 2 process that makes several nodes (stretch_core's stretch_driver makes the
driver and a ``joint_trajectory_action`` node) is given its launch ``parameters=`` as
process arguments: every node of the process gets each value and takes it only if it
declares it. ``parameter-set-not-read`` reports such a value when none of the process's
nodes reads it, once, not for each node of the process that has no use for it."""

from __future__ import annotations

import textwrap

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

SETUP = """
    from setuptools import setup
    setup(name="arm", packages=["arm"],
          entry_points={"console_scripts": ["driver = arm.driver:main"]})
    """
DRIVER = """
    import rclpy
    from rclpy.node import Node

    class Trajectory(Node):
        def __init__(self):
            super().__init__("trajectory_action")

    class Driver(Node):
        def __init__(self):
            super().__init__("driver")
            self.declare_parameter("rate", 30.0)
            self.rate = self.get_parameter("rate").value

    def main():
        rclpy.init()
        driver = Driver()
        action = Trajectory()
        rclpy.spin(driver)
    """
LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        return LaunchDescription([
            Node(package="arm", executable="driver", %s
                 parameters=[{"rate": 10.0, "nobody": 1}]),
        ])
    """


def _unread(write_tree, name: str = "") -> list[tuple[str, ...]]:
    root = write_tree({
        "src/arm/package.xml": package_xml("arm", "ament_python"),
        "src/arm/setup.py": SETUP,
        "src/arm/arm/__init__.py": "",
        "src/arm/arm/driver.py": DRIVER,
        "src/arm/launch/arm.launch.py": textwrap.dedent(LAUNCH % name).lstrip("\n"),
        "project.yaml": "project: p\nconfigurations:\n  c: [arm/launch/arm.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {})
    return sorted(tuple(f.entities) for f in run_catalogue(model)
                  if f.rule == "parameter-set-not-read")


def test_a_value_one_node_of_the_process_reads_is_read(write_tree) -> None:
    # rate: the driver reads it, the trajectory node has no use for it; nobody: no node
    # of the process reads it, said once
    assert _unread(write_tree) == [("parameter:/driver/nobody",)]
