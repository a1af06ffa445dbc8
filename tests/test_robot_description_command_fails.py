"""A robot description file that a command the launch runs cannot read: roslaunch runs a
``<param command="...">`` as it loads the launch and stops on a command that fails
(roslaunch/loader.py: "Cannot load command parameter [...]: command [...] returned with
code [1]", an XmlParseException), and ros2 launch stops on a ``Command`` substitution
that fails (SubstitutionFailure), whether or not a node reads the parameter. xacro fails
on a file that is not there, on an include that is not there and on XML that is not
well-formed. That is an error, ROBOT_DESCRIPTION_COMMAND_FAILS, not the warning
ROBOT_DESCRIPTION_FILE, which stays for what does not stop the launch: a parameter under
a condition not known statically, a file a spawner reads itself (``-file``), a file the
package's CMake writes whose value is not known here."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project

LAUNCH = """\
<launch>
  <arg name="extra" default="$(env BOT_EXTRA)"/>
  <param name="robot_description" command="xacro '$(find bot)/urdf/{top}'"/>
  <param name="arm_description" command="xacro '$(find bot)/urdf/gone_arm.xacro'"
         if="$(arg extra)"/>
  <node name="spawn_world" pkg="gazebo_ros" type="spawn_model"
        args="-urdf -model world -file $(find bot)/urdf/gone_world.urdf"/>
</launch>
"""

TOP = """\
<robot name="bot" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base_link"/>
  {body}
</robot>
"""


def said(write_tree, top: str, body: str = "", launch: str = LAUNCH
         ) -> list[tuple[str, str, str | None, int]]:
    root = str(write_tree({"bot/package.xml": package_xml("bot"),
                           "bot/launch/load.launch": launch.format(top=top),
                           "bot/urdf/top.urdf.xacro": TOP.format(body=body)}))
    project = Project("p", os.path.join(root, "project.yaml"), workspace=[root],
                      configurations=[ConfigurationSpec("c", ["bot/launch/load.launch"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    return sorted((d.code, d.severity, d.location.file, d.location.line)
                  for d in model.configurations[0].diagnostics
                  if d.code.startswith("ROBOT_DESCRIPTION"))


def test_a_missing_top_file_stops_the_launch(write_tree):
    assert said(write_tree, "gone.urdf.xacro") == [
        ("ROBOT_DESCRIPTION_COMMAND_FAILS", "error", "bot/launch/load.launch", 3),
        # under a condition not known statically (BOT_EXTRA is not set here)
        ("ROBOT_DESCRIPTION_FILE", "warning", "bot/launch/load.launch", 4),
        # the spawner's own file
        ("ROBOT_DESCRIPTION_FILE", "warning", "bot/launch/load.launch", 6)]


def test_a_missing_include_or_bad_xml_stops_the_launch(write_tree):
    # (the description is read for a spawner that takes the parameter)
    spawned = LAUNCH.replace('-urdf -model world -file $(find bot)/urdf/gone_world.urdf',
                             '-urdf -model bot -param robot_description')
    include = said(write_tree, "top.urdf.xacro",
                   '<xacro:include filename="$(find bot)/urdf/gone_part.xacro"/>', spawned)
    broken = said(write_tree, "top.urdf.xacro", "<link name='arm'>", spawned)
    assert ("ROBOT_DESCRIPTION_COMMAND_FAILS", "error", "bot/urdf/top.urdf.xacro", 3) \
        in include
    assert [s[:2] for s in broken if s[2] == "bot/urdf/top.urdf.xacro"] == [
        ("ROBOT_DESCRIPTION_COMMAND_FAILS", "error")]


def test_a_file_a_spawner_reads_is_no_command(write_tree):
    # gone_world.urdf is read by spawn_model itself: it fails, the launch goes on
    assert ("ROBOT_DESCRIPTION_FILE", "warning", "bot/launch/load.launch", 6) in said(
        write_tree, "top.urdf.xacro")


def test_a_text_file_that_is_not_there_is_said_once(write_tree):
    # roslaunch's own read of textfile= raises (FileNotFoundError): the launch's reader
    # says it (LAUNCH_BAD_VALUE, an error), not the description's reader again
    root = str(write_tree({"bot/package.xml": package_xml("bot"),
                           "bot/launch/load.launch": (
                               '<launch>\n  <param name="robot_description" '
                               'textfile="$(find bot)/urdf/gone.urdf"/>\n</launch>\n')}))
    project = Project("p", os.path.join(root, "project.yaml"), workspace=[root],
                      configurations=[ConfigurationSpec("c", ["bot/launch/load.launch"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    assert sorted((d.code, d.location.line) for d in model.configurations[0].diagnostics
                  if d.severity in ("warning", "error")) == [("LAUNCH_BAD_VALUE", 2)]
