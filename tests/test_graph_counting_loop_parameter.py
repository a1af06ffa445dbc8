"""A call made in each turn of a counting loop up to a parameter's value, named by the
loop's variable: ego-planner (and Fast-Planner, ego-planner-swarm) reads its waypoints
with ``nh.param("fsm/waypoint_num", waypoint_num_, -1); for (int i = 0; i <
waypoint_num_; i++) nh.param("fsm/waypoint" + to_string(i) + "_x", ...)``. The reads were
``~fsm/waypoint?_x`` whatever the launch file gives (every waypoint parameter undecided);
now they are one read per turn of the value the configuration gives the count (else of
the code's default), so a waypoint beyond it is set but never read."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

CODE = """
#include <ros/ros.h>
#include <string>
class Fsm {
 public:
  void init(ros::NodeHandle &nh) {
    nh.param("fsm/waypoint_num", waypoint_num_, -1);
    for (int i = 0; i < waypoint_num_; i++) {
      nh.param("fsm/waypoint" + std::to_string(i) + "_x", waypoints_[i][0], -1.0);
      nh.param("fsm/waypoint" + std::to_string(i) + "_y", waypoints_[i][1], -1.0);
    }
    int count;
    nh.param("count", count, 2);
    for (int k = 1; k <= count; ++k)
      nh.param("item_" + std::to_string(k), items_[k], 0.0);
  }
 private:
  int waypoint_num_;
  double waypoints_[50][3];
  double items_[10];
};
int main(int argc, char **argv) {
  ros::init(argc, argv, "fsm");
  ros::NodeHandle nh("~");
  Fsm fsm;
  fsm.init(nh);
  ros::spin();
}
"""

LAUNCH = """
<launch>
  <node pkg="wp" type="fsm" name="fsm">
    <param name="fsm/waypoint_num" value="2"/>
    <param name="fsm/waypoint0_x" value="1.0"/>
    <param name="fsm/waypoint0_y" value="1.0"/>
    <param name="fsm/waypoint1_x" value="2.0"/>
    <param name="fsm/waypoint1_y" value="2.0"/>
    <param name="fsm/waypoint2_x" value="3.0"/>
    COUNT
  </node>
</launch>
"""


def _analysed(write_tree, count: str):
    root = write_tree({
        "src/wp/package.xml": package_xml("wp"),
        "src/wp/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\nproject(wp)\n"
                                 "find_package(catkin REQUIRED COMPONENTS roscpp)\n"
                                 "catkin_package()\nadd_executable(fsm src/fsm.cpp)\n",
        "src/wp/src/fsm.cpp": CODE,
        "src/wp/launch/fsm.launch": LAUNCH.replace("COUNT", count),
        "project.yaml": "project: p\nconfigurations:\n  c: [wp/launch/fsm.launch]\n",
    })
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def _reads(model) -> list[str]:
    return sorted(link.resource.name for link in model.configurations[0].links
                  if link.kind == "read" and link.node.name == "/fsm")


def test_each_turn_of_the_loop_reads_its_parameter(write_tree) -> None:
    model = _analysed(write_tree, '<param name="count" value="1"/>')
    assert _reads(model) == [
        "/fsm/count", "/fsm/fsm/waypoint0_x", "/fsm/fsm/waypoint0_y", "/fsm/fsm/waypoint1_x",
        "/fsm/fsm/waypoint1_y", "/fsm/fsm/waypoint_num", "/fsm/item_1"]
    unread = sorted(e for f in run_catalogue(model) if f.rule == "parameter-set-not-read"
                    for e in f.entities if e.startswith("parameter:"))
    assert unread == ["parameter:/fsm/fsm/waypoint2_x"]


def test_a_count_the_configuration_does_not_give_takes_the_code_default(write_tree) -> None:
    # nh.param("count", count, 2) with nothing setting ~count: two turns, as in ROS
    # (a count with no default keeps the ``?``: test_graph_counting_loop_default.py)
    model = _analysed(write_tree, "")
    reads = _reads(model)
    assert "/fsm/item_1" in reads and "/fsm/item_2" in reads
    assert "/fsm/item_?" not in reads
    unread = sorted(e for f in run_catalogue(model) if f.rule == "parameter-set-not-read"
                    for e in f.entities if e.startswith("parameter:"))
    assert unread == ["parameter:/fsm/fsm/waypoint2_x"]
