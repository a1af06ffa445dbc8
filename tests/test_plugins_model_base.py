"""A workspace plugin class that derives from an exported class of a package with no
source here runs that base's code in its node: Universal_Robots_ROS2_Driver's
``ScaledJointTrajectoryController : public joint_trajectory_controller::
JointTrajectoryController`` calls the base's ``on_init``, ``on_configure`` and
``on_activate``, which make the controller's action server and topics. Only the
derived class's own calls were its node's: ``/scaled_joint_trajectory_controller`` had no
``follow_joint_trajectory`` server, and trajectory_until_node's client no server. The
base's interface model now gives them, as ``EXTENDS`` does for a base of the table."""

from __future__ import annotations

import os

from conftest import FIXTURES

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

PLUGINS = FIXTURES / "build" / "plugins"

HEADER = r"""
#pragma once
#include <joint_trajectory_controller/joint_trajectory_controller.hpp>

namespace ros2_ctrl
{
class Scaled : public joint_trajectory_controller::JointTrajectoryController
{
public:
  controller_interface::CallbackReturn on_init() override;
};
class Plain : public controller_interface::ControllerInterface
{
public:
  controller_interface::CallbackReturn on_init() override;
};
}  // namespace ros2_ctrl
"""

SOURCE = r"""
#include "ros2_ctrl/scaled.hpp"
#include <pluginlib/class_list_macros.hpp>

namespace ros2_ctrl
{
controller_interface::CallbackReturn Scaled::on_init()
{
  get_node()->declare_parameter<std::string>("speed_scaling_interface_name", "factor");
  return JointTrajectoryController::on_init();
}
controller_interface::CallbackReturn Plain::on_init()
{
  get_node()->declare_parameter<std::string>("mode", "plain");
  return controller_interface::CallbackReturn::SUCCESS;
}
}  // namespace ros2_ctrl

PLUGINLIB_EXPORT_CLASS(ros2_ctrl::Scaled, controller_interface::ControllerInterface)
PLUGINLIB_EXPORT_CLASS(ros2_ctrl::Plain, controller_interface::ControllerInterface)
"""

PLUGINS_XML = """<library path="ros2_ctrl">
  <class name="ros2_ctrl/Scaled" type="ros2_ctrl::Scaled"
         base_class_type="controller_interface::ControllerInterface"/>
  <class name="ros2_ctrl/Plain" type="ros2_ctrl::Plain"
         base_class_type="controller_interface::ControllerInterface"/>
</library>
"""

SPAWNED = """/scaled:
  ros__parameters:
    type: ros2_ctrl/Scaled
    joints: [a, b]
/plain:
  ros__parameters:
    type: ros2_ctrl/Plain
"""

LAUNCH = """
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config = os.path.join(get_package_share_directory('ros2_bringup'), 'config',
                          'spawned.yaml')
    return LaunchDescription([
        Node(package='controller_manager', executable='ros2_control_node',
             parameters=[{'robot_description': '<robot/>'}]),
        Node(package='controller_manager', executable='spawner',
             arguments=['scaled', 'plain', '--param-file', config]),
    ])
"""


def test_a_controller_runs_the_code_of_its_modelled_base_class(write_tree):
    files = {f"src/ros2_ctrl/{name}": (PLUGINS / "ros2_ctrl" / name).read_text()
             for name in ("CMakeLists.txt", "package.xml")}
    files["src/ros2_ctrl/ros2_ctrl.xml"] = PLUGINS_XML
    files["src/ros2_ctrl/include/ros2_ctrl/scaled.hpp"] = HEADER
    files["src/ros2_ctrl/src/follower.cpp"] = SOURCE
    files.update({f"src/ros2_bringup/{name}": (PLUGINS / "ros2_bringup" / name).read_text()
                  for name in ("CMakeLists.txt", "package.xml")})
    files["src/ros2_bringup/params/spawned.yaml"] = SPAWNED
    files["src/ros2_bringup/launch/c.launch.py"] = LAUNCH
    files["project.yaml"] = ("project: p\ndistro: jazzy\nconfigurations:\n"
                             "  c: [ros2_bringup/launch/c.launch.py]\n")
    root = write_tree(files)
    model = analyse(load(os.path.join(root, "project.yaml")), {},
                    Options(cache_dir=None, jobs=1))
    config = model.configuration("c")

    def links(node: str) -> set[tuple[str, str]]:
        return {(link.kind, link.resource.name) for link in config.links
                if link.node.name == node and link.kind not in ("read", "declare")}

    scaled = links("/scaled")
    assert ("action-server", "/scaled/follow_joint_trajectory") in scaled
    assert ("subscribe", "/scaled/joint_trajectory") in scaled
    # its own declaration stays, and the base's reads of the file's parameters
    reads = {link.resource.name for link in config.links
             if link.node.name == "/scaled" and link.kind in ("read", "declare")}
    assert {"/scaled/speed_scaling_interface_name", "/scaled/joints"} <= reads
    # a class that derives from no modelled plugin class gets nothing more
    assert links("/plain") == set()
