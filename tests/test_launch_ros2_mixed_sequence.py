"""A ROS 2 parameter file whose sequence mixes element types: rcl takes the array's
type from its first element and refuses the whole file on another ("Sequence should be
of same type"), so the node does not start. clearpath_sensors' microstrain_imu.yaml
(a0f07cfb^) wrote ``imu_orientation_cov: [0.01, 0, 0, ...]``; nothing said so. A
launch file's own dictionary is launch_ros' to promote (to doubles), and a text our
YAML reader keeps that rcl reads as a number (``1e3``) is no mixture."""

from __future__ import annotations

from typing import Any

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.launch.ros2.naming import mixed_sequences
from haros_arch.workspace import scan

LAUNCH = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    config = os.path.join(get_package_share_directory('imu'), 'config', 'imu.yaml')
    return LaunchDescription([
        Node(package='imu', executable='driver', name='imu', parameters=[config]),
        Node(package='imu', executable='driver', name='other',
             parameters=[{'cov': [0.01, 0, 0]}]),
    ])
"""


def _load(write_tree, text: str) -> Any:
    root = write_tree({"src/imu/package.xml": package_xml("imu", "ament_cmake"),
                       "src/imu/config/imu.yaml": text,
                       "src/imu/launch/imu.launch.py": LAUNCH})
    return load(str(root / "src/imu/launch/imu.launch.py"), scan([str(root / "src")], {}),
                {}, {})


def test_a_sequence_of_a_double_and_integers_is_refused(write_tree) -> None:
    model = _load(write_tree, "imu:\n  ros__parameters:\n"
                              "    orientation_cov: [0.01, 0, 0, 0, 0.01]\n"
                              "    linear_cov: [0.01, 0.0, 0.0]\n"
                              "    ids: [1, 2, 3]\n")
    (said,) = [d for d in model.diagnostics if d.code == "LAUNCH_PARAMS_MIXED_SEQUENCE"]
    assert said.severity == "error" and said.location.file == "imu/launch/imu.launch.py"
    assert said.message.startswith("parameter file imu/config/imu.yaml: "
                                   "imu/ros__parameters/orientation_cov (double then "
                                   "integer): a sequence")


def test_sequences_rcl_takes_are_not_said(write_tree) -> None:
    model = _load(write_tree, "imu:\n  ros__parameters:\n    cov: [0.01, 0.0]\n"
                              "    names: [a, b]\n    flags: [true, false]\n")
    assert not [d for d in model.diagnostics if d.code == "LAUNCH_PARAMS_MIXED_SEQUENCE"]


def test_the_types_rcl_gives_elements() -> None:
    assert mixed_sequences({"n": {"ros__parameters": {"a": [1, 2.5], "b": [True, 1],
                                                       "c": ["x", 2], "d": [1.0, "1e3"],
                                                       "e": ["a", "b"], "f": [[1], [2]]}}}) \
        == [("n/ros__parameters/a", "integer then double"),
            ("n/ros__parameters/b", "bool then integer"),
            ("n/ros__parameters/c", "string then integer")]
