"""A package kept for both ROS versions, in a run that names neither (CARLA's ros-bridge:
``<build_type condition="$ROS_VERSION == 1">catkin</build_type>`` and ``... == 2">
ament_python``, a catkin CMakeLists.txt installing ``driver.py`` beside a setup.py
whose ``setup()`` runs only under ``if ROS_VERSION == 2`` with the entry point
``driver``, launch files for both). The package was read as catkin alone: every ROS 2
launch file's executable "not in the workspace" and every include of a launch file
setup.py installs "does not exist" (21 errors on ros-bridge e9063d9), and the nodes'
code, which picks rospy or rclpy on ``os.environ["ROS_VERSION"]``, made no call, so what
the launch files set was "never read" (32 warnings). Now each build is read, said once
per package (PACKAGE_BUILD_BY_ROS_VERSION), the share folder is what the ROS 2 setup.py
installs, and a node's code is read with the ROS_VERSION of the build that makes it."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from haros_arch.cli import main

MANIFEST = """\
<?xml version="1.0"?>
<package format="3">
  <name>drive</name>
  <version>0.1.0</version>
  <description>d</description>
  <maintainer email="a@b.c">m</maintainer>
  <license>MIT</license>
  <depend condition="$ROS_VERSION == 1">rospy</depend>
  <depend condition="$ROS_VERSION == 2">rclpy</depend>
  <depend>std_msgs</depend>
  <export>
    <build_type condition="$ROS_VERSION == 1">catkin</build_type>
    <build_type condition="$ROS_VERSION == 2">ament_python</build_type>
  </export>
</package>
"""
CMAKE = """\
cmake_minimum_required(VERSION 3.0.2)
project(drive)
find_package(catkin REQUIRED COMPONENTS rospy std_msgs)
catkin_python_setup()
catkin_package()
install(PROGRAMS src/drive/driver.py DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
install(DIRECTORY launch/ DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/launch)
"""
SETUP = """\
import os
from glob import glob

ROS_VERSION = int(os.environ['ROS_VERSION'])

if ROS_VERSION == 1:
    from distutils.core import setup
    from catkin_pkg.python_setup import generate_distutils_setup

    setup(**generate_distutils_setup(packages=['drive'], package_dir={'': 'src'}))
elif ROS_VERSION == 2:
    from setuptools import setup

    package_name = 'drive'
    setup(
        name=package_name,
        packages=[package_name],
        data_files=[
            ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
            (os.path.join('share', package_name), ['package.xml']),
            (os.path.join('share', package_name), glob('launch/*.launch.py')),
        ],
        entry_points={'console_scripts': [
            '{} = {}.{}:main'.format('driver', package_name, 'driver')]},
        package_dir={'': 'src'},
    )
"""
DRIVER = """\
import os

from std_msgs.msg import String

ROS_VERSION = int(os.environ.get("ROS_VERSION", 0))

if ROS_VERSION == 1:
    import rospy

    def start():
        rospy.init_node("driver")
        speed = rospy.get_param("~speed", 1.0)
        return rospy.Publisher("status", String, queue_size=speed)

elif ROS_VERSION == 2:
    import rclpy

    def start():
        node = rclpy.create_node("driver")
        node.declare_parameter("speed", 1.0)
        return node.create_publisher(String, "status", 10)


def main():
    start()


if __name__ == "__main__":
    main()
"""
ROS1_LAUNCH = """\
<launch>
  <node pkg="drive" type="driver.py" name="driver">
    <param name="speed" value="2.0"/>
  </node>
</launch>
"""
ROS2_DRIVER_LAUNCH = """\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='drive', executable='driver', name='driver',
             parameters=[{'speed': 2.0}]),
    ])
"""
ROS2_ALL_LAUNCH = """\
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    share = get_package_share_directory('drive')
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join(share, 'driver.launch.py'))),
    ])
"""


def _workspace(root: Path) -> Path:
    files = {"drive/package.xml": MANIFEST, "drive/CMakeLists.txt": CMAKE,
             "drive/setup.py": SETUP, "drive/resource/drive": "",
             "drive/src/drive/__init__.py": "", "drive/src/drive/driver.py": DRIVER,
             "drive/launch/driver.launch": ROS1_LAUNCH,
             "drive/launch/driver.launch.py": ROS2_DRIVER_LAUNCH,
             "drive/launch/all.launch.py": ROS2_ALL_LAUNCH}
    for rel, text in files.items():
        path = root / "src" / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    (root / "src" / "drive" / "src" / "drive" / "driver.py").chmod(0o755)
    return root


@pytest.fixture
def checked(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> dict:
    for name in ("ROS_VERSION", "ROS_DISTRO", "ROS_PYTHON_VERSION"):
        monkeypatch.delenv(name, raising=False)
    root = _workspace(tmp_path / "ws")
    out = tmp_path / "model.json"
    assert main(["extract", str(root), "-o", str(out), "--no-cache", "-q"]) == 0
    return json.loads(out.read_text())


def _links(model: dict, configuration: str) -> list[tuple[str, str, str, str | None]]:
    (found,) = [c for c in model["configurations"] if c["name"] == configuration]
    return sorted((link["kind"], link["node"], link["name"], link["type"])
                  for link in found["links"])


def test_the_package_is_said_to_build_per_ros_version(checked: dict) -> None:
    said = [(d["code"], d["location"]["file"], d["location"]["line"], d["message"])
            for d in checked["diagnostics"] if d["code"] == "PACKAGE_BUILD_BY_ROS_VERSION"]
    assert [s[:3] for s in said] == [("PACKAGE_BUILD_BY_ROS_VERSION",
                                      "drive/package.xml", 12)]
    assert "catkin for ROS 1, ament_python for ROS 2" in said[0][3]


def test_each_launch_file_finds_the_executable_of_its_build(checked: dict) -> None:
    missing = [f for f in checked["findings"] if f["rule"] == "launch-missing-reference"]
    assert missing == []
    assert {c["name"] for c in checked["configurations"]} == {"drive/driver", "drive/all"}


def test_each_node_is_read_with_its_own_ros_version(checked: dict) -> None:
    assert _links(checked, "drive/driver") == [
        ("publish", "/driver", "/status", "std_msgs/String"),
        ("read", "/driver", "/driver/speed", "double")]
    # the share folder is what the ROS 2 setup.py installs: driver.launch.py at its top
    assert _links(checked, "drive/all") == [
        ("publish", "/driver", "/status", "std_msgs/msg/String"),
        ("read", "/driver", "/driver/speed", "double")]


def test_a_ros_version_given_reads_one_build(tmp_path: Path,
                                             monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ROS_DISTRO", "humble")
    monkeypatch.setenv("ROS_VERSION", "2")
    root = _workspace(tmp_path / "ws")
    out = tmp_path / "model.json"
    assert main(["extract", str(root), "-o", str(out), "--no-cache", "-q"]) == 0
    model = json.loads(out.read_text())
    assert not [d for d in model["diagnostics"]
                if d["code"] == "PACKAGE_BUILD_BY_ROS_VERSION"]
    (package,) = model["packages"]
    assert package["build_type"] == "ament_python"
    assert [n["executable"] for n in package["nodes"]] == ["driver"]
