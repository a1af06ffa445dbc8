"""Shipped interface models rebuilt after the explicit-cast fix (e47a4c9d): image_pipeline's
image_publisher declares ``declare_parameter("publish_rate", static_cast<double>(10))``
and ros_gz_sim's ``create`` ``declare_parameter("x", static_cast<double>(0))`` (and y, z,
R, P, Y; jazzy's: humble's reads gflags); the models, built before that fix, typed them
int, so a launch file giving ``publish_rate: 25.0`` (riptide_core's underwater camera)
or a pose ``x: 1.5`` was a false parameter-type-mismatch, and one giving
``publish_rate: 25`` (an int, which rclcpp refuses for a double) none."""

from __future__ import annotations

import os

import pytest

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue
from tests.conftest import package_xml

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='image_publisher', executable='image_publisher_node', name='camera',
             parameters=[{'publish_rate': 25.0}], arguments=['rtsp://camera/stream']),
        Node(package='image_publisher', executable='image_publisher_node', name='slow',
             parameters=[{'publish_rate': 5}], arguments=['rtsp://camera/other']),
        Node(package='ros_gz_sim', executable='create', name='spawn',
             parameters=[{'x': 1.5, 'Y': 3}]),
    ])
"""


@pytest.mark.parametrize("distro", ["humble", "jazzy"])
def test_a_double_default_given_through_a_cast(write_tree, distro: str) -> None:
    depends = "<exec_depend>image_publisher</exec_depend><exec_depend>ros_gz_sim</exec_depend>"
    root = write_tree({
        "src/bringup/package.xml": package_xml("bringup", "ament_cmake").replace(
            "<export>", depends + "<export>"),
        "src/bringup/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\n"
                                      "project(bringup)\n",
        "src/bringup/launch/camera.launch.py": LAUNCH,
        "project.yaml": f"project: p\ndistro: {distro}\nworkspace: src\nconfigurations:\n"
                        "  c: [bringup/launch/camera.launch.py]\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    found = sorted(f.message.split(" ")[0] for f in run_catalogue(model)
                   if f.rule == "parameter-type-mismatch")
    expected = ["/slow/publish_rate"]
    if distro == "jazzy":  # ros_gz_sim's models are jazzy's only
        expected.append("/spawn/Y")
    assert found == sorted(expected)
