"""A ROS 1 launch file that starts no node and only sets parameters (m-explore's
``map_merge/launch/experiments/3-robots.ttt.launch``: each robot's initial pose, for a
map_merge started by another launch file on the same master) is no configuration in
which its parameters can be unread: whoever reads them is started elsewhere. The
parameters are counted in parameter-set-not-read's undecided info, which says so; a
launch file that starts a node still has its unread parameters reported."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

POSES = """<launch>
  <group ns="/robot_0/map_merge">
    <param name="init_pose_x" value="-6.8"/>
    <param name="init_pose_y" value="5.2"/>
  </group>
</launch>
"""

NODE = """#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "talker");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::String>("chatter", 10);
}
"""

WITH_NODE = """<launch>
  <param name="/robot_0/map_merge/init_pose_x" value="-6.8"/>
  <node pkg="merge" type="talker" name="talker"/>
</launch>
"""


def test_parameters_of_a_launch_file_that_starts_no_node_are_undecided(write_tree):
    root = write_tree({
        "src/merge/package.xml": package_xml("merge").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "src/merge/CMakeLists.txt": ("project(merge)\nfind_package(catkin REQUIRED)\n"
                                     "catkin_package()\nadd_executable(talker talker.cpp)\n"),
        "src/merge/talker.cpp": NODE,
        "src/merge/launch/poses.launch": POSES,
        "src/merge/launch/with_node.launch": WITH_NODE,
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  poses: [merge/launch/poses.launch]\n"
                        "  with_node: [merge/launch/with_node.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {})
    findings = run_catalogue(model)
    unread = sorted((f.configuration, f.entities[0]) for f in findings
                    if f.rule == "parameter-set-not-read")
    assert unread == [("with_node", "parameter:/robot_0/map_merge/init_pose_x")]
    undecided = [f for f in findings if f.rule == "parameter-set-not-read-undecided"]
    assert [(f.configuration, f.location.line) for f in undecided] == [("poses", 3)]
    assert "2 possible finding(s) not reported" in undecided[0].message
    assert "nodes started elsewhere (poses.launch starts none) (2)" in undecided[0].message
