"""A ROS 1 Gazebo plugin written against gazebo_plugins' GazeboRos helper.

Many Gazebo classic plugins (gazebo_plugins' diff drive, navigation_oru's steer drive and
fork lifter) build ``GazeboRosPtr(new GazeboRos(parent, sdf, "Name"))``, read their
settings with ``getParameter<T>(member, "tag", default)`` (the <plugin> element's child
``tag``, else the default) and talk on ``node()``, a handle in the namespace of the
element's <robotNamespace> (the model's name where absent). With the helper's header
not in the workspace the plugin's calls were missed (``advertise`` named no template)
and the node was partial; its topics are now named from its SDF, as a plugin that reads
``_sdf->Get<std::string>("tag")`` itself.
"""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project

PLUGIN = """\
#include <gazebo/gazebo.hh>
#include <gazebo_plugins/gazebo_ros_utils.h>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <sensor_msgs/JointState.h>
namespace gazebo {
class Lifter : public ModelPlugin {
public:
  void Load(physics::ModelPtr parent, sdf::ElementPtr sdf) {
    gazebo_ros_ = GazeboRosPtr(new GazeboRos(parent, sdf, "Lifter"));
    gazebo_ros_->isInitialized();
    gazebo_ros_->getParameter<std::string>(command_topic_, "commandTopic", "cmd_fork");
    gazebo_ros_->getParameter<double>(rate_, "updateRate", 100.0);
    gazebo_ros_->getParameterBoolean(publish_, "publishJointState", false);
    frame_ = gazebo_ros_->resolveTF("base_link");
    states_ = gazebo_ros_->node()->advertise<sensor_msgs::JointState>("joint_states", 1);
    ros::SubscribeOptions so = ros::SubscribeOptions::create<std_msgs::Float64>(
        command_topic_, 1, boost::bind(&Lifter::command, this, _1), ros::VoidPtr(), &queue_);
    command_ = gazebo_ros_->node()->subscribe(so);
  }
  void command(const std_msgs::Float64::ConstPtr&) {}
private:
  GazeboRosPtr gazebo_ros_;
  ros::Publisher states_;
  ros::Subscriber command_;
  ros::CallbackQueue queue_;
  std::string command_topic_, frame_;
  double rate_;
  bool publish_;
};
GZ_REGISTER_MODEL_PLUGIN(Lifter)
}
"""

DESCRIPTION = """\
<robot name="r"><link name="b"/>
<gazebo><plugin name="lift" filename="liblifter_plugin.so">
  <robotNamespace>/truck</robotNamespace><commandTopic>fork/cmd</commandTopic>
</plugin></gazebo>
<gazebo><plugin name="other" filename="liblifter_plugin.so">
  <robotNamespace>/second</robotNamespace>
</plugin></gazebo>
</robot>
"""

LAUNCH = """\
<launch>
  <param name="robot_description" command="cat $(find d)/urdf/r.urdf"/>
  <node name="spawn" pkg="gazebo_ros" type="spawn_model"
        args="-urdf -param robot_description -model truck"/>
</launch>
"""


def _model(write_tree):  # type: ignore[no-untyped-def]
    root = write_tree({
        "p/package.xml": package_xml("p", "catkin").replace(
            "</package>", "<depend>roscpp</depend><depend>std_msgs</depend>"
                          "<depend>sensor_msgs</depend><depend>gazebo_plugins</depend>"
                          "</package>"),
        "p/CMakeLists.txt": "project(p)\nfind_package(catkin REQUIRED)\n"
                            "add_library(lifter_plugin src/lifter.cpp)\n",
        "p/src/lifter.cpp": PLUGIN,
        "d/package.xml": package_xml("d", "catkin"),
        "d/CMakeLists.txt": "project(d)\nfind_package(catkin REQUIRED)\n",
        "d/urdf/r.urdf": DESCRIPTION,
        "d/launch/sim.launch": LAUNCH,
    })
    project = Project("lifter", os.path.join(str(root), "project.yaml"),
                      workspace=[str(root)],
                      configurations=[ConfigurationSpec("c", ["d/launch/sim.launch"], {})])
    return pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))


def test_helper_plugin_topics_named_from_its_sdf(write_tree) -> None:
    model = _model(write_tree)
    codes = [(d.code, d.message) for d in model.diagnostics if d.code in (
        "CPP_NODE_PARTIAL", "CPP_CALL_MISSED")]
    assert not codes, codes
    config = model.configurations[0]
    made = sorted((link.kind, link.resource.name) for link in config.links
                  if link.origin == "description")
    assert made == [
        # <commandTopic> where given, else the code's default; in <robotNamespace>
        ("publish", "/second/joint_states"), ("publish", "/truck/joint_states"),
        ("subscribe", "/second/cmd_fork"), ("subscribe", "/truck/fork/cmd")], made


def test_helper_plugin_leaves_the_description_known(write_tree) -> None:
    """Its helper's header, read from our stand-in, is not a library whose calls go
    unread: the description (and the Gazebo node) is not partial for it."""
    model = _model(write_tree)
    (description,) = model.configurations[0].robot_descriptions
    assert description.completeness_reasons == [], description.completeness_reasons
