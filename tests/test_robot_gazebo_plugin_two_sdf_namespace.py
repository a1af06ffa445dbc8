"""A ROS 1 Gazebo plugin's handle whose namespace is made of two children of its SDF.

hector_gazebo's sonar (and magnetic, hector_quadrotor's baro) serve their
dynamic_reconfigure on ``ros::NodeHandle(*node_handle_, topic_)``: ``node_handle_`` is
``new ros::NodeHandle(namespace_)``, ``namespace_`` the plugin's <robotNamespace> (the
spawner's namespace where absent), ``topic_`` its <topicName>. Their services and
parameters were ``/?/?/set_parameters``, ``/?/?/gaussian_noise``: with two unknown runs
in the handle's namespace the code gave neither its element; each is now filled from the
description, in order (``/uav1/sonar_height/set_parameters``).
"""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project

PLUGIN = """\
#include <gazebo/gazebo.hh>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <std_srvs/Empty.h>
namespace gazebo {
class Sonar : public SensorPlugin {
public:
  void Load(sensors::SensorPtr, sdf::ElementPtr sdf) {
    namespace_.clear();
    topic_ = "sonar";
    if (sdf->HasElement("robotNamespace"))
      namespace_ = sdf->GetElement("robotNamespace")->GetValue()->GetAsString();
    if (sdf->HasElement("topicName"))
      topic_ = sdf->GetElement("topicName")->GetValue()->GetAsString();
    node_handle_ = new ros::NodeHandle(namespace_);
    publisher_ = node_handle_->advertise<std_msgs::Float64>(topic_, 1);
    ros::NodeHandle beside(*node_handle_, topic_);
    server_ = beside.advertiseService("reset", &Sonar::reset, this);
  }
  bool reset(std_srvs::Empty::Request&, std_srvs::Empty::Response&) { return true; }
private:
  ros::NodeHandle* node_handle_;
  ros::Publisher publisher_;
  ros::ServiceServer server_;
  std::string namespace_, topic_;
};
GZ_REGISTER_SENSOR_PLUGIN(Sonar)
}
"""

DESCRIPTION = """\
<robot name="r"><link name="b"/>
<gazebo reference="b"><sensor type="ray" name="s1">
  <plugin name="s1" filename="libsonar_plugin.so"><topicName>sonar_height</topicName></plugin>
</sensor></gazebo>
<gazebo reference="b"><sensor type="ray" name="s2">
  <plugin name="s2" filename="libsonar_plugin.so">
    <robotNamespace>/side</robotNamespace><topicName>range</topicName>
  </plugin>
</sensor></gazebo>
</robot>
"""

LAUNCH = """\
<launch>
  <group ns="team/uav1">
    <param name="robot_description" command="cat $(find d)/urdf/r.urdf"/>
    <node name="spawn" pkg="gazebo_ros" type="spawn_model"
          args="-urdf -param robot_description -model uav1"/>
  </group>
</launch>
"""


def test_each_unknown_run_of_the_handle_namespace_from_its_sdf_child(write_tree) -> None:
    root = write_tree({
        "p/package.xml": package_xml("p", "catkin").replace(
            "</package>", "<depend>roscpp</depend><depend>std_msgs</depend>"
                          "<depend>std_srvs</depend><depend>gazebo_ros</depend></package>"),
        "p/CMakeLists.txt": "project(p)\nfind_package(catkin REQUIRED)\n"
                            "add_library(sonar_plugin src/sonar.cpp)\n",
        "p/src/sonar.cpp": PLUGIN,
        "d/package.xml": package_xml("d", "catkin"),
        "d/CMakeLists.txt": "project(d)\nfind_package(catkin REQUIRED)\n",
        "d/urdf/r.urdf": DESCRIPTION,
        "d/launch/sim.launch": LAUNCH,
    })
    project = Project("sonar", os.path.join(str(root), "project.yaml"),
                      workspace=[str(root)],
                      configurations=[ConfigurationSpec("c", ["d/launch/sim.launch"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    config = model.configurations[0]
    made = sorted((link.kind, link.resource.name) for link in config.links
                  if link.origin == "description")
    assert made == [
        # no <robotNamespace>: the spawner's namespace; then <topicName>
        ("publish", "/side/range"), ("publish", "/team/uav1/sonar_height"),
        ("server", "/side/range/reset"), ("server", "/team/uav1/sonar_height/reset")], made
