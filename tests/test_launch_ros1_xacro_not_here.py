"""A ROS 1 ``<param command="$(find xacro)/xacro FILE">`` where xacro is neither in the
workspace nor installed here (71 infos in a census of 29 real trees): the command is
never run, so its program's folder is not needed (roslaunch runs ``$(find xacro)/xacro``
from xacro's ``lib`` folder, ``substitution_args._find_executable``; the robot
description, the spawner's model, is read from FILE). The info says what is not known,
the command's output, as it does when xacro is here (``command "..." is not run``), not
that the package is missing; the description is read. A package not here whose folder
holds the file the command reads is still said: that file is not known."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project

LAUNCH = """\
<launch>
  <param name="robot_description" command="$(find xacro)/xacro '$(find bot)/urdf/r.urdf.xacro'"/>
  <param name="legacy" command=" $(find xacro)/xacro.py $(find bot)/urdf/r.urdf.xacro"/>
  <param name="other" command="$(find xacro)/xacro $(find other_desc)/urdf/o.urdf.xacro"/>
  <node name="urdf_spawner" pkg="gazebo_ros" type="spawn_model"
        args="-urdf -model robot -param robot_description"/>
</launch>
"""

ROBOT = """\
<robot name="bot" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base_link"/><link name="arm"/>
  <joint name="j" type="fixed"><parent link="base_link"/><child link="arm"/></joint>
</robot>
"""


def analyse(write_tree, files: dict[str, str]):
    root = str(write_tree({"bot/package.xml": package_xml("bot"),
                           "bot/launch/sim.launch": LAUNCH, "bot/urdf/r.urdf.xacro": ROBOT,
                           **files}))
    project = Project("p", os.path.join(root, "project.yaml"), workspace=[root],
                      configurations=[ConfigurationSpec("c", ["bot/launch/sim.launch"], {})])
    config = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1)
                              ).configurations[0]
    unknown = [(d.location.line, d.message.replace(root, "WS")) for d in config.diagnostics
               if d.code == "LAUNCH_UNKNOWN_VALUE"]
    return config, unknown


def test_find_xacro_not_here_says_the_command_is_not_run(write_tree):
    config, unknown = analyse(write_tree, {})
    keeps = "; what depends on it keeps '?'"
    assert unknown == [
        (2, "command \"$(find xacro)/xacro 'WS/bot/urdf/r.urdf.xacro'\" is not run" + keeps),
        (3, "command \" $(find xacro)/xacro.py WS/bot/urdf/r.urdf.xacro\" is not run" + keeps),
        # the file this command reads is in a package not here: not known
        (4, "package other_desc is not in the workspace nor installed here" + keeps)]
    (description,) = [d for d in config.robot_descriptions if d.name == "/robot_description"]
    assert sorted(description.links) == ["arm", "base_link"]


def test_the_same_info_as_with_xacro_here(write_tree):
    _, unknown = analyse(write_tree, {"xacro/package.xml": package_xml("xacro")})
    assert unknown[0] == (
        2, "command \"WS/xacro/xacro 'WS/bot/urdf/r.urdf.xacro'\" is not run; what depends "
           "on it keeps '?'")
