"""A name made of a counting loop's variable plus a constant, in a loop up to a
parameter's value: denso_robot_control reads its joints' types with ``for (int i = 0; i <
m_robJoints; i++) { std::stringstream ss; ss << "joint_" << i + 1; nh.getParam(ss.str(),
m_type[i]); }`` after ``nh.getParam("robot_joints", m_robJoints)``. The graph filled the
name's ``?`` with the variable's value (``joint_0`` .. ``joint_5``), so ``joint_0`` was read
but never set and ``joint_6`` set but never read; the name holds ``i + 1`` (``joint_1`` ..
``joint_6``). A run that is no such value (``2 * i``) keeps its ``?``."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.model.source import counted_mark, counted_turns
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

CODE = """
#include <ros/ros.h>
#include <sstream>
#include <string>
int main(int argc, char **argv) {
  ros::init(argc, argv, "hw");
  ros::NodeHandle nh;
  int joints = 0;
  nh.getParam("robot_joints", joints);
  int type[8];
  double gain[8];
  for (int i = 0; i < joints; i++) {
    std::stringstream ss;
    ss << "joint_" << i + 1;
    nh.getParam(ss.str(), type[i]);
  }
  for (int k = 1; k <= joints; ++k)
    nh.getParam("axis_" + std::to_string(k - 1) + "/gain", gain[k - 1]);
  for (int j = 0; j < joints; j++)
    nh.getParam("even_" + std::to_string(2 * j), gain[j]);
  ros::spin();
}
"""

LAUNCH = """
<launch>
  <param name="robot_joints" value="2"/>
  <param name="joint_1" value="1"/>
  <param name="joint_2" value="1"/>
  <param name="axis_0/gain" value="1.0"/>
  <param name="axis_1/gain" value="1.0"/>
  <node pkg="wp" type="hw" name="hw"/>
</launch>
"""


def _analysed(write_tree):
    root = write_tree({
        "src/wp/package.xml": package_xml("wp"),
        "src/wp/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\nproject(wp)\n"
                                 "find_package(catkin REQUIRED COMPONENTS roscpp)\n"
                                 "catkin_package()\nadd_executable(hw src/hw.cpp)\n",
        "src/wp/src/hw.cpp": CODE,
        "src/wp/launch/hw.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [wp/launch/hw.launch]\n",
    })
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def test_each_turn_reads_the_name_its_shifted_value_makes(write_tree) -> None:
    model = _analysed(write_tree)
    reads = sorted(link.resource.name for link in model.configurations[0].links
                   if link.kind == "read" and link.node.name == "/hw")
    assert reads == ["/axis_0/gain", "/axis_1/gain", "/even_?", "/joint_1", "/joint_2",
                     "/robot_joints"]
    found = sorted((f.rule, e) for f in run_catalogue(model)
                   if f.rule in ("parameter-set-not-read", "parameter-read-not-set")
                   for e in f.entities if e.startswith("parameter:"))
    assert found == []


def test_the_mark_keeps_its_shift() -> None:
    assert counted_mark(0, False) == "<0"
    assert counted_mark(0, False, 1) == "<0+1"
    assert counted_mark(1, True, -1) == "<1=-1"
    assert list(counted_turns("<0+1", 3, 10) or []) == [1, 2, 3]
    assert list(counted_turns("<1=-1", 2, 10) or []) == [0, 1]
    assert list(counted_turns("<0", 2, 10) or []) == [0, 1]
    assert counted_turns("<x", 2, 10) is None
