"""A package's own header in a ``ros/`` folder of one of its include folders
(quadruped-robot's ``#include "ros/qr_cmd_vel_receiver.h"`` from ``include/quadruped``):
roscpp's installed ``ros/`` has no such file, so a compiler finds the package's. The
parse took every ``ros/`` header for roscpp's umbrella stand-in, the class stayed
undeclared and its constructor's subscription was lost (survey R: the keyboard teleop
and the robots' command-velocity receivers partial). A ``ros/`` header the stand-ins
have is still theirs."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

CMAKE = """\
cmake_minimum_required(VERSION 3.0.2)
project(legged)
find_package(catkin REQUIRED COMPONENTS roscpp geometry_msgs)
include_directories(include/legged ${catkin_INCLUDE_DIRS})
add_executable(receiver src/receiver.cpp)
"""
HEADER = """\
#pragma once
#include <ros/ros.h>
#include <geometry_msgs/Twist.h>
namespace legged {
class CmdVelReceiver {
 public:
  explicit CmdVelReceiver(ros::NodeHandle& nh);
  void callback(const geometry_msgs::Twist::ConstPtr& msg);
 private:
  ros::Subscriber sub_;
};
}
"""
SOURCE = """\
#include "ros/cmd_vel_receiver.h"
#include <ros/node_handle.h>
namespace legged {
CmdVelReceiver::CmdVelReceiver(ros::NodeHandle& nh) {
  sub_ = nh.subscribe("cmd_vel", 10, &CmdVelReceiver::callback, this);
}
void CmdVelReceiver::callback(const geometry_msgs::Twist::ConstPtr& msg) {}
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "receiver");
  ros::NodeHandle nh;
  legged::CmdVelReceiver receiver(nh);
  ros::spin();
}
"""


def test_a_package_header_in_a_ros_folder_is_read(tmp_path) -> None:
    root = tmp_path / "legged"
    files = {"package.xml": package_xml("legged", "catkin"), "CMakeLists.txt": CMAKE,
             "include/legged/ros/cmd_vel_receiver.h": HEADER,
             "src/receiver.cpp": SOURCE}
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    result = extract_cpp([str(root / "src" / "receiver.cpp")], scan([str(tmp_path)]),
                         cache_dir=None, distro="noetic")
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("subscribe", "cmd_vel", "geometry_msgs/Twist")]
    assert not {"CPP_PARSE_ERROR", "CPP_CALL_MISSED", "CPP_NODE_PARTIAL"} & {
        d.code for d in result.diagnostics}
