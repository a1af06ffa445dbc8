"""A ROS 1 controller calls free functions of another workspace package's library that
it links, handing them its handles: abb_robot_driver's EGMStateController reads
``publish_rate`` through abb_robot_cpp_utilities' ``utilities::getParameter(
controller_nh, "publish_rate", ...)``, and hector_quadrotor's controllers read
``robot_description`` through hector_quadrotor_interface's ``getMassAndInertia(root_nh,
...)``. The plugin's sources left those files out (only the classes it builds were
added), so ``publish_rate`` was "set but never read"; read through the root handle, the
name is in the manager's namespace, as a call the controller makes on ``root_nh``
itself."""

from __future__ import annotations

import os
import textwrap
from typing import Any

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from tests.conftest import package_xml

UTIL_HEADER = """
    #pragma once
    #include <ros/ros.h>
    #include <string>
    namespace util {
    template <typename T>
    void getParameter(ros::NodeHandle& nh, const std::string& key, T& value, const T& def);
    bool getMass(const ros::NodeHandle& nh, double& mass);
    }
    """

UTIL_SOURCE = """
    #include <util/helpers.h>
    namespace util {
    template <typename T>
    void getParameter(ros::NodeHandle& nh, const std::string& key, T& value, const T& def)
    {
      if (!nh.param<T>(key, value, def)) ROS_DEBUG("default for %s", key.c_str());
    }
    bool getMass(const ros::NodeHandle& nh, double& mass)
    {
      std::string description;
      if (!nh.getParam("robot_description", description)) return false;
      mass = 1.0;
      return true;
    }
    template void getParameter<double>(ros::NodeHandle&, const std::string&, double&,
                                       const double&);
    }
    """

CONTROLLER = """
    #include <ros/ros.h>
    #include <controller_interface/controller.h>
    #include <hardware_interface/joint_command_interface.h>
    #include <pluginlib/class_list_macros.h>
    #include <util/helpers.h>

    namespace quad {
    class StateController
        : public controller_interface::Controller<hardware_interface::EffortJointInterface> {
     public:
      virtual bool init(hardware_interface::EffortJointInterface* hw, ros::NodeHandle& root_nh,
                        ros::NodeHandle& controller_nh) {
        util::getParameter(controller_nh, "publish_rate", rate_, 50.0);
        util::getMass(root_nh, mass_);
        return true;
      }
      void update(const ros::Time&, const ros::Duration&) {}
     private:
      double rate_;
      double mass_;
    };
    }  // namespace quad
    PLUGINLIB_EXPORT_CLASS(quad::StateController, controller_interface::ControllerBase)
    """

HARDWARE = """
    #include <ros/ros.h>
    #include <controller_manager/controller_manager.h>
    #include <hardware_interface/robot_hw.h>

    class Robot : public hardware_interface::RobotHW {
     public:
      void read() {}
      void write() {}
    };

    int main(int argc, char** argv) {
      ros::init(argc, argv, "base_node");
      Robot robot;
      controller_manager::ControllerManager cm(&robot, ros::NodeHandle("uav1"));
      ros::spin();
      return 0;
    }
    """

LAUNCH = """<launch>
  <node name="base" pkg="quad" type="base_node"/>
  <group ns="uav1">
    <param name="robot_description" value="&lt;robot name='uav1'/&gt;"/>
    <param name="state/type" value="quad/StateController"/>
    <param name="state/publish_rate" value="100.0"/>
    <node name="spawner" pkg="controller_manager" type="spawner" args="state"/>
  </group>
</launch>
"""


def _model(write_tree: Any) -> Any:
    depends = ("roscpp", "controller_manager", "controller_interface", "hardware_interface",
               "pluginlib", "util")
    xml = package_xml("quad", None).replace("</package>", "".join(
        f"<depend>{d}</depend>" for d in depends)
        + '<export><controller_interface plugin="${prefix}/plugins.xml"/></export></package>')
    root = write_tree({
        "src/util/package.xml": package_xml("util", None).replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "src/util/CMakeLists.txt": (
            "project(util)\nfind_package(catkin REQUIRED COMPONENTS roscpp)\n"
            "catkin_package(INCLUDE_DIRS include LIBRARIES util)\n"
            "add_library(util src/helpers.cpp)\n"),
        "src/util/include/util/helpers.h": textwrap.dedent(UTIL_HEADER),
        "src/util/src/helpers.cpp": textwrap.dedent(UTIL_SOURCE),
        "src/quad/package.xml": xml,
        "src/quad/CMakeLists.txt": (
            "project(quad)\nfind_package(catkin REQUIRED COMPONENTS roscpp util)\n"
            "catkin_package()\n"
            "add_library(quad_controllers src/controller.cpp)\n"
            "target_link_libraries(quad_controllers ${catkin_LIBRARIES})\n"
            "add_executable(base_node src/base.cpp)\n"),
        "src/quad/plugins.xml": (
            '<library path="lib/libquad_controllers">'
            '<class name="quad/StateController" type="quad::StateController" '
            'base_class_type="controller_interface::ControllerBase"/></library>'),
        "src/quad/src/controller.cpp": textwrap.dedent(CONTROLLER),
        "src/quad/src/base.cpp": textwrap.dedent(HARDWARE),
        "src/quad/launch/sim.launch": LAUNCH,
        "project.yaml": ("project: p\nworkspace: [src]\ndistro: noetic\nconfigurations:\n"
                         "  c: {launch: [quad/launch/sim.launch]}\n")})
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def test_a_controller_reads_through_free_functions_of_a_library_it_links(
        write_tree: Any) -> None:
    from haros_arch.query import run_catalogue

    model = _model(write_tree)
    (plugin,) = [n for n in model.nodes if n.name == "quad/quad/StateController"]
    assert "util/src/helpers.cpp" in plugin.sources
    (config,) = model.configurations
    reads = sorted((link.node.name, link.resource.name) for link in config.links
                   if link.kind == "read" and link.location.file == "util/src/helpers.cpp")
    # the controller's handle is /uav1/state, its root handle the manager's, /uav1
    assert ("/base", "/uav1/state/publish_rate") in reads
    assert ("/base", "/uav1/robot_description") in reads
    assert not [r for r in reads if r[1] == "/robot_description"]
    unread = [f.message for f in run_catalogue(model) if f.rule == "parameter-set-not-read"]
    assert unread == []
