"""A constructor that value-initialises a member (``command(double())``, quori_ros'
``quori_controller::Joint``) next to a string member a topic is named with: clang
exposes ``double()`` as an expression of no children, and reading which argument the
constructor hands a node base class stopped on it with an IndexError, an internal
error for the whole check. The member is the constructor's parameter: the topic is
named after the joint the program constructs."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#pragma once
#include <string>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
namespace arm {
struct Joint {
  Joint();
  explicit Joint(const std::string &name);
  void advertise(ros::NodeHandle &nh);
  std::string name;
  double command;
  double effort;
  ros::Publisher pub;
};
}  // namespace arm
"""
JOINT = """\
#include "arm/joint.hpp"
using namespace arm;
Joint::Joint() : command(double()), effort(double()) {}
Joint::Joint(const std::string &name) : name(name), command(double()), effort(double()) {}
void Joint::advertise(ros::NodeHandle &nh) {
  pub = nh.advertise<std_msgs::Float64>(name + "/command", 1);
}
"""
MAIN = """\
#include "arm/joint.hpp"
int main(int argc, char **argv) {
  ros::init(argc, argv, "arm");
  ros::NodeHandle nh;
  arm::Joint joint("%s");
  joint.advertise(nh);
  ros::spin();
}
"""


def test_a_value_initialised_member_leaves_the_constructor_readable(write_tree) -> None:
    root = write_tree({"arm/package.xml": package_xml("arm", "catkin").replace(
                           "</package>", "<depend>roscpp</depend></package>"),
                       "arm/include/arm/joint.hpp": HEADER,
                       "arm/src/joint.cpp": JOINT,
                       "arm/src/main.cpp": MAIN % "elbow"})
    sources = [str(root / "arm" / "src" / name) for name in ("main.cpp", "joint.cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None,
                         include_dirs=[str(root / "arm" / "include")])
    # the program constructs the joint with its name: the topic is named after it
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("publish", "elbow/command", "std_msgs/Float64")]
