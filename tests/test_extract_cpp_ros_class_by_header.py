"""Whether a class the parse knows only by name may be a ROS package's (``ros_classes``)
follows the rule by which a ROS 1 class of a missing header is credited to a dependency
(``header_packages``, fixV's): MoveIt's ``planning_interface::PlannerManager`` of
``<moveit/planning_interface/planning_interface.h>``, moveit_core's, headers missing.
A method of a class derived from it that makes an unqualified call with the node handle
may be calling the base's own method (a ROS package's code, not read): the node gives
its handle to unknown code (``CPP_NODE_TO_UNKNOWN``, partial). The namespace
``planning_interface`` names no package, so the base was taken for a plain library's
and the node was complete. A base of a missing header whose folder names no package
the unit may include stays a library's."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <{header}>
namespace my {{
class Planner : public {base} {{
public:
  bool initialize() {{
    ros::NodeHandle nh("~");
    configure(options_);
    pub_ = nh.advertise<std_msgs::String>("out", 1);
    return true;
  }}
  ros::Publisher pub_;
  {space}::Options options_;
}};
}}
int main(int argc, char** argv) {{
  ros::init(argc, argv, "planner");
  my::Planner planner;
  planner.initialize();
  ros::spin();
}}
"""


def _extract(write_tree, header: str, base: str):
    root = write_tree({
        "src/planner/package.xml": package_xml("planner", "catkin").replace(
            "<export>", "<depend>roscpp</depend><depend>std_msgs</depend>"
            "<depend>moveit_core</depend><export>"),
        "src/planner/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\n"
                                      "project(planner)\n"
                                      "add_executable(planner src/planner.cpp)\n",
        "src/planner/src/planner.cpp": SOURCE.format(header=header, base=base,
                                                     space=base.split("::")[0]),
    })
    ws = scan([str(root / "src")])
    return extract_cpp([str(root / "src/planner/src/planner.cpp")], ws, cache_dir=None,
                       jobs=1)


def test_a_base_of_a_missing_moveit_header_may_be_a_ros_package_s(write_tree) -> None:
    result = _extract(write_tree, "moveit/planning_interface/planning_interface.h",
                      "planning_interface::PlannerManager")
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "~out")]
    said = [d.message for d in result.diagnostics if d.code == "CPP_NODE_TO_UNKNOWN"]
    assert len(said) == 1 and "configure" in said[0]


def test_a_base_of_a_missing_header_of_no_package_stays_a_library_s(write_tree) -> None:
    result = _extract(write_tree, "vendorlib/filters/smoother.h", "filters::Smoother")
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "~out")]
    assert "CPP_NODE_TO_UNKNOWN" not in [d.code for d in result.diagnostics]
