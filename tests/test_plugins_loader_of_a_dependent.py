"""A class exported under a tag that a ClassLoader of another package reads, the two
packages not depending on each other: jsk_aerial_robot's dragon exports its controller
and navigator under ``aerial_robot_control`` (the base's package), and aerial_robot_base,
which depends on aerial_robot_control but not on dragon, creates them by the value of a
parameter the bringup sets (``aerial_robot_control_name``). Only ClassLoaders of the
exporting package and of its dependencies were looked for, so the class was no plugin
node: ``PLUGIN_NOT_FOUND`` ("not exported by an analysed package") and the host node
partial. pluginlib's ClassLoader(tag, base) reads what every package exports under its
tag, and its code includes the base's header: its package is the tag's or depends on it.
"""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load


def _package(name: str, depends: tuple[str, ...], export: str = "") -> str:
    return package_xml(name).replace(
        "</license>", "</license><buildtool_depend>catkin</buildtool_depend>" + "".join(
            f"<depend>{d}</depend>" for d in depends)).replace(
        "</package>", f"<export>{export}</export></package>" if export else "</package>")


BASE_H = """\
#pragma once
#include <ros/ros.h>
namespace control {
class ControlBase {
 public:
  virtual ~ControlBase() {}
  virtual void initialize(ros::NodeHandle nh) = 0;
};
}
"""

HOST_CPP = """\
#include <ros/ros.h>
#include <pluginlib/class_loader.h>
#include <boost/shared_ptr.hpp>
#include <control/base.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "host");
  ros::NodeHandle nh;
  pluginlib::ClassLoader<control::ControlBase> loader("control", "control::ControlBase");
  std::string name;
  nh.param("control_name", name, std::string("control/none"));
  boost::shared_ptr<control::ControlBase> controller = loader.createInstance(name);
  controller->initialize(nh);
  ros::spin();
}
"""

ROBOT_CPP = """\
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <pluginlib/class_list_macros.h>
#include <control/base.h>
namespace robot {
class Lqi : public control::ControlBase {
 public:
  void initialize(ros::NodeHandle nh) override {
    pub_ = nh.advertise<std_msgs::Float64>("lqi_gain", 1);
  }
 private:
  ros::Publisher pub_;
};
}
PLUGINLIB_EXPORT_CLASS(robot::Lqi, control::ControlBase)
"""

PLUGINS_XML = """\
<library path="lib/librobot_control">
  <class name="robot/lqi" type="robot::Lqi" base_class_type="control::ControlBase">
    <description>d</description>
  </class>
</library>
"""

LAUNCH = """\
<launch>
  <group ns="robot">
    <param name="control_name" value="robot/lqi" />
    <node pkg="host" type="host_node" name="host" />
  </group>
</launch>
"""


def test_a_class_exported_under_the_loaders_tag_is_loaded(write_tree) -> None:
    root = write_tree({
        "src/control/package.xml": _package("control", ("roscpp",)),
        "src/control/CMakeLists.txt": "project(control)\nfind_package(catkin REQUIRED)\n"
                                      "catkin_package(INCLUDE_DIRS include)\n",
        "src/control/include/control/base.h": BASE_H,
        "src/host/package.xml": _package("host", ("roscpp", "pluginlib", "control")),
        "src/host/CMakeLists.txt": "project(host)\nfind_package(catkin REQUIRED)\n"
                                   "catkin_package()\n"
                                   "add_executable(host_node src/host_node.cpp)\n",
        "src/host/src/host_node.cpp": HOST_CPP,
        "src/host/launch/run.launch": LAUNCH,
        "src/robot/package.xml": _package("robot", ("roscpp", "pluginlib", "control"),
                                          '<control plugin="${prefix}/plugins.xml"/>'),
        "src/robot/CMakeLists.txt": "project(robot)\nfind_package(catkin REQUIRED)\n"
                                    "catkin_package()\n"
                                    "add_library(robot_control src/lqi.cpp)\n",
        "src/robot/src/lqi.cpp": ROBOT_CPP,
        "src/robot/plugins.xml": PLUGINS_XML,
        "project.yaml": "project: p\nconfigurations:\n  c: [host/launch/run.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (config,) = model.configurations
    (host,) = config.nodes
    # the class's calls are the host's (the handle it is given is not followed into
    # the plugin: its namespace stays unknown)
    assert [link.resource.name.rsplit("/", 1)[-1] for link in host.links
            if link.call is not None and link.call.kind == "publish"] == ["lqi_gain"]
    assert not [d for d in model.diagnostics + config.diagnostics
                if d.code == "PLUGIN_NOT_FOUND"]
