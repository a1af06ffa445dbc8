"""A method defined in a unit's own source and declared in a header, called by its own
file and by another file of the node: hector_exploration_planner's
``HectorExplorationPlanner(name, costmap)`` calls ``initialize(name, costmap)``, and
hector_exploration_node's exploration_node.cpp builds the planner with its default
constructor, then calls ``planner_->initialize("hector_exploration_planner", costmap)``.
``initialize`` makes ``ros::NodeHandle private_nh_("~/" + name)`` and advertises on it;
its own file's call alone gave ``name`` (the unused constructor's parameter, unknown):
``~?/goal_pose``. A non-virtual method so takes every file's values, as a constructor or
a free function does; a virtual one's come from the host's calls of what it overrides."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """#include <string>
#include <ros/ros.h>
namespace explore {
class Planner {
 public:
  Planner();
  Planner(std::string name, double* costmap);
  void initialize(std::string name, double* costmap);
  ros::Publisher goal_pub_;
  bool initialized_;
};
}  // namespace explore
"""
PLANNER = """#include <explore/planner.h>
#include <geometry_msgs/PoseStamped.h>
namespace explore {
Planner::Planner() : initialized_(false) {}
Planner::Planner(std::string name, double* costmap) : initialized_(false) {
  Planner::initialize(name, costmap);
}
void Planner::initialize(std::string name, double* costmap) {
  ros::NodeHandle private_nh("~/" + name);
  goal_pub_ = private_nh.advertise<geometry_msgs::PoseStamped>("goal_pose", 1, true);
  initialized_ = true;
}
}  // namespace explore
"""
NODE = """#include <explore/planner.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "exploration");
  double costmap = 0.0;
  explore::Planner* planner = new explore::Planner();
  planner->initialize("exploration_planner", &costmap);
  ros::spin();
  return 0;
}
"""


def test_a_method_its_own_file_calls_takes_other_files_values_too(write_tree) -> None:
    root = write_tree({
        "explore/package.xml": package_xml("explore", "catkin"),
        "explore/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(explore)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp geometry_msgs)\n"
            "catkin_package()\ninclude_directories(include)\n"
            "add_executable(exploration src/node.cpp src/planner.cpp)\n"),
        "explore/include/explore/planner.h": HEADER,
        "explore/src/planner.cpp": PLANNER,
        "explore/src/node.cpp": NODE})
    sources = [str(root / "explore" / "src" / name) for name in ("node.cpp", "planner.cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None, jobs=1)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "~exploration_planner/goal_pose")]
