"""A ROS 2 parameter file of several YAML documents (bench/README, helper surveyP): rcl's
parameter file parser (rcl_yaml_param_parser parse_file_events) passes over the document
start and end events, so a node given the file's path reads every document, their
entries merged (ros2-rover's robot_localization.yaml: the local EKF in one document, the
global EKF and navsat_transform in the next two). The file was refused
(LAUNCH_YAML_SYNTAX "but found another document", an error) and every parameter of it
unknown. launch_ros reads a file itself, one document only, when it substitutes in it
(``ParameterFile(allow_substs=True)``: ``yaml.safe_load``, SubstitutionFailure): that is
still the error."""

from __future__ import annotations

import json

import pytest
from conftest import package_xml

from haros_arch.cli import main

SETUP = """
    from setuptools import setup
    setup(name="loc", packages=["loc"],
          entry_points={"console_scripts": ["ekf = loc.node:main"]})
    """
NODE = """
    import rclpy
    def main():
        rclpy.init()
        node = rclpy.create_node("ekf")
        node.declare_parameter("frequency", 10.0)
        node.declare_parameter("two_d_mode", False)
    """
LAUNCH = """
    import os
    from ament_index_python.packages import get_package_share_directory
    from launch import LaunchDescription
    from launch_ros.actions import Node
    from launch_ros.parameter_descriptions import ParameterFile

    def generate_launch_description():
        config = os.path.join(get_package_share_directory("loc"), "config", "ekf.yaml")
        return LaunchDescription([
            Node(package="loc", executable="ekf", name="ekf_local", parameters=[@FILE@]),
            Node(package="loc", executable="ekf", name="ekf_global", parameters=[@FILE@]),
        ])
    """
CONFIG = """\
ekf_local:
  ros__parameters:
    frequency: 30.0
---
ekf_global:
  ros__parameters:
    frequency: 15.0
---
ekf_local:
  ros__parameters:
    two_d_mode: true
"""


def _extract(write_tree, given: str) -> dict:
    root = write_tree({
        "src/loc/package.xml": package_xml("loc", "ament_python"),
        "src/loc/setup.py": SETUP,
        "src/loc/loc/__init__.py": "",
        "src/loc/loc/node.py": NODE,
        "src/loc/config/ekf.yaml": CONFIG,
        "src/loc/launch/loc.launch.py": LAUNCH.replace("@FILE@", given),
        "project.yaml": "project: p\nconfigurations:\n  c: [loc/launch/loc.launch.py]\n",
    })
    out = root / "model.json"
    main(["extract", str(root / "project.yaml"), "-o", str(out)])
    return json.loads(out.read_text())


def _syntax(model: dict) -> list[tuple[int, str]]:
    return [(d["location"]["line"], d["message"])
            for c in model["configurations"] for d in c["diagnostics"]
            if d["code"] == "LAUNCH_YAML_SYNTAX"]


def test_a_node_reads_every_document_of_its_file(write_tree) -> None:
    model = _extract(write_tree, "config")
    assert _syntax(model) == []
    values = {p["name"]: p["value"] for p in model["configurations"][0]["parameters"]}
    assert values["/ekf_local/frequency"] == 30.0
    assert values["/ekf_local/two_d_mode"] is True  # the third document's, merged
    assert values["/ekf_global/frequency"] == 15.0


@pytest.mark.parametrize("given", ["ParameterFile(config, allow_substs=True)"])
def test_a_file_launch_ros_reads_itself_is_one_document(write_tree, given: str) -> None:
    model = _extract(write_tree, given)
    assert [line for line, _ in _syntax(model)] == [4]
