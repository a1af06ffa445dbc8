"""An ambiguous construction of the unit's own class whose constructors make no ROS call
hides none: HEBI's ROS 1 teach-repeat node (arm_teach_repeat_node.cpp:361) builds
``hebi::ros::TeachRepeatNode teach_repeat_node(*arm);`` from the vendor's arm, its headers
missing. The parse takes ``*arm`` for a permissive value that converts to ``Arm&`` and to
the class's own copy and move alike: "call to constructor of ... is ambiguous", in the
``main`` that subscribes, and the node was partial. Whichever constructor runs, it only
stores the arm. A class whose constructor, member initialiser or base makes ROS calls
still counts."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

LOUD = """
class LoudNode {
public:
  LoudNode(vendor::Arm& arm) : arm_(arm) {
    ros::NodeHandle nh;
    pub_ = nh.advertise<std_msgs::Bool>("loud", 1);
  }
private:
  vendor::Arm& arm_;
  ros::Publisher pub_;
};
"""

SOURCE = """
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <vendor_api/arm.hpp>

class TeachNode {
public:
  TeachNode(vendor::Arm& arm) : arm_(arm) {}
  void setCompliant(const std_msgs::Bool::ConstPtr& msg) { compliant_ = msg->data; }
private:
  vendor::Arm& arm_;
  bool compliant_ = false;
};

CLASS
int main(int argc, char** argv) {
  ros::init(argc, argv, "teach_repeat");
  ros::NodeHandle node;
  auto arm = vendor::Arm::create(node.getNamespace());
  TeachNode teach_node(*arm);
  ros::Subscriber sub = node.subscribe("compliant_mode", 50, &TeachNode::setCompliant,
                                       &teach_node);
  LOUD
  ros::spin();
  return 0;
}
"""


def _extract(write_tree, loud: str, cls: str = ""):
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "catkin"),
        "pkg/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0)\nproject(pkg)\n"
                              "find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)\n"
                              "add_executable(teach src/teach.cpp)\n",
        "pkg/src/teach.cpp": SOURCE.replace("LOUD", loud).replace("CLASS", cls)})
    return extract_cpp([str(root / "pkg" / "src" / "teach.cpp")], scan([str(root)]),
                       cache_dir=None)


def test_an_ambiguous_construction_of_a_quiet_class_hides_no_call(write_tree) -> None:
    result = _extract(write_tree, "")
    assert [d.message for d in result.diagnostics if d.code == "CPP_ERROR_NEAR_CALL"] == []
    assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "compliant_mode")]


def test_an_ambiguous_construction_of_a_class_that_advertises_counts(write_tree) -> None:
    result = _extract(write_tree, "LoudNode loud_node(*arm);", LOUD)
    assert [d.message for d in result.diagnostics if d.code == "CPP_ERROR_NEAR_CALL"] == [
        "C++ error in main (lines 26-36), which calls the ROS API: call to constructor of "
        "'LoudNode' is ambiguous"]
