"""Gazebo classic plugins a workspace package builds (a library registering a class with
``GZ_REGISTER_<KIND>_PLUGIN``): their calls come from their C++, with the names their
code takes from the <plugin> element's SDF children filled from the robot description.
They were GAZEBO_PLUGIN_UNKNOWN, the Gazebo node partial (uuv_simulator, rotors_simulator,
hector_gazebo build many). fixtures/robot/classic_ros1 and classic_ros2."""

from __future__ import annotations

import os
import shutil

from conftest import FIXTURES, package_xml

from haros_arch import pipeline
from haros_arch.model.runtime import Configuration
from haros_arch.project import ConfigurationSpec, Project
from haros_arch.workspace import scan

ROS1 = str(FIXTURES / "robot" / "classic_ros1")
ROS2 = str(FIXTURES / "robot" / "classic_ros2")


def configuration(root: str, launch: str) -> Configuration:
    project = Project("classic", os.path.join(root, "project.yaml"), workspace=[root],
                      configurations=[ConfigurationSpec("c", [launch], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    return model.configurations[0]


def made(config: Configuration) -> list[tuple[str, str, str, str | None, int]]:
    return sorted((link.node.name, link.kind, link.resource.name, link.type,
                   link.location.line) for link in config.links
                  if link.origin == "description")


def test_ros1_plugin_of_the_workspace_makes_its_code_calls_on_the_gazebo_node() -> None:
    config = configuration(ROS1, "depth_description/launch/sim.launch")
    assert made(config) == [
        # gauge2: no <robotNamespace>, the spawner's -robot_namespace; no <topicName>,
        # the code's default; a global <resetService> stays global
        ("/gazebo", "publish", "/fleet/depth", "std_msgs/Float64", 27),
        # gauge: <robotNamespace> and <topicName> (a xacro argument's default) given
        ("/gazebo", "publish", "/sub/pressure/depth", "std_msgs/Float64", 27),
        # <statusTopic>, given by neither the description nor the code, is wholly
        # unknown in both: it may be global, so in no namespace
        ("/gazebo", "publish", "?", "std_msgs/Float64", 33),
        ("/gazebo", "publish", "?", "std_msgs/Float64", 33),
        ("/gazebo", "server", "/global_reset", "std_srvs/Empty", 28),
        ("/gazebo", "server", "/sub/reset_gauge", "std_srvs/Empty", 28),
        ("/gazebo", "subscribe", "/fleet/set_offset", "std_msgs/Float64", 31),
        ("/gazebo", "subscribe", "/sub/set_offset", "std_msgs/Float64", 31),
    ]
    # each call at its line of the plugin's code
    assert {link.location.file for link in config.links if link.origin == "description"} \
        == {"depth_plugins/src/depth_gauge.cpp"}
    # the thruster (Gazebo transport only) makes no ROS call and is known; the library
    # no package builds is still unknown
    unknown = [(d.message, d.location.line) for d in config.diagnostics
               if d.code == "GAZEBO_PLUGIN_UNKNOWN"]
    assert unknown == [("Gazebo plugin libnot_built_here.so loaded by /gazebo is not known",
                        18)]
    (description,) = config.robot_descriptions
    assert [(p.name, p.node) for p in description.plugins] == [
        ("gauge", "/gazebo"), ("gauge2", "/gazebo"), ("thruster", "/gazebo"),
        ("elsewhere", None), ("sonar_camera", "/gazebo")]
    # the camera builds on gazebo_plugins' utilities, which the workspace does not have:
    # what they make is not read, and the description says so
    assert description.completeness_reasons == [
        "Gazebo plugin libnot_built_here.so loaded by /gazebo is not known "
        "(depth_description/urdf/sub.urdf.xacro:18)",
        "Gazebo plugin sonar_camera (depth_plugins/sonar_camera_plugin): "
        "depth_plugins/include/depth_plugins/sonar_camera.h includes "
        "gazebo_plugins/gazebo_ros_camera_utils.h, whose classes make calls that are not "
        "read (depth_description/urdf/sub.urdf.xacro:22)"]
    # no ROS parameter is read for the SDF elements
    assert not [link for link in config.links if "sdf" in link.resource.name]


def test_ros1_plugin_node_of_the_build_stage() -> None:
    workspace = scan([ROS1], {})
    package = workspace.packages["depth_plugins"]
    pipeline.read_build_files(package, workspace)
    plugins = sorted((n.executable, n.kind, n.plugin_class, n.plugin_base, n.sources)
                     for n in package.nodes)
    assert plugins == [
        ("depth_gauge_plugin", "plugin", "DepthGauge", "gazebo::ModelPlugin",
         ["depth_plugins/src/depth_gauge.cpp"]),
        ("sonar_camera_plugin", "plugin", "SonarCamera", "gazebo::SensorPlugin",
         ["depth_plugins/src/sonar_camera.cpp"]),
        ("thruster_plugin", "plugin", "Thruster", "gazebo::ModelPlugin",
         ["depth_plugins/src/thruster.cpp"])]


def test_ros2_plugin_of_the_workspace_is_a_node_of_its_own() -> None:
    config = configuration(ROS2, "arm_description/launch/sim.launch.py")
    assert made(config) == [
        # <joint_name> fills the code's ``joint + "_state"``; <ros><namespace> and
        # <remapping> apply to the plugin's gazebo_ros node, named by the <plugin>
        ("/arm/gripper", "publish", "/arm/left_finger_state", "std_msgs/msg/Float64", 24),
        ("/arm/gripper", "server", "/arm/gripper/grasp", "std_srvs/srv/Trigger", 27),
        ("/arm/gripper", "subscribe", "/arm/gripper/command", "std_msgs/msg/Float64", 25),
        # a plugin that makes an rclcpp node of its own: named as its code names it (the
        # <ros> element is gazebo_ros::Node's, not this node's)
        ("/arm_tools/control", "subscribe", "/arm_tools/reset", "std_msgs/msg/Empty", 17),
    ]
    assert not [d for d in config.diagnostics if d.code == "GAZEBO_PLUGIN_UNKNOWN"]
    (instance,) = [n for n in config.nodes if n.name == "/arm/gripper"]
    assert instance.node is not None
    assert (instance.node.name, instance.node.completeness) == (
        "arm_plugins/arm_gripper_plugin", "complete")
    (description,) = config.robot_descriptions
    assert description.completeness == "complete"


def test_a_plugin_whose_code_is_partial_leaves_the_gazebo_node_partial(write_tree) -> None:
    """What the parse cannot read of the plugin is said on the Gazebo node: never an
    empty interface taken for a known one."""
    root = write_tree({
        "p/package.xml": package_xml("p", "catkin"),
        "p/CMakeLists.txt": "project(p)\nfind_package(catkin REQUIRED)\n"
                            "add_library(broken_plugin src/broken.cpp)\n",
        "p/src/broken.cpp": "#include <gazebo/gazebo.hh>\n#include <ros/ros.h>\n"
                            "namespace gazebo {\nclass Broken : public ModelPlugin {\n"
                            "public:\n  void Load(physics::ModelPtr, sdf::ElementPtr s) {\n"
                            "    ros::NodeHandle nh;\n    nh.advertise<std_msgs::Float64>(\n"
                            "      ((( s->Get<std::string>(\"topic\"), 1);\n  }\n};\n"
                            "GZ_REGISTER_MODEL_PLUGIN(Broken)\n}\n",
        "d/package.xml": package_xml("d", "catkin"),
        "d/CMakeLists.txt": "project(d)\nfind_package(catkin REQUIRED)\n",
        "d/urdf/r.urdf": "<robot name=\"r\"><link name=\"b\"/><gazebo>"
                         "<plugin name=\"x\" filename=\"libbroken_plugin.so\"/>"
                         "</gazebo></robot>\n",
        "d/launch/sim.launch": "<launch><param name=\"robot_description\" "
                               "command=\"cat $(find d)/urdf/r.urdf\"/>"
                               "<node name=\"s\" pkg=\"gazebo_ros\" type=\"spawn_model\" "
                               "args=\"-urdf -param robot_description -model r\"/></launch>\n",
    })
    config = configuration(str(root), "d/launch/sim.launch")
    assert not [d for d in config.diagnostics if d.code == "GAZEBO_PLUGIN_UNKNOWN"]
    (description,) = config.robot_descriptions
    assert description.completeness == "partial"
    assert any("p/broken_plugin" in reason and "d/urdf/r.urdf:1" in reason
               for reason in description.completeness_reasons)


def test_ros1_plugin_namespace_member_cleared_when_the_sdf_gives_none(tmp_path) -> None:
    # hector_gazebo_plugins' magnetic, sonar and baro plugins: ``if (HasElement(
    # "robotNamespace")) namespace_ = ...; else namespace_.clear();``, a member written
    # twice, the SDF's value or "" (a string's clear() was a change in place, not known:
    # ``/?/magnetic``)
    root = tmp_path / "ws"
    shutil.copytree(ROS1, root)
    source = root / "depth_plugins" / "src" / "depth_gauge.cpp"
    code = source.read_text()
    for old, new in (
            ('    std::string ns;\n    if (sdf->HasElement("robotNamespace"))\n'
             '      ns = sdf->GetElement("robotNamespace")->Get<std::string>();\n',
             '    if (sdf->HasElement("robotNamespace"))\n'
             '      namespace_ = sdf->GetElement("robotNamespace")->Get<std::string>();\n'
             '    else\n      namespace_.clear();\n'),
            ("new ros::NodeHandle(ns)", "new ros::NodeHandle(namespace_)"),
            ("  std::string topic_;\n", "  std::string topic_;\n  std::string namespace_;\n")):
        assert old in code
        code = code.replace(old, new)
    source.write_text(code)
    published = [(kind, name) for _, kind, name, _, _ in made(
        configuration(str(root), "depth_description/launch/sim.launch"))]
    assert ("publish", "/sub/pressure/depth") in published
    assert ("publish", "/fleet/depth") in published
    assert not [name for _, name in published if name.startswith("/?")]


ARM_PLUGIN = """\
// a robot's own ros_control plugin: it derives from gazebo_ros_control's, whose Load
// starts the controller manager in <robotNamespace>, and subscribes on its handle
#include <gazebo_ros_control/gazebo_ros_control_plugin.h>
#include <std_msgs/Bool.h>

namespace arm_gazebo
{
class ArmControlPlugin : public gazebo_ros_control::GazeboRosControlPlugin
{
public:
  void Load(gazebo::physics::ModelPtr parent, sdf::ElementPtr sdf)
  {
    GazeboRosControlPlugin::Load(parent, sdf);
    enable_sub_ = model_nh_.subscribe("/arm/enable", 1, &ArmControlPlugin::onEnable, this);
  }
  void onEnable(const std_msgs::Bool::ConstPtr& msg)
  {
    controller_manager_->switchController(std::vector<std::string>(),
                                          std::vector<std::string>(), 1);
  }

private:
  ros::Subscriber enable_sub_;
};
}  // namespace arm_gazebo
GZ_REGISTER_MODEL_PLUGIN(arm_gazebo::ArmControlPlugin)
"""


def test_ros1_plugin_deriving_from_gazebo_ros_control_makes_its_calls_and_the_managers(
        tmp_path) -> None:
    # baxter_gazebo's BaxterGazeboRosControlPlugin: gazebo_ros_control is installed, not
    # in the workspace. Its header was an empty stand-in, model_nh_ undeclared: the
    # plugin's subscriptions were lost (CPP_CALL_MISSED, the gazebo node partial), no
    # controller manager served its services, so the spawned controllers were nodes of
    # their own instead of calls of the gazebo node
    root = tmp_path / "ws"
    shutil.copytree(ROS1, root)
    plugins = root / "arm_gazebo"
    (plugins / "src").mkdir(parents=True)
    (plugins / "src" / "arm_control.cpp").write_text(ARM_PLUGIN)
    (plugins / "package.xml").write_text(package_xml("arm_gazebo"))
    (plugins / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.0.2)\nproject(arm_gazebo)\n"
        "find_package(catkin REQUIRED COMPONENTS gazebo_ros_control roscpp std_msgs)\n"
        "find_package(gazebo REQUIRED)\ncatkin_package()\n"
        "include_directories(${catkin_INCLUDE_DIRS} ${GAZEBO_INCLUDE_DIRS})\n"
        "add_library(arm_gazebo_ros_control src/arm_control.cpp)\n")
    (plugins / "launch").mkdir()
    (plugins / "launch" / "sim.launch").write_text(
        '<launch>\n'
        '  <param name="robot_description" textfile="$(find arm_gazebo)/arm.urdf"/>\n'
        '  <node name="spawn_arm" pkg="gazebo_ros" type="spawn_model"\n'
        '        args="-urdf -param robot_description -model arm"/>\n'
        '  <rosparam ns="/robot/joint_state_controller">\n'
        '    type: joint_state_controller/JointStateController\n'
        '    publish_rate: 50\n'
        '  </rosparam>\n'
        '  <node name="spawner" pkg="controller_manager" type="spawner" ns="/robot"\n'
        '        args="joint_state_controller"/>\n'
        '</launch>\n')
    (plugins / "arm.urdf").write_text(
        '<robot name="arm">\n  <link name="base"/>\n  <gazebo>\n'
        '    <plugin name="arm_control" filename="libarm_gazebo_ros_control.so">\n'
        '      <robotNamespace>/robot</robotNamespace>\n'
        '    </plugin>\n  </gazebo>\n</robot>\n')
    config = configuration(str(root), "arm_gazebo/launch/sim.launch")
    gazebo = {(link.kind, link.resource.name) for link in config.links
              if link.node.name == "/gazebo"}
    assert {("subscribe", "/arm/enable"),  # the plugin's own code, on model_nh_
            # gazebo_ros_control's Load: its manager in <robotNamespace>, and the
            # description it searches for from there
            ("server", "/robot/controller_manager/load_controller"),
            ("server", "/robot/controller_manager/switch_controller"),
            ("read", "/robot_description"),
            # the spawned controller, loaded into that manager
            ("publish", "/robot/joint_states"),
            ("read", "/robot/joint_state_controller/publish_rate")} <= gazebo
    assert config.node("/robot/joint_state_controller") is None
    assert ("read", "/robot/robot_description") not in gazebo
    assert not [d for d in config.diagnostics if d.code in (
        "CPP_CALL_MISSED", "CPP_NODE_PARTIAL", "CPP_INCLUDE_MISSING")
        and "arm_gazebo" in d.location.file]
    assert config.node("/gazebo").completeness == "unknown" or not [
        r for r in config.node("/gazebo").completeness_reasons if "arm_control" in r]
