"""A name made of an element of a local array the function initialises with a list,
read in a counting loop over literal bounds, is one call per turn: orb_slam3_ros_wrapper
(thien94, b707ff2) reads ``node_name + "/world_" + angle_names[i]`` for ``i`` from 0 to 2,
``std::string angle_names[3] = {"roll", "pitch", "yaw"};`` (mono_node.cc:54-58 and its
three siblings): one read of ``~world_?`` before, which left the launch files'
``world_roll``, ``world_pitch`` and ``world_yaw`` undecided. An array whose element the
function writes, or hands whole to another function, stays unknown."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <ros/ros.h>
#include <string>
void fill(std::string *names);
int main(int argc, char **argv) {
  ros::init(argc, argv, "slam");
  ros::NodeHandle nh;
  std::string node_name = ros::this_node::getName();
  double rpy[3];
  std::string angle_names[3] = {"roll", "pitch", "yaw"};
  for (int i = 0; i < 3; i++) {
    nh.param<double>(node_name + "/world_" + angle_names[i], rpy[i], 0);
  }
  nh.param<double>(node_name + "/first_" + angle_names[0], rpy[0], 0);
  CHANGE
  return 0;
}
"""


def _reads(write_tree, change: str = "") -> list[str]:
    root = write_tree({"p/package.xml": package_xml("p"),
                       "p/src/main.cpp": SOURCE.replace("CHANGE", change)})
    result = extract_cpp([str(root / "p" / "src" / "main.cpp")], scan([str(root)]),
                         cache_dir=None)
    return [c.name for c in result.calls if c.kind == "read"]


def test_an_element_of_a_local_list_at_each_turn(write_tree) -> None:
    assert _reads(write_tree) == ["~world_roll", "~world_pitch", "~world_yaw",
                                  "~first_roll"]


def test_an_array_the_function_changes_is_unknown(write_tree) -> None:
    for change in ('angle_names[1] = "heading";', "fill(angle_names);"):
        reads = _reads(write_tree, change)
        assert "~world_roll" not in reads and "~first_roll" not in reads, change
