"""The project file's ``distro:`` is the ROS_DISTRO the launch files run under, as the
distribution's setup script sets it. OrbbecSDK_ROS2's camera launch files start a plain
node on Foxy and a component elsewhere (``if os.environ["ROS_DISTRO"] == "foxy"``): with
``distro: humble`` and no ROS_DISTRO in the shell, both were started (an unknown test)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

LAUNCH = """import os
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    if os.environ["ROS_DISTRO"] == "foxy":
        return LaunchDescription([Node(package='cam', executable='old', name='old')])
    return LaunchDescription([Node(package='cam', executable='new', name='new')])
"""


@pytest.mark.parametrize(("distro", "environment", "shell", "nodes"), [
    ("humble", "", {}, ["/new"]),
    ("foxy", "", {"ROS_DISTRO": "jazzy"}, ["/old"]),
    ("humble", "environment: {ROS_DISTRO: foxy}\n", {}, ["/old"]),
    ("", "", {"ROS_DISTRO": "foxy"}, ["/old"]),
    ("", "", {}, ["/old", "/new"]),
], ids=["distro", "distro-over-shell", "project-environment", "shell", "none"])
def test_the_project_distro_is_the_launch_files_ros_distro(
        write_tree: Any, distro: str, environment: str, shell: dict[str, str],
        nodes: list[str]) -> None:
    root: Path = write_tree({
        "src/cam/package.xml": package_xml("cam", "ament_python"),
        "src/cam/launch/cam.launch.py": LAUNCH,
        "project.yaml": "project: p\n" + (f"distro: {distro}\n" if distro else "")
                        + environment + "configurations:\n  c: [cam/launch/cam.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), shell, Options(cache_dir=None))
    assert [n.name for n in model.configurations[0].nodes] == nodes


DUAL_XML = """<?xml version="1.0"?>
<package format="3">
  <name>dual</name>
  <version>1.0.0</version>
  <description>d</description>
  <maintainer email="a@b.c">a</maintainer>
  <license>BSD</license>
  <buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>
  <buildtool_depend condition="$ROS_VERSION == 2">ament_cmake</buildtool_depend>
  <export>
    <build_type condition="$ROS_VERSION == 1">catkin</build_type>
    <build_type condition="$ROS_VERSION == 2">ament_cmake</build_type>
  </export>
</package>
"""


@pytest.mark.parametrize(("distro", "shell", "build_type"), [
    ("humble", {}, "ament_cmake"),
    ("noetic", {"ROS_VERSION": "2"}, "catkin"),
    ("", {"ROS_VERSION": "2"}, "ament_cmake"),
], ids=["distro", "distro-over-shell", "shell"])
def test_the_project_distro_sets_ros_version(write_tree: Any, distro: str,
                                             shell: dict[str, str], build_type: str) -> None:
    """The distribution's setup script sets ROS_VERSION too (ros_environment), which a
    package built for ROS 1 and ROS 2 from one tree tests in its package.xml (REP 149)
    and its CMake files (sick_scan_xd: ``$ENV{ROS_VERSION}``): with ``distro: humble``
    and no ROS_VERSION in the shell, ``$ROS_VERSION == 2`` held for no package."""
    root: Path = write_tree({
        "src/dual/package.xml": DUAL_XML,
        "src/dual/CMakeLists.txt": "project(dual)\n",
        "project.yaml": "project: p\n" + (f"distro: {distro}\n" if distro else "")
                        + "configurations: {}\n",
    })
    model = analyse(load(str(root / "project.yaml")), shell, Options(cache_dir=None))
    assert [p.build_type for p in model.packages] == [build_type]
