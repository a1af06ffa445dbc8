"""gazebo_plugins' force plugin (``libgazebo_ros_force.so``), which unitree_ros'
aliengoZ1 and laikago descriptions load to push their trunk (``<bodyName>trunk``,
``<topicName>/apply_force/trunk``), was GAZEBO_PLUGIN_UNKNOWN. ROS 1 (noetic
gazebo_ros_force.cpp): a ``ros::NodeHandle(<robotNamespace> + "/")``, the spawner's
namespace where absent, subscribes to ``<topicName>``, a ``geometry_msgs/Wrench``. ROS 2
(gazebo_ros_force.cpp of the ros2 branch): the plugin's node subscribes to
``gazebo_ros_force``, a ``geometry_msgs/msg/Wrench``."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project
from haros_arch.robot.gazebo_plugins import plugin_row

DESCRIPTION = """\
<robot name="r"><link name="trunk"/>
<gazebo>
  <plugin filename="libgazebo_ros_force.so" name="gazebo_ros_force">
    <bodyName>trunk</bodyName><topicName>apply_force/trunk</topicName>
  </plugin>
</gazebo>
</robot>
"""

LAUNCH = """\
<launch>
  <group ns="dog">
    <param name="robot_description" command="cat $(find d)/urdf/r.urdf"/>
    <node name="spawn" pkg="gazebo_ros" type="spawn_model"
          args="-urdf -param robot_description -model dog"/>
  </group>
</launch>
"""


def test_ros1_force_plugin_subscribes_to_its_topic(write_tree) -> None:
    root = write_tree({
        "d/package.xml": package_xml("d", "catkin"),
        "d/CMakeLists.txt": "project(d)\nfind_package(catkin REQUIRED)\n",
        "d/urdf/r.urdf": DESCRIPTION,
        "d/launch/sim.launch": LAUNCH,
    })
    project = Project("force", os.path.join(str(root), "project.yaml"),
                      workspace=[str(root)],
                      configurations=[ConfigurationSpec("c", ["d/launch/sim.launch"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    config = model.configurations[0]
    made = sorted((link.kind, link.resource.name, link.type) for link in config.links
                  if link.origin == "description")
    assert made == [("subscribe", "/dog/apply_force/trunk", "geometry_msgs/Wrench")], made
    assert "GAZEBO_PLUGIN_UNKNOWN" not in {d.code for d in config.diagnostics}


def test_ros2_force_plugin_row() -> None:
    row = plugin_row("libgazebo_ros_force.so", 2)
    assert row is not None
    assert [(e.kind, e.name, e.type) for e in row.entities] == [
        ("subscribe", "gazebo_ros_force", "geometry_msgs/msg/Wrench")]
