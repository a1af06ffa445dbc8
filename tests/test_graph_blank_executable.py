"""A node whose executable is blank (Universal_Robots_ROS2_Driver 2477f13's spawner,
``executable="  "``; ROS 1's ``type=" "``): the package is in the workspace, the program
named is blank. It was NODE_NOT_FOUND, "node type controller_manager/ is not in the
workspace", which named no executable and called the package missing; now
NODE_EXECUTABLE_BLANK says what is wrong, still a launch-missing-reference. (A ROS 1
``type=" "`` was already refused where the launch file is read.)"""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

ROS2 = """<launch>
  <node pkg="drv" exec="  " name="spawner"/>
  <node pkg="drv" exec="nothing_here" name="other"/>
</launch>
"""

ROS1 = """<launch>
  <node pkg="drv" type=" " name="blank"/>
</launch>
"""


def _findings(write_tree, build_type: str, launch: str, name: str, distro: str):
    root = write_tree({
        "src/drv/package.xml": package_xml("drv", build_type),
        f"src/drv/launch/{name}": launch,
        "project.yaml": f"project: p\ndistro: {distro}\n"
                        f"configurations:\n  c: [drv/launch/{name}]\n",
    })
    model = analyse(load(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    config = model.configuration("c")
    return [(d.code, d.location.line, d.message) for d in config.diagnostics
            if d.code.startswith("NODE_")]


def test_a_blank_ros2_executable(write_tree) -> None:
    found = _findings(write_tree, "ament_cmake", ROS2, "a.launch.xml", "jazzy")
    assert [(code, line) for code, line, _ in found] == [
        ("NODE_EXECUTABLE_BLANK", 2), ("NODE_NOT_FOUND", 3)]
    assert "package drv is given a blank executable ('  ')" in found[0][2]


def test_a_blank_ros1_type_is_refused_by_the_launch_reader(write_tree) -> None:
    # (as before: roslaunch's "package and type must be non-empty", LAUNCH_BAD_VALUE,
    # and no node)
    assert _findings(write_tree, "catkin", ROS1, "a.launch", "noetic") == []
