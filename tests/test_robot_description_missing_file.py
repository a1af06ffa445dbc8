"""A launch file whose xacro command names a description file that is not there
(stretch_ros's stretch_rtabmap/launch/gazebo/gazebo.launch:9 names
stretch_gazebo/urdf/stretch_gazebo.urdf.xacro, a file the repository no longer has):
ROBOT_DESCRIPTION_FILE was placed at line 0 of the missing file, a place nobody can
open; it is now at the launch file's line that gives the command. A file missing deeper
(an include of the description) keeps its own place, the including element's line.
(Either makes the command fail, and roslaunch stop: ROBOT_DESCRIPTION_COMMAND_FAILS,
tests/test_robot_description_command_fails.py.)"""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project

LAUNCH = """\
<launch>
  <arg name="model" default="$(find bot)/urdf/{file}"/>

  <param name="robot_description" command="$(find xacro)/xacro $(arg model)"/>
  <node name="urdf_spawner" pkg="gazebo_ros" type="spawn_model"
        args="-urdf -model robot -param robot_description"/>
</launch>
"""

TOP = """\
<robot name="bot" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base_link"/>
  <xacro:include filename="$(find bot)/urdf/part_gone.xacro"/>
</robot>
"""


def places(write_tree, file: str) -> list[tuple[str | None, int, str]]:
    root = str(write_tree({"bot/package.xml": package_xml("bot"),
                           "xacro/package.xml": package_xml("xacro"),
                           "bot/launch/sim.launch": LAUNCH.format(file=file),
                           "bot/urdf/top.urdf.xacro": TOP}))
    project = Project("p", os.path.join(root, "project.yaml"), workspace=[root],
                      configurations=[ConfigurationSpec("c", ["bot/launch/sim.launch"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    return [(d.location.file, d.location.line, d.message)
            for d in model.configurations[0].diagnostics
            if d.code == "ROBOT_DESCRIPTION_COMMAND_FAILS"]


def test_a_missing_description_file_is_said_where_the_launch_file_names_it(write_tree):
    ((file, line, message),) = places(write_tree, "gone.urdf.xacro")
    assert (file, line) == ("bot/launch/sim.launch", 4)
    assert "bot/urdf/gone.urdf.xacro" in message


def test_a_missing_included_file_is_said_at_the_include(write_tree):
    ((file, line, message),) = places(write_tree, "top.urdf.xacro")
    assert (file, line) == ("bot/urdf/top.urdf.xacro", 3)
    assert "bot/urdf/part_gone.xacro" in message


UNSPAWNED = """\
<launch>
  <param name="robot_description"
         command="$(find xacro)/xacro.py '$(find bot)/urdf/{file}' prefix:=a_"/>
  <param name="other" command="$(find xacro)/xacro '$(find bot)/urdf/top.urdf.xacro'"/>
</launch>
"""


def test_a_missing_file_is_said_when_no_node_here_takes_the_description(write_tree):
    # kuka_experimental's load_kr60_ha.launch ran xacro on urdf/kr60_ha.xacro, the file
    # being kr60ha.xacro: roslaunch stops on the failed command, spawned or not; and
    # xacro not found here (installed on the robot) changes nothing of that
    def said(file: str) -> list[tuple[str | None, int, str]]:
        root = str(write_tree({"bot/package.xml": package_xml("bot"),
                               "bot/launch/load.launch": UNSPAWNED.format(file=file),
                               "bot/urdf/top.urdf.xacro": TOP}))
        project = Project("p", os.path.join(root, "project.yaml"), workspace=[root],
                          configurations=[ConfigurationSpec("c", ["bot/launch/load.launch"],
                                                            {})])
        model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
        return [(d.location.file, d.location.line, d.message) for d in
                model.configurations[0].diagnostics
                if d.code == "ROBOT_DESCRIPTION_COMMAND_FAILS"]

    ((file, line, message),) = said("kr60_ha.xacro")
    assert (file, line) == ("bot/launch/load.launch", 2)
    assert "bot/urdf/kr60_ha.xacro" in message
    assert said("top.urdf.xacro") == []
