"""A description file the build writes with configure_file into the package's folder
(hector_quadrotor_gazebo's urdf/CMakeLists.txt makes quadrotor_plugins.gazebo.xacro from
quadrotor_plugins.gazebo.xacro.in, each plugin macro the options choose one
``<xacro:NAME />`` line of ``@MODEL_PLUGINS_URDF@``). A checkout does not hold it: the
description that includes it lost every Gazebo plugin, "no such file". It is now read as
CMake would write it, with the values the CMake reading holds at the command; one it
cannot know leaves it unread, said with the command's place."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch import pipeline
from haros_arch.cmake.interpreter import Interpreter
from haros_arch.cmake.lexer import tokenize
from haros_arch.project import ConfigurationSpec, Project

LAUNCH = """\
<launch>
  <param name="robot_description"
         command="$(find xacro)/xacro '$(find bot)/urdf/bot.urdf.xacro'"/>
  <node name="spawn_bot" pkg="gazebo_ros" type="spawn_model"
        args="-urdf -param robot_description -model bot"/>
</launch>
"""

TOP = """\
<robot name="bot" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base_link"/>
  <link name="laser"/>
  <xacro:include filename="$(find bot)/urdf/plugins.gazebo.xacro"/>
</robot>
"""

TEMPLATE = """\
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="imu">
    <gazebo>
      <plugin name="imu" filename="libgazebo_ros_imu.so">
        <topicName>imu/data</topicName>
        <serviceName>imu/calibrate</serviceName>
        <bodyName>base_link</bodyName>
      </plugin>
    </gazebo>
  </xacro:macro>
  <xacro:macro name="laser">
    <gazebo reference="laser">
      <sensor type="ray" name="laser">
        <plugin name="laser" filename="libgazebo_ros_laser.so">
          <topicName>front/scan</topicName>
        </plugin>
      </sensor>
    </gazebo>
  </xacro:macro>
@PLUGINS_URDF@
</robot>
"""

CMAKE = """\
cmake_minimum_required(VERSION 3.0.2)
project(bot)
find_package(catkin REQUIRED)
catkin_package()
add_subdirectory(urdf)
"""

URDF_CMAKE = """\
set(PLUGINS)
option(USE_LASER "a laser" ON)
list(APPEND PLUGINS imu)
if(USE_LASER)
  list(APPEND PLUGINS laser)
endif()
set(PLUGINS_URDF {start})
foreach(PLUGIN ${{PLUGINS}})
  set(PLUGINS_URDF "${{PLUGINS_URDF}}  <xacro:${{PLUGIN}} />\\n")
endforeach()
configure_file(plugins.gazebo.xacro.in ${{PROJECT_SOURCE_DIR}}/urdf/plugins.gazebo.xacro @ONLY)
"""


def analyse(write_tree, start: str = ""):
    root = str(write_tree({
        "bot/package.xml": package_xml("bot"), "xacro/package.xml": package_xml("xacro"),
        "bot/CMakeLists.txt": CMAKE, "bot/urdf/CMakeLists.txt": URDF_CMAKE.format(start=start),
        "bot/urdf/plugins.gazebo.xacro.in": TEMPLATE, "bot/urdf/bot.urdf.xacro": TOP,
        "bot/launch/sim.launch": LAUNCH}))
    project = Project("p", os.path.join(root, "project.yaml"), workspace=[root],
                      configurations=[ConfigurationSpec("c", ["bot/launch/sim.launch"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    return model.configurations[0]


def test_a_description_file_the_build_writes_is_read_as_written(write_tree):
    config = analyse(write_tree)
    assert not [d for d in config.diagnostics if d.code == "ROBOT_DESCRIPTION_FILE"]
    (description,) = config.robot_descriptions
    # both plugins the options choose, placed in the template the build writes from
    assert sorted((p.name, p.location.file) for p in description.plugins) == [
        ("imu", "bot/urdf/plugins.gazebo.xacro.in"),
        ("laser", "bot/urdf/plugins.gazebo.xacro.in")]
    made = sorted((link.kind, link.resource.name) for link in config.links
                  if link.origin == "description")
    assert ("publish", "/front/scan") in made and ("publish", "/imu/data") in made


def test_a_written_file_with_a_value_not_known_is_not_read_and_says_why(write_tree):
    # the list starts from what a find_package would give: not known here
    config = analyse(write_tree, start="${laser_driver_URDF}")
    (found,) = [d for d in config.diagnostics if d.code == "ROBOT_DESCRIPTION_FILE"]
    assert (found.location.file, found.location.line) == ("bot/urdf/bot.urdf.xacro", 4)
    assert "made by configure_file at bot/urdf/CMakeLists.txt:11" in found.message
    assert "${PLUGINS_URDF}" in found.message
    (description,) = config.robot_descriptions
    assert description.plugins == [] and description.completeness == "partial"


def configured(tmp_path, program: str, template: str) -> tuple[str | None, str]:
    (tmp_path / "in.txt").write_text(template)
    it = Interpreter(str(tmp_path), {})
    it.run_file(tokenize(program, str(tmp_path / "CMakeLists.txt")))
    (made,) = it.configured
    return made.text, made.unknown


def test_configure_file_replaces_as_cmake_does(tmp_path):
    out = f"configure_file(in.txt {tmp_path}/out.txt"
    # a variable this reading empties is known to be empty
    assert configured(tmp_path, f"set(A x)\nset(B)\n{out} @ONLY)",
                      "@A@-${A}-@B@") == ("x-${A}-", "")
    assert configured(tmp_path, f"set(A x)\nset(B)\n{out})", "@A@-${A}-@B@") == ("x-x-", "")
    assert configured(tmp_path, f"set(ON_ 1)\nset(OFF_ NO)\n{out})",
                      "#cmakedefine ON_ 3\n#cmakedefine OFF_\n#cmakedefine01 OFF_\n") == (
        "#define ON_ 3\n/* #undef OFF_ */\n#define OFF_ 0\n", "")
    assert configured(tmp_path, f"{out} COPYONLY)", "@A@") == ("@A@", "")
    # what the reading does not know: a find_package result, an if() not decided
    text, why = configured(tmp_path, f"{out})", "@Foo_VERSION@")
    assert text is None and "${Foo_VERSION}" in why
    text, why = configured(tmp_path, f"if(Foo_FOUND)\n{out})\nendif()", "x")
    assert text is None and "if() not decided" in why
