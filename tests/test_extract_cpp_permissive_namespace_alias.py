"""A namespace alias of a vendor namespace whose headers are missing: HEBI's ROS 1 kit
(arm_teach_repeat_node.hpp:16 and .cpp:11) writes ``namespace arm =
hebi::experimental::arm;`` and then ``arm::Arm``, ``arm::Goal`` bare. The permissive parse
learned the namespaces of ``using namespace X::Y;`` only: the alias stayed "expected
namespace name", ``arm::Arm`` was declared under a top-level ``arm`` that clashes with the
alias, and the errors were in ``main``, which advertises: the node partial. The alias's target is
now declared, each part a namespace, so the alias is valid and the names written through it
are the target's."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <vendor_api/arm/arm.hpp>

namespace arm = vendor::experimental::arm;

namespace vendor {
namespace ros {

class TeachNode {
public:
  TeachNode(arm::Arm& arm) : arm_(arm) {}
  void replay() { arm_.setGoal(arm::Goal::createFromPosition(last_)); }
private:
  vendor::experimental::arm::Arm& arm_;
  double last_ = 0;
};

}  // namespace ros
}  // namespace vendor
"""

SOURCE = """
#include "teach_node.hpp"

namespace arm = vendor::experimental::arm;

int main(int argc, char** argv) {
  ros::init(argc, argv, "teach_repeat");
  ros::NodeHandle node;
  arm::Arm::Params params;
  params.hrdf_file_ = "arm.hrdf";
  auto arm = arm::Arm::create(params);
  if (!arm) {
    return 1;
  }
  arm::Arm& arm_ref = *arm;
  vendor::ros::TeachNode teach_node(arm_ref);
  ros::Publisher pub = node.advertise<std_msgs::Bool>("recording", 10);
  ros::spin();
  return 0;
}
"""


def test_a_namespace_alias_of_a_vendor_namespace(write_tree) -> None:
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "catkin"),
        "pkg/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0)\nproject(pkg)\n"
                              "find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)\n"
                              "include_directories(include ${catkin_INCLUDE_DIRS})\n"
                              "add_executable(teach src/teach.cpp)\n",
        "pkg/include/teach_node.hpp": HEADER,
        "pkg/src/teach.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "teach.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "recording")]
