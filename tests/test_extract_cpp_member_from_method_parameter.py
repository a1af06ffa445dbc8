"""A handle member a non-virtual method stores from its parameter, where the method is
called from another file of the node (ego-planner bfda512: ``GridMap::initMap(
ros::NodeHandle& nh) { node_ = nh; node_.param("grid_map/resolution", ...); }`` in
plan_env's grid_map.cpp, called from planner_manager.cpp with the node's private handle).
The member was unknown (``?/grid_map/resolution``, 38 reads and the findings on them):
a method no call of its own file passes was taken for a plugin's initialisation, whose
host gives the value. The node's other files give it, as they do for a direct use of the
parameter in the same method."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#include <memory>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
class GridMap {
 public:
  void initMap(ros::NodeHandle& nh);
  void publish();
  typedef std::shared_ptr<GridMap> Ptr;
 private:
  ros::NodeHandle node_;
  ros::Publisher pub_;
  double resolution_;
};
"""

GRID_MAP = """\
#include "p/grid_map.h"
void GridMap::initMap(ros::NodeHandle& nh) {
  node_ = nh;
  nh.param("direct", resolution_, 1.0);
  node_.param("grid_map/resolution", resolution_, -1.0);
  pub_ = node_.advertise<std_msgs::Float64>("grid_map/occupancy", 1);
}
"""

MAIN = """\
#include "p/grid_map.h"
class Manager {
 public:
  void initPlanModules(ros::NodeHandle& nh) {
    grid_map_.reset(new GridMap);
    grid_map_->initMap(nh);
  }
  GridMap::Ptr grid_map_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "planner");
  ros::NodeHandle nh(%s);
  Manager manager;
  manager.initPlanModules(nh);
}
"""


def _extract(write_tree, handle: str) -> CppResult:
    root: Path = write_tree({
        "p/package.xml": package_xml("p"),
        "p/include/p/grid_map.h": HEADER,
        "p/src/grid_map.cpp": GRID_MAP,
        "p/src/main.cpp": MAIN % handle,
    })
    return extract_cpp([str(root / "p/src" / name) for name in ("main.cpp", "grid_map.cpp")],
                       scan([str(root)]), cache_dir=None)


def test_a_member_set_from_a_parameter_another_file_passes(write_tree) -> None:
    result = _extract(write_tree, '"~"')
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "~grid_map/occupancy"), ("read", "~direct"),
        ("read", "~grid_map/resolution")]


def test_the_namespace_the_caller_computes(write_tree) -> None:
    result = _extract(write_tree, 'ros::NodeHandle("~"), "planner"')
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "~planner/grid_map/occupancy"), ("read", "~planner/direct"),
        ("read", "~planner/grid_map/resolution")]
