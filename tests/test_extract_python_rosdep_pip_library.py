"""A package.xml dependency that names, by its import name, a Python library rosdep
installs from PyPI is no ROS package whose code is not read (drone_autonomous_landing_on_
ugv's ros2_px4_testing: ``<depend>dt_apriltags</depend>``, rosdep's key being
``python-dt-apriltags-pip``; its test_apriltag node builds ``dt_apriltags.Detector`` and
was partial, PY_CLASS_UNSEEN "of ROS package dt_apriltags"). The names are every pip
rule's library in rosdistro's rosdep/python.yaml (``pip_libraries.yaml``), less the names
of released ROS packages (``depthai``, a pip library and a ROS package) and of libraries
that talk to ROS themselves (``roslibpy``, through rosbridge): those stay partial."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

MANIFEST = """<?xml version="1.0"?>
<package format="3">
  <name>p</name><version>0.0.1</version><description>d</description>
  <maintainer email="a@b.c">a</maintainer><license>MIT</license>
  <depend>rclpy</depend>
  <depend>dt_apriltags</depend>
  <depend>depthai</depend>
  <depend>roslibpy</depend>
  <depend>other_ros_pkg</depend>
  <export><build_type>ament_python</build_type></export>
</package>
"""


def _unseen(tmp_path, module: str, cls: str) -> list[str]:
    package = tmp_path / "src" / "p"
    (package / "p").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST)
    (package / "p" / "__init__.py").write_text("")
    source = package / "p" / "n.py"
    source.write_text(
        "import rclpy\n"
        "from rclpy.node import Node\n"
        f"from {module} import {cls}\n"
        "class N(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('n')\n"
        f"        self.used = {cls}(families='tag36h11')\n"
        "        self.pub = self.create_publisher(rclpy.AnyMsg, 'out', 1)\n"
        "def main():\n"
        "    rclpy.init()\n"
        "    rclpy.spin(N())\n")
    result = extract_python([str(source)], scan([str(tmp_path / "src")]), package="p")
    return [d.message for d in result.diagnostics if d.code == "PY_CLASS_UNSEEN"]


def test_a_pip_library_named_by_its_import_name_hides_no_ros_call(tmp_path):
    assert _unseen(tmp_path, "dt_apriltags", "Detector") == []


def test_a_released_ros_package_of_the_same_name_still_may(tmp_path):
    assert _unseen(tmp_path, "depthai", "Device") == [
        "depthai.Device of ROS package depthai is built here and its code is not read"]


def test_a_library_that_talks_to_ros_still_may(tmp_path):
    assert _unseen(tmp_path, "roslibpy", "Ros") == [
        "roslibpy.Ros of ROS package roslibpy is built here and its code is not read"]


def test_a_ros_package_dependency_still_may(tmp_path):
    assert len(_unseen(tmp_path, "other_ros_pkg", "Helper")) == 1
