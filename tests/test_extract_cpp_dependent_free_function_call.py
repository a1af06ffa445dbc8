"""In a class template, a call of a free function template whose template argument
depends on the class's (joint_trajectory_controller's ``ros::NodeHandle tol_nh(
controller_nh_, "constraints"); getSegmentTolerances<Scalar>(tol_nh, joint_names_)``,
``Scalar`` its segment's) is no call clang resolves: the function's reads on its handle
parameter were not tied to the handle passed, and took the controller's own namespace
(``<controller>/stopped_velocity_tolerance``; the tolerances a configuration sets under
``constraints/`` were reported set but never read). The call is now a call of the one
function its name was looked up to that takes that many arguments."""

from __future__ import annotations

import os
from typing import Any

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from tests.conftest import package_xml

CONTROLLER = """
#include <ros/ros.h>
#include <controller_interface/controller.h>
#include <hardware_interface/joint_command_interface.h>
#include <pluginlib/class_list_macros.h>
#include <string>
#include <vector>
namespace arm {
template <class Scalar>
Scalar getTolerances(const ros::NodeHandle& nh, const std::vector<std::string>& names) {
  double stopped;
  nh.param("stopped_velocity_tolerance", stopped, 0.01);
  nh.param("goal_time", stopped, 0.0);
  return stopped;
}
template <class Scalar>
Scalar getTolerances(const ros::NodeHandle& nh) { return Scalar(); }
template <class T> struct Segment { typedef double Scalar; };
template <class HW>
class TrajectoryController : public controller_interface::Controller<HW> {
 public:
  typedef typename Segment<HW>::Scalar Scalar;
  bool init(HW* hw, ros::NodeHandle& root_nh, ros::NodeHandle& controller_nh) {
    controller_nh_ = controller_nh;
    std::vector<std::string> names;
    controller_nh_.getParam("joints", names);
    ros::NodeHandle tol_nh(controller_nh_, "constraints");
    tolerance_ = getTolerances<Scalar>(tol_nh, names);
    return true;
  }
  void update(const ros::Time&, const ros::Duration&) {}
 private:
  ros::NodeHandle controller_nh_;
  Scalar tolerance_;
};
typedef TrajectoryController<hardware_interface::EffortJointInterface> EffortController;
}  // namespace arm
PLUGINLIB_EXPORT_CLASS(arm::EffortController, controller_interface::ControllerBase)
"""

HARDWARE = """
#include <ros/ros.h>
#include <controller_manager/controller_manager.h>
#include <hardware_interface/robot_hw.h>
class Robot : public hardware_interface::RobotHW {};
int main(int argc, char** argv) {
  ros::init(argc, argv, "driver");
  Robot robot;
  ros::NodeHandle nh;
  controller_manager::ControllerManager cm(&robot, nh);
  ros::spin();
  return 0;
}
"""

LAUNCH = """<launch>
  <group ns="arm">
    <node name="driver" pkg="arm" type="driver"/>
    <param name="trajectory/type" value="arm/EffortController"/>
    <param name="trajectory/joints" type="yaml" value="[a, b]"/>
    <param name="trajectory/constraints/stopped_velocity_tolerance" value="0.02"/>
    <param name="trajectory/constraints/goal_time" value="0.5"/>
    <node name="spawner" pkg="controller_manager" type="spawner" args="trajectory"/>
  </group>
</launch>
"""


def _model(write_tree: Any) -> Any:
    xml = package_xml("arm", None).replace("</package>", "".join(
        f"<depend>{d}</depend>" for d in ("roscpp", "controller_manager", "controller_interface",
                                          "hardware_interface", "pluginlib"))
        + '<export><controller_interface plugin="${prefix}/plugins.xml"/></export></package>')
    root = write_tree({
        "src/arm/package.xml": xml,
        "src/arm/CMakeLists.txt": (
            "project(arm)\nfind_package(catkin REQUIRED)\ncatkin_package()\n"
            "add_library(arm_controllers src/controller.cpp)\n"
            "add_executable(driver src/driver.cpp)\n"),
        "src/arm/plugins.xml": (
            '<library path="lib/libarm_controllers">'
            '<class name="arm/EffortController" type="arm::EffortController" '
            'base_class_type="controller_interface::ControllerBase"/></library>'),
        "src/arm/src/controller.cpp": CONTROLLER,
        "src/arm/src/driver.cpp": HARDWARE,
        "src/arm/launch/arm.launch": LAUNCH,
        "project.yaml": ("project: p\nworkspace: [src]\ndistro: noetic\nconfigurations:\n"
                         "  c: {launch: [arm/launch/arm.launch]}\n")})
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def test_the_function_reads_on_the_handle_the_dependent_call_passes(write_tree: Any) -> None:
    from haros_arch.query import run_catalogue

    model = _model(write_tree)
    reads = sorted(link.resource.name for link in model.configurations[0].links
                   if link.kind == "read" and link.node.name == "/arm/driver"
                   and link.resource.name.startswith("/arm/trajectory/"))
    assert reads == ["/arm/trajectory/constraints/goal_time",
                     "/arm/trajectory/constraints/stopped_velocity_tolerance",
                     "/arm/trajectory/joints", "/arm/trajectory/type"]
    assert [f.message for f in run_catalogue(model) if f.rule == "parameter-set-not-read"] == []
