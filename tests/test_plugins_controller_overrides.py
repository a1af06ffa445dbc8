"""A ros2_control controller is a node of the manager's process made with
``automatically_declare_parameters_from_overrides(true)``: the ``/**`` entries of the
process's parameter files are its parameters too, so the ``robot_description`` a launch
file gives ros2_control_node as a dictionary (launch_ros writes it under ``/**``)
reaches a controller that requires it (franka_ros2's state broadcaster aborts its
configuration without it)."""

from __future__ import annotations

import os

from conftest import FIXTURES

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

PLUGINS = FIXTURES / "build" / "plugins"

CONTROLLER = r"""
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <pluginlib/class_list_macros.hpp>

namespace ros2_ctrl
{
class Follower
{
public:
  bool on_init(rclcpp::Node::SharedPtr node)
  {
    std::string description, mode;
    if (!node->get_parameter("robot_description", description)) {
      RCLCPP_ERROR(node->get_logger(), "Failed to get robot_description parameter");
      return false;
    }
    if (!node->get_parameter("mode", mode)) {
      RCLCPP_ERROR(node->get_logger(), "Failed to get mode parameter");
      return false;
    }
    return true;
  }
};
}  // namespace ros2_ctrl

PLUGINLIB_EXPORT_CLASS(ros2_ctrl::Follower, controller_interface::ControllerInterface)
"""

LAUNCH = """
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config = os.path.join(get_package_share_directory('ros2_bringup'), 'config',
                          'controllers.yaml')
    return LaunchDescription([
        Node(package='controller_manager', executable='ros2_control_node',
             namespace='robot', parameters=[{'robot_description': '<robot/>'}]),
        Node(package='controller_manager', executable='spawner', namespace='robot',
             arguments=['follower', '--param-file', config]),
    ])
"""


def test_a_controller_gets_the_managers_dictionary_parameters(write_tree):
    files = {f"src/ros2_ctrl/{name}": (PLUGINS / "ros2_ctrl" / name).read_text()
             for name in ("CMakeLists.txt", "package.xml", "ros2_ctrl.xml")}
    files.update({f"src/ros2_bringup/{name}": (PLUGINS / "ros2_bringup" / name).read_text()
                  for name in ("CMakeLists.txt", "package.xml", "params/controllers.yaml")})
    files["src/ros2_ctrl/src/follower.cpp"] = CONTROLLER
    files["src/ros2_bringup/launch/c.launch.py"] = LAUNCH
    files["project.yaml"] = ("project: p\ndistro: jazzy\nconfigurations:\n"
                             "  c: [ros2_bringup/launch/c.launch.py]\n")
    root = write_tree(files)
    model = analyse(load(os.path.join(root, "project.yaml")), {},
                    Options(cache_dir=None, jobs=1))
    config = model.configuration("c")
    description = config.parameter("/robot/follower/robot_description")
    assert description is not None and description.set_by_launch
    # the required parameter nothing sets is reported, the one the manager's process
    # gives is not
    unset = sorted(f.message.split(" is read")[0] for f in run_catalogue(model)
                   if f.rule == "parameter-read-not-set")
    assert unset == ["/robot/follower/mode"]
