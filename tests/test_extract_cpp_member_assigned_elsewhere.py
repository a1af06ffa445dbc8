"""A handle member that the class's own constructor leaves to its default, and that
another file of the node assigns through an object of the class: FUEL's SDFMap hands its
private handle to its MapROS (``mr_->node_ = nh`` in sdf_map.cpp), whose ``init()`` in
map_ros.cpp reads ``map_ros/fx`` on ``node_``. The reads were taken on the default handle
(``/map_ros/fx``, so the launch file's ``~map_ros/fx`` looked unread); they are on the
handle the other file writes, when the node's files are read together. A member no file
assigns stays the default handle."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """#include <ros/ros.h>
#include <std_msgs/String.h>
namespace m {
class Helper {
 public:
  Helper();
  void init();
 private:
  ros::NodeHandle node_;
  ros::NodeHandle plain_;
  ros::Publisher pub_;
  double fx_;
  friend class Owner;
};
class Owner {
 public:
  void initMap(ros::NodeHandle& nh);
  Helper* helper_;
};
}  // namespace m
"""
HELPER = """#include "m/map.h"
namespace m {
Helper::Helper() {}
void Helper::init() {
  node_.param("helper/fx", fx_, -1.0);
  pub_ = plain_.advertise<std_msgs::String>("plain", 1);
}
}  // namespace m
"""
OWNER = """#include "m/map.h"
namespace m {
void Owner::initMap(ros::NodeHandle& nh) {
  helper_ = new Helper();
  helper_->node_ = nh;
  helper_->init();
}
}  // namespace m
"""
NODE = """#include "m/map.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "mapper");
  ros::NodeHandle nh("~");
  m::Owner owner;
  owner.initMap(nh);
  ros::spin();
  return 0;
}
"""


def _calls(write_tree, owner: str = OWNER, implicit: bool = False) -> list[tuple[str, str]]:
    root = write_tree({
        "m/package.xml": package_xml("m", "catkin"),
        "m/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(m)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)\ncatkin_package()\n"
            "include_directories(include)\n"
            "add_library(m src/helper.cpp src/owner.cpp)\n"
            "add_executable(mapper src/node.cpp)\n"
            "target_link_libraries(mapper m)\n"),
        "m/include/m/map.h": HEADER.replace("  Helper();\n", "") if implicit else HEADER,
        "m/src/helper.cpp": HELPER.replace("Helper::Helper() {}\n", "") if implicit
        else HELPER,
        "m/src/owner.cpp": owner,
        "m/src/node.cpp": NODE})
    sources = [str(root / "m" / "src" / name) for name in ("node.cpp", "helper.cpp",
                                                           "owner.cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None, jobs=1)
    return sorted({(c.kind, c.name) for c in result.calls})


def test_a_handle_member_assigned_through_an_object_elsewhere_is_that_handle(
        write_tree) -> None:
    calls = _calls(write_tree)
    assert ("read", "~helper/fx") in calls
    assert ("read", "helper/fx") not in calls
    # a member no file assigns is the default handle still
    assert ("publish", "plain") in calls


def test_a_handle_member_no_file_assigns_is_the_default_handle(write_tree) -> None:
    calls = _calls(write_tree, OWNER.replace("  helper_->node_ = nh;\n", ""))
    assert ("read", "helper/fx") in calls and ("publish", "plain") in calls


def test_a_class_that_declares_no_constructor_takes_the_assigned_handle(
        write_tree) -> None:
    calls = _calls(write_tree, implicit=True)
    assert ("read", "~helper/fx") in calls and ("read", "helper/fx") not in calls
    assert ("publish", "plain") in calls
    calls = _calls(write_tree, OWNER.replace("  helper_->node_ = nh;\n", ""), implicit=True)
    assert ("read", "helper/fx") in calls and ("publish", "plain") in calls


def test_a_handle_member_assigned_differently_elsewhere_is_unknown(write_tree) -> None:
    calls = _calls(write_tree, OWNER.replace(
        "  helper_->node_ = nh;\n",
        "  if (nh.hasParam(\"other\")) helper_->node_ = ros::NodeHandle(\"other\");\n"
        "  else helper_->node_ = nh;\n"))
    names = [name for kind, name in calls if kind == "read" and name.endswith("helper/fx")]
    assert names == ["?/helper/fx"]
