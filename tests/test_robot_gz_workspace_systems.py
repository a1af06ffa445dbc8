"""A gz sim system a workspace package builds: leo_simulator-ros2's leo_gz_plugins
builds ``leo_gz_differential_plugin`` (``IGNITION_ADD_PLUGIN``, gz transport only), which
leo_description's macros.xacro:495 loads into gz sim; it was GAZEBO_PLUGIN_UNKNOWN, the
description partial. A system of the workspace that uses rclcpp stays partial, said why."""

from __future__ import annotations

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project
from tests.conftest import package_xml

SDF = """<?xml version="1.0"?>
<sdf version="1.9"><model name="bot">
  <plugin name="bot::Drive" filename="libbot_drive_system.so"/>
  <plugin name="bot::Bridge" filename="bot_ros_system"/>
  <plugin name="other" filename="libnot_built_here.so"/>
</model></sdf>
"""

LAUNCH = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    share = get_package_share_directory("bot_description")
    return LaunchDescription([
        Node(package="ros_gz_sim", executable="create",
             arguments=["-name", "bot", "-file", os.path.join(share, "models", "bot.sdf")]),
    ])
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(bot_gz_plugins)
find_package(ament_cmake REQUIRED)
add_library(bot_drive_system SHARED src/drive.cpp)
add_library(bot_ros_system SHARED src/ros.cpp)
ament_package()
"""

DRIVE = """#include <ignition/gazebo/System.hh>
#include <ignition/plugin/Register.hh>
namespace bot { class Drive : public ignition::gazebo::System {}; }
IGNITION_ADD_PLUGIN(bot::Drive, ignition::gazebo::System)
"""

ROS = """#include <gz/sim/System.hh>
#include <gz/plugin/Register.hh>
#include <rclcpp/rclcpp.hpp>
namespace bot { class Bridge : public gz::sim::System { rclcpp::Node::SharedPtr node_; }; }
GZ_ADD_PLUGIN(bot::Bridge, gz::sim::System)
"""


def test_a_gz_system_the_workspace_builds(write_tree) -> None:
    root = write_tree({
        "bot_description/package.xml": package_xml("bot_description", "ament_cmake"),
        "bot_description/CMakeLists.txt": "project(bot_description)\nament_package()\n",
        "bot_description/models/bot.sdf": SDF,
        "bot_description/launch/gz.launch.py": LAUNCH,
        "bot_gz_plugins/package.xml": package_xml("bot_gz_plugins", "ament_cmake"),
        "bot_gz_plugins/CMakeLists.txt": CMAKE,
        "bot_gz_plugins/src/drive.cpp": DRIVE,
        "bot_gz_plugins/src/ros.cpp": ROS,
    })
    project = Project("bot", str(root / "project.yaml"), workspace=[str(root)],
                      configurations=[ConfigurationSpec(
                          "c", ["bot_description/launch/gz.launch.py"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    unknown = [d.message for d in config.diagnostics if d.code == "GAZEBO_PLUGIN_UNKNOWN"]
    assert unknown == ["Gazebo plugin libnot_built_here.so loaded by gz sim is not known"]
    (description,) = config.robot_descriptions
    assert description.completeness == "partial"
    reasons = " ".join(description.completeness_reasons)
    assert "bot_ros_system" in reasons and "bot_gz_plugins" in reasons
    assert "bot_drive_system" not in reasons
