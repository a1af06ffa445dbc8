"""The handles a host gives a loaded plugin's entry method: jsk_aerial_robot's
aerial_robot_base creates its controller by pluginlib and calls ``controller_->
initialize(nh_, nhp_, ...)`` through ``aerial_robot_control::ControlBase``; the plugin's
``initialize(ros::NodeHandle nh, ros::NodeHandle nhp, ...)`` makes its calls on them
(through the base's inline ``initialize``, which keeps them in members). Nothing in the
plugin's own files passes those handles, so its names kept an unknown namespace
(``?/lqi_gain``, and a ``?/motor_info`` beside the host's own ``motor_info``). The
extraction marks such a call (``PrimitiveCall.host_handle``: the base methods the
entry method overrides, and the parameter), the host's extraction says what its code
passes to virtual methods it calls through their class (``Node.handles_given``), and
the graph puts the plugin's call in the namespace of the host's handle; a handle the
host gives that is not known keeps the ``?``. A member the base's virtual ``initialize``
sets from its handle (``nh_ = nh``) holds that handle's placeholder, not an unknown, so
the calls other methods make on it follow too, and the host's own copy of the base's
inline code no longer adds a ``?/motor_info`` beside ``motor_info``."""

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
#include <std_msgs/Float64.h>
namespace control {
class ControlBase {
 public:
  virtual ~ControlBase() {}
  virtual void initialize(ros::NodeHandle nh, ros::NodeHandle nhp, double rate) {
    nh_ = nh;
    nhp_ = nhp;
    info_pub_ = nh_.advertise<std_msgs::Float64>("motor_info", 1);
    ros::NodeHandle motor_nh(nh_, "motor");
    motor_nh.param("max_pwm", max_pwm_, 0.0);
  }
 protected:
  ros::NodeHandle nh_, nhp_;
  ros::Publisher info_pub_;
  double max_pwm_;
};
class Linear : public ControlBase {
 public:
  void initialize(ros::NodeHandle nh, ros::NodeHandle nhp, double rate) override {
    ControlBase::initialize(nh, nhp, rate);
    nhp_.param("verbose", verbose_, false);
  }
 protected:
  bool verbose_;
};
}
"""

HOST_H = """\
#pragma once
#include <ros/ros.h>
#include <pluginlib/class_loader.h>
#include <boost/shared_ptr.hpp>
#include <control/base.h>
class Host {
 public:
  Host(ros::NodeHandle nh, ros::NodeHandle nhp);
 private:
  ros::NodeHandle nh_, nhp_;
  pluginlib::ClassLoader<control::ControlBase> loader_;
  boost::shared_ptr<control::ControlBase> controller_;
};
"""

HOST_CPP = """\
#include <host/host.h>
Host::Host(ros::NodeHandle nh, ros::NodeHandle nhp)
  : nh_(nh), nhp_(nhp), loader_("control", "control::ControlBase") {
  std::string name;
  nh_.param("control_name", name, std::string("control/none"));
  controller_ = loader_.createInstance(name);
  controller_->initialize(nh_, ros::NodeHandle(nhp_, "ctrl"), 0.01);
}
"""

MAIN_CPP = """\
#include <host/host.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "host");
  ros::NodeHandle nh;
  ros::NodeHandle nhp("~");
  Host host(nh, nhp);
  ros::spin();
}
"""

ROBOT_CPP = """\
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <pluginlib/class_list_macros.h>
#include <control/base.h>
namespace robot {
class Lqi : public control::Linear {
 public:
  void initialize(ros::NodeHandle nh, ros::NodeHandle nhp, double rate) override {
    control::Linear::initialize(nh, nhp, rate);
    pub_ = nh_.advertise<std_msgs::Float64>("lqi_gain", 1);
    ros::NodeHandle gains(nhp, "gains");
    gains.param("p", p_, 1.0);
  }
 private:
  ros::Publisher pub_;
  double p_;
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


def _tree(write_tree, host_cpp: str):
    return write_tree({
        "src/control/package.xml": _package("control", ("roscpp",)),
        "src/control/CMakeLists.txt": "project(control)\nfind_package(catkin REQUIRED)\n"
                                      "catkin_package(INCLUDE_DIRS include)\n",
        "src/control/include/control/base.h": BASE_H,
        "src/host/package.xml": _package("host", ("roscpp", "pluginlib", "control")),
        "src/host/CMakeLists.txt": "project(host)\nfind_package(catkin REQUIRED)\n"
                                   "catkin_package()\n"
                                   "add_executable(host_node src/host_node.cpp src/host.cpp)\n",
        "src/host/include/host/host.h": HOST_H,
        "src/host/src/host.cpp": host_cpp,
        "src/host/src/host_node.cpp": MAIN_CPP,
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


def _names(root) -> list[tuple[str, str]]:
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (config,) = model.configurations
    (host,) = config.nodes
    return sorted({(link.call.kind, link.resource.name) for link in host.links
                   if link.call is not None and link.call.kind in ("publish", "read")
                   and link.resource.name != "/robot/control_name"})


def test_the_plugins_calls_are_made_on_the_handles_the_host_gives(write_tree) -> None:
    root = _tree(write_tree, HOST_CPP)
    assert _names(root) == [
        ("publish", "/robot/lqi_gain"),
        ("publish", "/robot/motor_info"),
        ("read", "/robot/host/ctrl/gains/p"),
        ("read", "/robot/host/ctrl/verbose"),
        ("read", "/robot/motor/max_pwm"),
    ]


def test_a_handle_the_host_gives_that_is_not_known_keeps_its_namespace_unknown(
        write_tree) -> None:
    # the host hands on a handle of another object, which no file of the node makes
    unknown = HOST_CPP.replace("controller_->initialize(nh_,",
                               "controller_->initialize(other_->handle(),").replace(
        "#include <host/host.h>",
        "#include <host/host.h>\nstruct Other { ros::NodeHandle handle(); };\n"
        "extern Other* other_;")
    names = _names(_tree(write_tree, unknown))
    # the public handle is not known: its names stay unknown; the private one is
    assert ("publish", "/?/lqi_gain") in names
    assert ("publish", "/robot/lqi_gain") not in names
    assert ("read", "/robot/host/ctrl/gains/p") in names
