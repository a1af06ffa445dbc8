"""Gazebo classic's own plugins (the ``plugins`` folder Gazebo 11 ships: unitree_ros'
descriptions load ``libLinkPlot3DPlugin.so`` to draw the trunk's path, fixed wings
``libLiftDragPlugin.so``) talk Gazebo transport only: they were GAZEBO_PLUGIN_UNKNOWN and
left the gazebo instance partial, which undecided every check over its names. A library
of another name stays unknown, and a workspace package building a plugin of one of those
names is read as its own."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project
from haros_arch.robot.gazebo_plugins import classic_builtin

DESCRIPTION = """\
<robot name="r"><link name="trunk"/>
<gazebo>
  <plugin filename="{filename}" name="plot">
    <link><name>trunk</name></link>
  </plugin>
  <plugin filename="libgazebo_ros_force.so" name="gazebo_ros_force">
    <bodyName>trunk</bodyName><topicName>apply_force/trunk</topicName>
  </plugin>
</gazebo>
</robot>
"""

LAUNCH = """\
<launch>
  <param name="robot_description" command="cat $(find d)/urdf/r.urdf"/>
  <node name="spawn" pkg="gazebo_ros" type="spawn_model"
        args="-urdf -param robot_description -model dog"/>
</launch>
"""


def _config(write_tree, filename: str):
    root = write_tree({
        "d/package.xml": package_xml("d", "catkin"),
        "d/CMakeLists.txt": "project(d)\nfind_package(catkin REQUIRED)\n",
        "d/urdf/r.urdf": DESCRIPTION.format(filename=filename),
        "d/launch/sim.launch": LAUNCH,
    })
    project = Project("plot", os.path.join(str(root), "project.yaml"), workspace=[str(root)],
                      configurations=[ConfigurationSpec("c", ["d/launch/sim.launch"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    return model.configurations[0]


def test_a_gazebo_classic_plugin_is_known_and_adds_nothing(write_tree) -> None:
    config = _config(write_tree, "libLinkPlot3DPlugin.so")
    assert "GAZEBO_PLUGIN_UNKNOWN" not in {d.code for d in config.diagnostics}
    (gazebo,) = [n for n in config.nodes if n.name == "/gazebo"]
    made = sorted((link.kind, link.resource.name) for link in gazebo.links
                  if link.origin == "description")
    assert made == [("subscribe", "/apply_force/trunk")]
    assert not any("LinkPlot3D" in r for r in gazebo.completeness_reasons)
    (description,) = config.robot_descriptions
    assert description.plugins[0].filename == "libLinkPlot3DPlugin.so"


def test_another_library_stays_unknown(write_tree) -> None:
    config = _config(write_tree, "libLinkPlot4DPlugin.so")
    assert "GAZEBO_PLUGIN_UNKNOWN" in {d.code for d in config.diagnostics}


def test_the_names_gazebo_gives_its_libraries() -> None:
    assert classic_builtin("libLiftDragPlugin.so")
    assert classic_builtin("LiftDragPlugin")
    assert classic_builtin("/usr/lib/x86_64-linux-gnu/gazebo-11/plugins/libWindPlugin.so")
    assert not classic_builtin("libgazebo_ros_force.so")
    assert not classic_builtin("libunitreeFootContactPlugin.so")
