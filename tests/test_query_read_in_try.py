"""A parameter read without a default inside a ``try`` block is prepared for the
parameter not to be set when a handler catches what a missing parameter raises (rclcpp
throws, rospy raises KeyError) and goes on after the block (no ``throw`` / ``raise``,
``return`` or exit in it): no "read but never set". navigation2's collision monitor
reads the deprecated ``<polygon>.max_points`` so, only to warn when a configuration still
sets it (polygon.cpp:455-464); the same read outside a ``try`` is still a finding."""

from __future__ import annotations

import os

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
#include <tf2/exceptions.h>
class Monitor : public rclcpp::Node
{
public:
  Monitor() : rclcpp::Node("monitor")
  {
    try {
      max_points_ = declare_parameter<int>("max_points") + 1;
      RCLCPP_WARN(get_logger(), "max_points is deprecated");
    } catch (const std::exception &) {
    }
    try {
      frame_ = declare_parameter<std::string>("frame");  // its failure is not caught
    } catch (const tf2::TransformException &) {
    }
    try {
      topic_ = declare_parameter<std::string>("topic");
    } catch (const std::exception & ex) {  // caught, and thrown on: the node fails
      throw std::runtime_error(std::string("no topic: ") + ex.what());
    }
    min_points_ = declare_parameter<int>("min_points");
  }
  int max_points_ = 0, min_points_ = 0;
  std::string frame_, topic_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Monitor>());
}
"""

SCRIPT = """#!/usr/bin/env python3
import rospy
rospy.init_node('watcher')
try:
    old = rospy.get_param('~old_rate')
    rospy.logwarn('old_rate is deprecated')
except KeyError:
    pass
rate = rospy.get_param('~rate')


def main():
    needed = rospy.get_param('~needed')
    try:
        port = rospy.get_param('~port')
    except KeyError:
        rospy.logfatal('no port')
        return


try:
    main()
except rospy.ROSInterruptException:  # not what a missing parameter raises
    pass
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='ex', executable='monitor', name='monitor')])
"""


def test_a_read_in_a_try_block_is_no_read_not_set(write_tree) -> None:
    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n"
                                 "add_executable(monitor src/node.cpp)\n",
        "src/ex/src/node.cpp": NODE,
        "src/ex/launch/ex.launch.py": LAUNCH,
        "src/old/package.xml": package_xml("old"),
        "src/old/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0)\nproject(old)\n"
                                  "find_package(catkin REQUIRED)\ncatkin_package()\n"
                                  "catkin_install_python(PROGRAMS scripts/watcher.py\n"
                                  "  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n",
        "src/old/scripts/watcher.py": SCRIPT,
        "src/old/launch/old.launch": '<launch><node pkg="old" type="watcher.py" '
                                     'name="watcher"/></launch>\n',
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"
                        "  d: [old/launch/old.launch]\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    unset = sorted(f.message.split(" ")[0] for f in run_catalogue(model)
                   if f.rule == "parameter-read-not-set")
    assert unset == ["/monitor/frame", "/monitor/min_points", "/monitor/topic",
                     "/watcher/needed", "/watcher/port", "/watcher/rate"]
